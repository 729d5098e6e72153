"""SequenceDir on folders of PCD and PLY scans (README "Your own data"): the bundled KITTI 00 scans written as
binary PCD and PLY with a label field read back to the points and labels of the .bin files; read_ply; errors."""
import shutil

import numpy as np
import pytest
import sgtllc

from conftest import KITTI


def write_pcd(path, points, labels=None):
    fields = "x y z label" if labels is not None else "x y z"
    n = len(points)
    header = (f"VERSION 0.7\nFIELDS {fields}\nSIZE {' '.join(['4'] * len(fields.split()))}\n"
              f"TYPE F F F{' U' if labels is not None else ''}\nCOUNT {' '.join(['1'] * len(fields.split()))}\n"
              f"WIDTH {n}\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS {n}\nDATA binary\n")
    dtype = [("x", "<f4"), ("y", "<f4"), ("z", "<f4")] + ([("label", "<u4")] if labels is not None else [])
    rec = np.zeros(n, dtype=dtype)
    rec["x"], rec["y"], rec["z"] = points[:, 0], points[:, 1], points[:, 2]
    if labels is not None:
        rec["label"] = labels
    path.write_bytes(header.encode() + rec.tobytes())


def write_ply(path, points, labels):
    n = len(points)
    header = (f"ply\nformat binary_little_endian 1.0\nelement vertex {n}\nproperty float x\nproperty float y\n"
              f"property float z\nproperty uint label\nend_header\n")
    rec = np.zeros(n, dtype=[("xyz", "<f4", 3), ("label", "<u4")])
    rec["xyz"], rec["label"] = points, labels
    path.write_bytes(header.encode() + rec.tobytes())


@pytest.mark.parametrize("ext", ["pcd", "ply"])
def test_a_folder_of_scans_reads_as_its_bin_files(tmp_path, ext):
    bins = sgtllc.SequenceDir(str(KITTI))
    for i in range(len(bins)):
        points, labels = bins.load(i)
        target = tmp_path / f"{bins.frame_name(i)}.{ext}"
        (write_pcd if ext == "pcd" else write_ply)(target, points, labels)
    seq = sgtllc.SequenceDir(str(tmp_path))
    assert (seq.format, seq.labels_in_scans, seq.scan_dir) == (ext, True, str(tmp_path))
    assert [seq.frame_name(i) for i in range(len(seq))] == ["000052", "000088", "000850", "004501"]
    assert seq.scan_path(3).endswith(f"004501.{ext}")
    for i in range(len(seq)):
        p, l = seq.load(i)
        q, m = bins.load(i)
        np.testing.assert_array_equal(p, q)
        np.testing.assert_array_equal(l, m)
    with pytest.raises(sgtllc.Error, match="label field"):
        seq.label_path(0)
    if ext == "ply":
        p, l = sgtllc.read_ply(seq.scan_path(0))
        np.testing.assert_array_equal(sgtllc.read_ply_points(seq.scan_path(0)), p)


def test_labels_from_labels_folder_or_none(tmp_path):
    bins = sgtllc.SequenceDir(str(KITTI))
    (tmp_path / "velodyne").mkdir()
    for i in range(len(bins)):
        write_pcd(tmp_path / "velodyne" / f"{bins.frame_name(i)}.pcd", bins.load(i)[0])
    with pytest.raises(sgtllc.Error, match=r"missing label file \(4 of 4 scans .* no 'label' field"):
        sgtllc.SequenceDir(str(tmp_path))
    points_only = sgtllc.SequenceDir(str(tmp_path), read_labels=False)
    assert len(points_only.load(0)[1]) == 0
    shutil.copytree(KITTI / "labels", tmp_path / "labels")
    seq = sgtllc.SequenceDir(str(tmp_path))
    assert not seq.labels_in_scans and seq.label_path(1).endswith("labels/000088.label")
    np.testing.assert_array_equal(seq.load(1)[1], bins.load(1)[1])


def test_mixed_formats_and_bad_scans_name_the_folder_or_file(tmp_path):
    points = np.array([[1, 2, 3]], dtype=np.float32)
    write_pcd(tmp_path / "a.pcd", points, np.array([40], dtype=np.uint32))
    shutil.copy(KITTI / "velodyne" / "000052.bin", tmp_path / "b.bin")
    with pytest.raises(sgtllc.Error, match="mixes scan formats"):
        sgtllc.SequenceDir(str(tmp_path))
    (tmp_path / "b.bin").unlink()
    (tmp_path / "b.pcd").write_bytes(b"VERSION 0.7\nFIELDS x y z label\n")
    seq = sgtllc.SequenceDir(str(tmp_path))
    with pytest.raises(sgtllc.Error, match="b.pcd"):
        seq.load(1)
