"""Config from Python: nested fields that change the configuration itself, YAML both ways (equal to `sgtllc
config`), and validation errors as ConfigError naming the field."""
import copy

import pytest

import sgtllc
from conftest import SOURCE, run_cli


def test_defaults_are_the_cli_defaults(cli):
    assert sgtllc.Config().to_yaml() == run_cli(cli, "config")


def test_nested_fields_change_the_config():
    c = sgtllc.Config()
    c.verification.sigma_4 = 0.5
    c.graph.max_nodes = 300
    c.cluster.classes[0].radius = 2.0
    c.labels.custom_map[10] = 0
    c.retrieval.method = sgtllc.RetrievalMethod.KD_TREE
    assert c.retrieval.key == sgtllc.RetrievalKey.DISTANCE_HISTOGRAM and c.retrieval.histogram_bins == 30
    c.retrieval.key = sgtllc.RetrievalKey.GLOBAL_DESCRIPTOR
    c.retrieval.histogram_range = 25.0
    c.backend.solver.max_iterations = 7
    text = c.to_yaml()
    for line in ["sigma_4: 0.5", "max_nodes: 300", "method: kdtree", "key: global", "histogram_range: 25.0",
                 "max_iterations: 7", "10: 0"]:
        assert line in text
    assert "radius: 2.0" in text.split("fence:")[0].split("building:")[1]
    assert len(c.cluster.classes) == 7 and c.cluster.classes[0].min_size == 200


def test_yaml_round_trip(tmp_path):
    c = sgtllc.Config()
    c.verification.sigma_4 = 0.25
    c.descriptor.global_mode = sgtllc.GlobalMode.G3
    c.add_class(sgtllc.ExtraClass("vehicle", [10, 252]), sgtllc.ClassClusterConfig(0.4, 1.0, 100))
    # Upright objects' nodes at the sensor's height (algorithm §2): poles by default, any class when set.
    assert c.cluster.classes[5].centre_height == sgtllc.CentreHeight.SENSOR
    assert c.cluster.classes[0].centre_height == sgtllc.CentreHeight.POINTS
    c.cluster.classes[0].centre_height = sgtllc.CentreHeight.SENSOR
    # A class whose unmatched nodes do not count in the loop score (algorithm §7.3, "Node count").
    assert c.cluster.classes[4].score_unmatched
    assert not sgtllc.ClassClusterConfig(score_unmatched=False).score_unmatched
    c.cluster.classes[4].score_unmatched = False
    path = tmp_path / "c.yaml"
    path.write_text(c.to_yaml())
    back = sgtllc.Config.from_yaml(str(path))
    assert back == c and back.num_classes() == 8
    assert back.labels.extra_classes[0].ids == (10, 252) and back.labels.class_name(7) == "vehicle"
    assert back.verification.sigma_4 == 0.25 and back.cluster.classes[7].min_size == 100
    assert back.cluster.classes[0].centre_height == sgtllc.CentreHeight.SENSOR
    assert "centre_height: sensor" in c.to_yaml().split("fence:")[0]
    assert not back.cluster.classes[4].score_unmatched and back.cluster.classes[3].score_unmatched
    assert "score_unmatched: false" in c.to_yaml().split("terrain:")[1].split("pole:")[0]
    assert sgtllc.Config.from_yaml_string(c.to_yaml()) == c


def test_bundled_config_file_reads():
    c = sgtllc.Config.from_yaml(str(SOURCE / "configs" / "kitti00-objects.yaml"))
    assert c.num_classes() >= 7


def test_out_of_range_value_raises_config_error_naming_the_key():
    c = sgtllc.Config()
    c.verification.sigma_4 = 5.0
    with pytest.raises(sgtllc.ConfigError, match=r"verification\.sigma_4") as e:
        c.validate()
    assert e.value.key == "verification.sigma_4"
    assert isinstance(e.value, ValueError) and isinstance(e.value, sgtllc.Error)
    with pytest.raises(sgtllc.ConfigError, match=r"verification\.sigma_4"):
        sgtllc.LoopDetector(c)
    with pytest.raises(sgtllc.ConfigError):
        sgtllc.compare_nodes([[0.0, 0, 0]], [0], [[0.0, 0, 0]], [0], c)


def test_backend_value_out_of_range_names_the_key():
    c = sgtllc.Config()
    c.backend.loss_scale = 0.0
    with pytest.raises(sgtllc.ConfigError) as e:
        c.validate()
    assert e.value.key == "backend.loss_scale"


def test_bad_yaml_names_source_and_key(tmp_path):
    with pytest.raises(sgtllc.Error, match=r"bad\.yaml.*graph\.nope"):
        p = tmp_path / "bad.yaml"
        p.write_text("graph:\n  nope: 3\n")
        sgtllc.Config.from_yaml(str(p))
    with pytest.raises(sgtllc.Error, match=r"my-source.*verification\.sigma_4"):
        sgtllc.Config.from_yaml_string("verification:\n  sigma_4: 7\n", "my-source")


def test_wrong_type_is_a_type_error():
    c = sgtllc.Config()
    with pytest.raises(TypeError):
        c.graph.max_nodes = 2.5
    with pytest.raises(AttributeError):
        c.graph.no_such_field = 1
    with pytest.raises(AttributeError):
        c.labels.extra_classes.append(sgtllc.ExtraClass("x")) or c.labels.extra_classes[0].ids.append(3)


def test_copy_is_independent():
    c = sgtllc.Config()
    d = copy.deepcopy(c)
    d.graph.sigma_d = 10.0
    assert c.graph.sigma_d == 30.0 and d != c
    detector = sgtllc.LoopDetector(c)
    c.graph.sigma_d = 12.0
    assert detector.config.graph.sigma_d == 30.0


def test_reference_lists_every_setting_with_its_value_and_range():
    c = sgtllc.Config()
    c.verification.sigma_4 = 0.25
    text = c.reference()
    assert "| `verification.sigma_4` | `0.25` | [0, 1] |" in text
    assert "| `labeller.source` | `file` | `file`, `geometric`, `hybrid` |" in text
    # The property's docstring carries the same range.
    assert "in [0, 1]" in sgtllc.VerificationConfig.sigma_4.__doc__
