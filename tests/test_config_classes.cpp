// The configuration's class set (labels.extra_classes, cluster.NAME): YAML round trip, key order, and validation
// errors that name the file, the line and the key.
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "sgtllc/detector.h"
#include "sgtllc/io/config_yaml.h"
#include "test_config_support.h"

namespace sgtllc {
namespace {

using ::testing::HasSubstr;

std::string errorOf(const std::string& yaml) { return test::configErrorOf(yaml); }

const char* const kVehicleYaml =
    "labels:\n"
    "  extra_classes:\n"
    "    - {name: vehicle, ids: [10, 13, 18, 20, 252, 256, 257, 258, 259]}\n"
    "    - name: person\n"
    "      ids: [30, 254]\n"
    "cluster:\n"
    "  vehicle: {voxel: 0.2, radius: 0.8, min_size: 15}\n";

TEST(ConfigClasses, ExtraClassesReadWithTheirParameters) {
  const Config c = io::parseConfig(kVehicleYaml, "my.yaml");
  ASSERT_EQ(c.numClasses(), 9);
  EXPECT_EQ(c.labels.extra_classes[0], (ExtraClass{"vehicle", {10, 13, 18, 20, 252, 256, 257, 258, 259}}));
  EXPECT_EQ(c.labels.extra_classes[1], (ExtraClass{"person", {30, 254}}));
  ASSERT_EQ(c.cluster.classes.size(), 9u);
  EXPECT_EQ(c.cluster.classes[7].voxel, 0.2);
  EXPECT_EQ(c.cluster.classes[7].radius, 0.8);
  EXPECT_EQ(c.cluster.classes[7].min_size, 15);
  // Not given: the ClassClusterConfig defaults.
  EXPECT_EQ(c.cluster.classes[8].voxel, 0.0);
  EXPECT_EQ(c.cluster.classes[8].radius, 1.0);
  EXPECT_EQ(c.cluster.classes[8].min_size, 20);
  EXPECT_EQ(c.cluster.classes[0].min_size, 200);  // the seven keep theirs
}

TEST(ConfigClasses, PrintedConfigurationReadsBackEqual) {
  const Config c = io::parseConfig(kVehicleYaml, "my.yaml");
  const std::string text = io::configToYaml(c);
  EXPECT_THAT(text, HasSubstr("  extra_classes: [{name: vehicle, ids: [10, 13, 18, 20, 252, 256, 257, 258, 259]}, "
                              "{name: person, ids: [30, 254]}]  # "));
  EXPECT_THAT(text, HasSubstr("\n  vehicle:\n    voxel: 0.2  # voxel leaf (m); 0 = no downsampling\n"
                              "    radius: 0.8  # FEC radius r (m)\n    min_size: 15  #"));
  EXPECT_THAT(text, HasSubstr("\n  person:\n    voxel: 0.0  #"));
  const Config back = io::parseConfig(text, "printed.yaml");
  EXPECT_EQ(back.labels.extra_classes, c.labels.extra_classes);
  ASSERT_EQ(back.cluster.classes.size(), c.cluster.classes.size());
  for (size_t k = 0; k < c.cluster.classes.size(); ++k) {
    EXPECT_EQ(back.cluster.classes[k].voxel, c.cluster.classes[k].voxel) << k;
    EXPECT_EQ(back.cluster.classes[k].radius, c.cluster.classes[k].radius) << k;
    EXPECT_EQ(back.cluster.classes[k].min_size, c.cluster.classes[k].min_size) << k;
  }
  EXPECT_EQ(io::configToYaml(back), text);
  EXPECT_THAT(io::configToYaml(Config{}), HasSubstr("\n  extra_classes: []  # "));
}

TEST(ConfigClasses, KeyOrderDoesNotMatter) {
  // cluster.NAME before the declaration; custom_map targets class 7 before extra_classes declares it.
  const Config c = io::parseConfig(
      "cluster:\n  vehicle:\n    min_size: 5\nlabels:\n  preset: custom\n  custom_map: {3: 7, 4: 0}\n"
      "  extra_classes: [{name: vehicle, ids: []}]\n",
      "my.yaml");
  EXPECT_EQ(c.cluster.classes[7].min_size, 5);
  EXPECT_EQ(c.labels.custom_map.at(3), 7);
}

TEST(ConfigClasses, InvalidClassSetsNameTheKeyAndLine) {
  const auto two = [](const std::string& a, const std::string& b) {
    return "labels:\n  extra_classes:\n    - " + a + "\n    - " + b + "\n";
  };
  EXPECT_THAT(errorOf(two("{name: vehicle, ids: [10]}", "{name: vehicle, ids: [20]}")),
              HasSubstr("my.yaml:4: labels.extra_classes[1].name: 'vehicle' is already the name of class 7"));
  EXPECT_THAT(errorOf(two("{name: vehicle, ids: [10]}", "{name: pole, ids: [20]}")),
              HasSubstr("my.yaml:4: labels.extra_classes[1].name: 'pole' is one of the paper's classes"));
  EXPECT_THAT(errorOf(two("{name: vehicle, ids: [10]}", "{name: Truck, ids: [20]}")),
              HasSubstr("my.yaml:4: labels.extra_classes[1].name: 'Truck' is not a class name"));
  EXPECT_THAT(errorOf(two("{name: vehicle, ids: [10]}", "{name: a.b, ids: [20]}")),
              HasSubstr("labels.extra_classes[1].name: 'a.b' is not a class name"));
  EXPECT_THAT(errorOf(two("{name: car, ids: [10, 13]}", "{name: truck, ids: [18, 10]}")),
              HasSubstr("my.yaml:4: labels.extra_classes[1].ids: id 10 is mapped twice: already to 'car'"));
  EXPECT_THAT(errorOf(two("{name: car, ids: [10, 10]}", "{name: truck, ids: [18]}")),
              HasSubstr("my.yaml:3: labels.extra_classes[0].ids: id 10 is mapped twice: already to 'car'"));
  EXPECT_THAT(errorOf(two("{name: car, ids: [10]}", "{name: wall, ids: [50]}")),
              HasSubstr("labels.extra_classes[1].ids: id 50 is mapped twice: the preset maps it to 'building'"));
  EXPECT_THAT(errorOf("labels:\n  preset: custom\n  custom_map: {7: 0}\n  extra_classes: [{name: car, ids: [7]}]\n"),
              HasSubstr("my.yaml:4: labels.extra_classes[0].ids: id 7 is mapped twice: labels.custom_map lists it"));
  EXPECT_THAT(errorOf(two("{name: car, ids: [10]}", "{name: truck, ids: []}")),
              HasSubstr("my.yaml:4: labels.extra_classes[1].ids: class 'truck' lists no raw ids"));

  std::string many = "labels:\n  extra_classes:\n";
  for (int k = 0; k < 10; ++k) many += "    - {name: c" + std::to_string(k) + ", ids: [" + std::to_string(k) + "]}\n";
  EXPECT_THAT(errorOf(many), HasSubstr("my.yaml:3: labels.extra_classes: 10 extra classes make 17 in all, more than "
                                       "16 (the G2 global descriptor has C³ entries per frame)"));
  many.resize(many.rfind("    - "));  // nine: sixteen classes
  EXPECT_EQ(errorOf(many), "(no error)");
}

TEST(ConfigClasses, MalformedEntriesAndUndeclaredClasses) {
  EXPECT_THAT(errorOf("labels:\n  extra_classes: [{name: car, ids: [10], colour: red}]\n"),
              HasSubstr("my.yaml:2: labels.extra_classes: entry 0: unknown key 'colour' (expected name and ids)"));
  EXPECT_THAT(errorOf("labels:\n  extra_classes: [{ids: [10]}]\n"), HasSubstr("entry 0: missing name"));
  EXPECT_THAT(errorOf("labels:\n  extra_classes: [{name: car, ids: 10}]\n"),
              HasSubstr("entry 0: ids: expected a list of raw ids"));
  EXPECT_THAT(errorOf("labels:\n  extra_classes: {name: car}\n"), HasSubstr("expected a list of {name: NAME"));
  EXPECT_THAT(errorOf("labels:\n  extra_classes: [{name: car, ids: [10, {a: 1}]}]\n"),
              HasSubstr("entry 0: ids must be integers 0..65535"));
  EXPECT_THAT(errorOf("labels:\n  extra_classes: [{name: car, ids: [10, 10], ids: [3]}]\n"),
              HasSubstr("appears twice"));
  EXPECT_THAT(errorOf("cluster:\n  vehicle:\n    min_size: 5\n"),
              HasSubstr("my.yaml:2: unknown key 'cluster.vehicle' (run `sgtllc config` for the valid keys; a new "
                        "class is declared in labels.extra_classes)"));
  EXPECT_THAT(errorOf("labels:\n  extra_classes: [{name: car, ids: [10]}]\ncluster:\n  car:\n    radius: 0\n"),
              HasSubstr("my.yaml:5: cluster.car.radius = 0 is out of range [0.001, 10]"));
  EXPECT_THAT(errorOf("labels:\n  preset: custom\n  custom_map: {3: 8}\n  extra_classes: [{name: car, ids: []}]\n"),
              HasSubstr("classes must be integers -1..7 (id 3)"));
  EXPECT_THAT(errorOf("association:\n  score: count\n  sigma_2: 64.5\nlabels:\n  extra_classes: [{name: c, ids: [1]}]\n"),
              HasSubstr("association.sigma_2 = 64.5 is out of range [0, 64] (association.score: count)"));
}

TEST(ConfigClasses, LibraryChecksTheClassSet) {
  Config c;
  EXPECT_EQ(c.addClass({"vehicle", {10}}), 7);
  EXPECT_NO_THROW(c.validate());
  c.cluster.classes.pop_back();
  try {
    LoopDetector detector(c);
    FAIL() << "no error";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.key(), "cluster");
    EXPECT_THAT(e.what(), HasSubstr("cluster.classes has 7 entries for 8 classes"));
  }
  Config bad;
  bad.addClass({"vehicle", {70000}});
  try {
    bad.validate();
    FAIL() << "no error";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.key(), "labels.extra_classes[0].ids");
    EXPECT_THAT(e.what(), HasSubstr("id 70000 is out of range [0, 65535]"));
  }
}

}  // namespace
}  // namespace sgtllc
