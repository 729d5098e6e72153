"""One-byte label files and the nuScenes preset on the real nuScenes-lidarseg frames in data/nuscenes."""
import numpy as np
import pytest

import sgtllc
from conftest import SOURCE

SCENE = SOURCE / "data" / "nuscenes" / "0001"
BIN = SCENE / "velodyne" / "000000.bin"
LABEL = SCENE / "labels" / "000000.label"


def test_one_byte_labels_equal_numpy():
    want = np.fromfile(LABEL, np.uint8).astype(np.uint32)
    points, labels = sgtllc.read_labeled_scan(str(BIN))  # format AUTO: 34,720 bytes for 34,720 points
    np.testing.assert_array_equal(labels, want)
    assert len(points) == 34720
    np.testing.assert_array_equal(sgtllc.read_labels(str(LABEL), point_count=34720), want)
    np.testing.assert_array_equal(sgtllc.read_labels(str(LABEL), format=sgtllc.LabelFormat.UINT8), want)
    with pytest.raises(sgtllc.Error, match="has 34720 bytes, not 138880 .uint32"):
        sgtllc.read_labeled_scan(str(BIN), format=sgtllc.LabelFormat.UINT32)


def test_nuscenes_preset_in_the_config():
    config = sgtllc.Config.from_yaml(str(SOURCE / "configs" / "nuscenes.yaml"))
    assert config.labels.preset == sgtllc.LabelPreset.NUSCENES
    assert config.labels.format == sgtllc.LabelFormat.UINT8
    assert config.labeller.source == sgtllc.LabelSource.HYBRID
    assert sgtllc.Config().labels.format == sgtllc.LabelFormat.AUTO
