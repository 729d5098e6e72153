// Config ranges: every numeric key rejects a value outside its documented range with a message naming the file,
// the line, the YAML key and the range, and accepts the range's boundaries.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "sgtllc/detector.h"
#include "sgtllc/io/config_yaml.h"
#include "test_config_support.h"

namespace sgtllc {
namespace {

using ::testing::HasSubstr;

/// Declares the extra class `vehicle`, whose cluster.vehicle keys the table tests like those of the seven.
const std::string kVehiclePrelude = "labels:\n  extra_classes: [{name: vehicle, ids: [10]}]\n";

/// A YAML document setting the dotted @p key to @p value after @p prelude; the value sits on the line returned in
/// *line.
std::string yamlFor(const std::string& key, const std::string& value, int* line = nullptr,
                    const std::string& prelude = "") {
  std::vector<std::string> parts;
  std::stringstream ss(key);
  for (std::string part; std::getline(ss, part, '.');) parts.push_back(part);
  std::string doc = prelude;
  for (size_t d = 0; d < parts.size(); ++d) {
    doc += std::string(2 * d, ' ') + parts[d] + ":" + (d + 1 < parts.size() ? "\n" : " " + value + "\n");
  }
  if (line) *line = static_cast<int>(std::count(prelude.begin(), prelude.end(), '\n') + parts.size());
  return doc;
}

std::string errorOf(const std::string& yaml) { return test::configErrorOf(yaml); }

/// One numeric key: values that must load, values that must not, and the range the message states.
struct Range {
  std::string key;
  std::vector<std::string> good;  ///< the boundaries (and, for open ends, a value just inside)
  std::vector<std::string> bad;   ///< written as the message prints them (shortest round-trip text)
  std::string range;              ///< "[0, 1]"; or, for a check made while parsing, the parser's message
  bool parse_level = false;       ///< the YAML reader rejects the value before Config::validate() sees it
  std::string prelude = {};       ///< YAML before the key (the declaration of an extra class)
};

std::vector<Range> ranges() {
  std::vector<Range> r;
  std::vector<std::string> classes(kClassNames.begin(), kClassNames.end());
  classes.push_back("vehicle");
  for (const std::string& c : classes) {
    const std::string p = "cluster." + c + ".";
    const std::string pre = c == "vehicle" ? kVehiclePrelude : "";
    r.push_back({p + "voxel", {"0", "0.001", "10"}, {"-1", "0.0005", "10.5"}, "0 (no downsampling) or [0.001, 10]",
                 false, pre});
    r.push_back({p + "radius", {"0.001", "10"}, {"0", "-1", "11"}, "[0.001, 10]", false, pre});
    r.push_back({p + "min_size", {"1", "1000000"}, {"0", "-5", "1000001"}, "[1, 1000000]", false, pre});
  }
  r.push_back({"cluster.max_neighbors", {"1", "10000"}, {"0", "10001"}, "[1, 10000]"});
  r.push_back({"cluster.duplicate_radius", {"0", "100"}, {"-0.5", "100.5"}, "[0, 100]"});
  r.push_back({"graph.sigma_d", {"1e-09", "1000"}, {"0", "-3", "1000.5"}, "(0, 1000]"});
  r.push_back({"graph.max_nodes", {"1", "2000"}, {"0", "2001"}, "[1, 2000]"});
  r.push_back({"retrieval.histogram_bins", {"1", "100"}, {"0", "101"}, "[1, 100]"});
  r.push_back({"retrieval.histogram_range", {"0.001", "1000"}, {"0", "-1", "1000.5"}, "(0, 1000]"});
  r.push_back({"retrieval.num_candidates", {"1", "1000"}, {"0", "1001", "1000000000"}, "[1, 1000]"});
  r.push_back({"retrieval.exclude_recent", {"1", "1000000"}, {"0", "1000001"}, "[1, 1000000]"});
  r.push_back({"retrieval.warmup_frames", {"0", "1000000"}, {"-1", "1000001"}, "[0, 1000000]"});
  r.push_back({"retrieval.ivf_lists", {"0", "65536"}, {"-1", "65537"}, "[0, 65536]"});
  r.push_back({"retrieval.ivf_probe", {"1", "65536"}, {"0", "65537"}, "[1, 65536]"});
  r.push_back({"retrieval.ivf_train_frames", {"64", "1000000"}, {"63", "1000001"}, "[64, 1000000]"});
  r.push_back({"association.sigma_1", {"-1", "1"}, {"-1.5", "1.5"}, "[-1, 1]"});
  r.push_back({"association.max_delta_aj", {"1e-09", "1000000"}, {"0", "1000001"}, "(0, 1000000]"});
  r.push_back({"association.sigma_2", {"0", "1"}, {"-0.1", "1.5"}, "[0, 1] (association.score: ratio"});
  r.push_back({"verification.sigma_3", {"0", "1"}, {"-0.1", "1.01"}, "[0, 1]"});
  r.push_back({"verification.min_associations", {"1", "2000"}, {"0", "2001"}, "[1, 2000]"});
  r.push_back({"verification.ransac_iterations", {"1", "10000"}, {"0", "10001"}, "[1, 10000]"});
  r.push_back({"verification.ransac_sample_size", {"3", "100"}, {"2", "101"}, "[3, 100]"});
  r.push_back({"verification.inlier_threshold", {"1e-09", "10"}, {"0", "10.5"}, "(0, 10]"});
  r.push_back({"verification.min_inliers", {"1", "2000"}, {"0", "2001"}, "[1, 2000]"});
  r.push_back({"verification.min_inlier_fraction", {"0", "1"}, {"-0.01", "1.5"}, "[0, 1]"});
  r.push_back({"verification.ransac_confidence", {"1e-09", "1"}, {"0", "1.001"}, "(0, 1]"});
  r.push_back({"verification.max_tilt_deg", {"1", "180"}, {"0", "0.5", "180.5"}, "[1, 180]"});
  r.push_back({"verification.sigma_4", {"0", "1"}, {"5", "-3", "1.0000001"}, "[0, 1]"});
  r.push_back({"verification.select_margin", {"0", "1"}, {"-0.1", "1.5"}, "[0, 1]"});
  r.push_back({"verification.lateral_distance", {"1e-09", "1000"}, {"0", "1001"}, "(0, 1000]"});
  r.push_back({"verification.neighbour_frames", {"0", "50"}, {"-1", "51"}, "[0, 50]"});
  r.push_back({"verification.offset_decay_start", {"0", "5"}, {"-1", "1001"}, "[0, 1000]"});
  r.push_back({"verification.offset_decay_end", {"0", "1000"}, {"-1", "1001"}, "[0, 1000]"});
  r.push_back({"verification.consistency_pairs", {"0", "16"}, {"-1", "17"}, "[0, 16]"});
  r.push_back({"verification.weak_inliers", {"0", "1000"}, {"-1", "1001"}, "[0, 1000]"});
  r.push_back({"verification.weak_min_footprint", {"0", "1"}, {"-0.1", "1.1"}, "[0, 1]"});
  r.push_back({"verification.min_footprint_overlap", {"0", "1"}, {"-0.1", "1.1"}, "[0, 1]"});
  r.push_back({"verification.footprint_cell", {"0.2", "10"}, {"0.1", "11"}, "[0.2, 10]"});
  r.push_back({"verification.footprint_radius", {"5", "200"}, {"4", "201"}, "[5, 200]"});
  r.push_back({"verification.seed", {"0", "4294967295"}, {"-1", "4294967296"}, "expected an integer in 0..4294967295",
               true});
  const std::string lg = "labeller.ground.", ls = "labeller.segments.";
  r.push_back({lg + "sectors", {"8", "1440"}, {"7", "1441"}, "[8, 1440]"});
  r.push_back({lg + "bin", {"0.05", "10"}, {"0.04", "11"}, "[0.05, 10]"});
  r.push_back({lg + "max_range", {"1e-09", "1000"}, {"0", "1001"}, "(0, 1000]"});
  r.push_back({lg + "min_range", {"0", "19.99"}, {"-0.1", "20"}, "[0, 20)"});
  for (const char* k : {"step", "max_slope", "max_climb"}) {
    r.push_back({lg + k, {"0", "10"}, {"-0.1", "10.5"}, "[0, 10]"});
  }
  r.push_back({lg + "tolerance", {"1e-09", "10"}, {"0", "10.5"}, "(0, 10]"});
  r.push_back({ls + "voxel", {"0.05", "10"}, {"0.04", "11"}, "[0.05, 10]"});
  r.push_back({ls + "min_points", {"1", "1000000"}, {"0", "1000001"}, "[1, 1000000]"});
  r.push_back({ls + "min_voxel_points", {"3", "1000"}, {"2", "1001"}, "[3, 1000]"});
  for (const char* k : {"pole_max_width", "pole_min_height", "pole_min_span", "building_min_top", "fence_max_top",
                        "fence_max_width"}) {
    r.push_back({ls + k, {"1e-09", "100"}, {"0", "101"}, "(0, 100]"});
  }
  // The slice must stay above its bottom (default 0.5 .. 1.8): the boundaries that keep it so.
  r.push_back({ls + "pole_slice_low", {"0", "1.79"}, {"-0.1", "100.5"}, "[0, 100]"});
  r.push_back({ls + "pole_slice_high", {"0.51", "100"}, {"0", "101"}, "(0, 100]"});
  r.push_back({ls + "pole_voxel", {"0.05", "10"}, {"0.04", "11"}, "[0.05, 10]"});
  r.push_back({ls + "pole_radius", {"1e-09", "10"}, {"0", "10.5"}, "(0, 10]"});
  r.push_back({ls + "pole_max_occluded", {"0", "1"}, {"-0.01", "1.01"}, "[0, 1]"});
  for (const char* k : {"building_min_length", "fence_min_length"}) {
    r.push_back({ls + k, {"1e-09", "1000"}, {"0", "1001"}, "(0, 1000]"});
  }
  for (const char* k : {"min_wall_share", "min_fence_wall_share", "min_scatter_share"}) {
    r.push_back({ls + k, {"0", "1"}, {"-0.1", "1.5"}, "[0, 1]"});
  }
  r.push_back({"registration.ground_ids", {"[]", "[0, 40, 65535]"}, {"[65536]", "[-1]"},
               "ids must be integers 0..65535", true});
  r.push_back({"registration.voxel", {"0.05", "10"}, {"0.04", "11"}, "[0.05, 10]"});
  r.push_back({"registration.max_points", {"100", "1000000"}, {"99", "1000001"}, "[100, 1000000]"});
  r.push_back({"registration.match_voxel", {"0.05", "10"}, {"0", "10.5"}, "[0.05, 10]"});
  r.push_back({"registration.match_max_points", {"100", "1000000"}, {"0", "1000001"}, "[100, 1000000]"});
  r.push_back({"registration.normal_neighbors", {"5", "100"}, {"4", "101"}, "[5, 100]"});
  r.push_back({"registration.max_correspondence", {"1e-09", "10"}, {"0", "10.5"}, "(0, 10]"});
  r.push_back({"registration.coarse_correspondence", {"0", "10"}, {"-0.1", "10.5"}, "[0, 10]"});
  r.push_back({"registration.kernel", {"0", "10"}, {"-0.1", "10.5"}, "[0, 10]"});
  r.push_back({"registration.max_iterations", {"1", "500"}, {"0", "501"}, "[1, 500]"});
  r.push_back({"registration.convergence", {"1e-09", "0.1"}, {"0", "0.2"}, "(0, 0.1]"});
  r.push_back({"registration.min_fitness", {"0", "1"}, {"-0.1", "1.1"}, "[0, 1]"});
  r.push_back({"registration.max_translation_change", {"1e-09", "100"}, {"0", "101"}, "(0, 100]"});
  r.push_back({"registration.max_rotation_change_deg", {"1e-09", "180"}, {"0", "181"}, "(0, 180]"});
  r.push_back({"registration.information_sigma_min", {"1e-09", "10"}, {"0", "11"}, "(0, 10]"});
  r.push_back({"registration.information_scale", {"1e-09", "1"}, {"0", "1.5"}, "(0, 1]"});
  r.push_back({"threads", {"1", "256"}, {"0", "257"}, "[1, 256]"});
  const std::string b = "backend.";
  r.push_back({b + "odometry.translation_sigma_per_m", {"0", "1"}, {"-0.1", "1.5"}, "[0, 1]"});
  r.push_back({b + "odometry.translation_sigma_min", {"1e-09", "100"}, {"0", "100.5"}, "(0, 100]"});
  r.push_back({b + "odometry.rotation_sigma_per_m", {"0", "1"}, {"-0.1", "1.5"}, "[0, 1]"});
  r.push_back({b + "odometry.rotation_sigma_per_rad", {"0", "10"}, {"-1", "11"}, "[0, 10]"});
  r.push_back({b + "odometry.rotation_sigma_min", {"1e-09", "10"}, {"0", "11"}, "(0, 10]"});
  r.push_back({b + "loops.sigma_min", {"1e-09", "100"}, {"0", "-1", "101"}, "(0, 100]"});
  r.push_back({b + "loops.information_scale", {"1e-09", "1"}, {"0", "1.5"}, "(0, 1]"});
  r.push_back({b + "loss_scale", {"1e-09", "1000"}, {"0", "1001"}, "(0, 1000]"});
  r.push_back({b + "consistency.translation_m", {"0", "1000"}, {"-1", "1001"}, "[0, 1000]"});
  r.push_back({b + "consistency.translation_per_m", {"0", "1"}, {"-0.5", "2"}, "[0, 1]"});
  r.push_back({b + "consistency.rotation_rad", {"0", "10"}, {"-0.1", "11"}, "[0, 10]"});
  r.push_back({b + "consistency.rotation_per_m", {"0", "1"}, {"-0.5", "2"}, "[0, 1]"});
  r.push_back({b + "max_loop_chi2", {"1e-09", "1000000000000"}, {"0", "2000000000000"}, "(0, 1000000000000]"});
  r.push_back({b + "max_rejection_rounds", {"0", "100000"}, {"-1", "100001"}, "[0, 100000]"});
  r.push_back({b + "solver.num_threads", {"1", "256"}, {"0", "257"}, "[1, 256]"});
  r.push_back({b + "solver.max_iterations", {"1", "100000"}, {"0", "100001"}, "[1, 100000]"});
  r.push_back({b + "solver.function_tolerance", {"1e-09", "1"}, {"0", "2"}, "(0, 1]"});
  r.push_back({b + "solver.parameter_tolerance", {"1e-09", "1"}, {"0", "2"}, "(0, 1]"});
  r.push_back({b + "online.anchor_spacing_m", {"0", "1000"}, {"-1", "1001"}, "[0, 1000]"});
  r.push_back({"labels.custom_map", {"{0: -1, 65535: 6}"}, {"{65536: 0}", "{-1: 0}"}, "ids must be integers 0..65535",
               true});
  r.push_back({"labels.custom_map", {}, {"{50: 7}", "{50: -2}"}, "classes must be integers -1..6", true});
  r.push_back({"labels.extra_classes", {"[{name: car, ids: [0, 10, 65535]}]"},
               {"[{name: car, ids: [65536]}]", "[{name: car, ids: [-1]}]"}, "entry 0: ids must be integers 0..65535",
               true});
  return r;
}

TEST(ConfigRanges, EveryNumericKeyRejectsValuesOutsideItsRange) {
  for (const Range& row : ranges()) {
    for (const std::string& bad : row.bad) {
      int line = 0;
      const std::string yaml = yamlFor(row.key, bad, &line, row.prelude);
      const std::string at = "my.yaml:" + std::to_string(line) + ": " + row.key;
      const std::string expected =
          row.parse_level ? at + ": " + row.range : at + " = " + bad + " is out of range " + row.range;
      EXPECT_THAT(errorOf(yaml), HasSubstr(expected)) << yaml;
    }
  }
}

TEST(ConfigRanges, EveryNumericKeyAcceptsItsBoundaries) {
  for (const Range& row : ranges()) {
    for (const std::string& good : row.good) {
      EXPECT_EQ(errorOf(yamlFor(row.key, good, nullptr, row.prelude)), "(no error)") << row.key << ": " << good;
    }
  }
}

TEST(ConfigRanges, TheTableCoversEveryNumericKey) {
  // Every key that `sgtllc config` prints with a number (or the id map, or the id lists of extra classes) must have
  // a row, so a new field cannot arrive without a range test. The printed configuration has one extra class.
  std::set<std::string> tested;
  for (const Range& row : ranges()) tested.insert(row.key);
  std::istringstream text(io::configToYaml(io::parseConfig(kVehiclePrelude)));
  std::vector<std::string> path;
  int numeric = 0;
  for (std::string line; std::getline(text, line);) {
    if (line.empty() || line[0] == '#') continue;
    const size_t indent = line.find_first_not_of(' ') / 2;
    const size_t colon = line.find(':');
    path.resize(indent);
    path.push_back(line.substr(2 * indent, colon - 2 * indent));
    std::string value = line.substr(colon + 1);
    value = value.substr(0, value.find("  #"));
    value.erase(0, value.find_first_not_of(' '));
    char* end = nullptr;
    const bool is_number = !value.empty() && (std::strtod(value.c_str(), &end), *end == '\0');
    if (!is_number && value.rfind('{', 0) != 0 && value.rfind('[', 0) != 0) continue;
    std::string key;
    for (const std::string& p : path) key += (key.empty() ? "" : ".") + p;
    EXPECT_TRUE(tested.count(key)) << "no range row for " << key;
    ++numeric;
  }
  // 8 classes incl. vehicle, 40 other keys, 19 backend.*, 16 registration.*, 27 labeller.*
  EXPECT_EQ(numeric, 8 * 3 + 40 + 19 + 16 + 27);
}

TEST(ConfigRanges, Sigma2RangeFollowsTheNodeScore) {
  EXPECT_EQ(errorOf("association:\n  score: count\n  sigma_2: 49\n"), "(no error)");
  EXPECT_THAT(errorOf("association:\n  score: count\n  sigma_2: 49.5\n"),
              HasSubstr("my.yaml:3: association.sigma_2 = 49.5 is out of range [0, 49] (association.score: count)"));
}

TEST(ConfigRanges, OffsetDecayEndsAfterItStarts) {
  EXPECT_EQ(errorOf("verification:\n  offset_decay_start: 30\n  offset_decay_end: 0\n"), "(no error)");
  EXPECT_EQ(errorOf("verification:\n  offset_decay_start: 30\n  offset_decay_end: 30.5\n"), "(no error)");
  EXPECT_THAT(errorOf("verification:\n  offset_decay_start: 30\n"),
              HasSubstr("verification.offset_decay_end = 20 must be 0 (no decay) or greater than "
                        "verification.offset_decay_start = 30"));
}

TEST(ConfigRanges, DuplicatedKeysNameTheKeyAndBothLines) {
  EXPECT_THAT(errorOf("graph:\n  sigma_d: 20\n  max_nodes: 50\n  sigma_d: 25\n"),
              HasSubstr("my.yaml:4: key 'graph.sigma_d' appears twice, at lines 2 and 4"));
  EXPECT_THAT(errorOf("threads: 1\nverification:\n  seed: 1\nthreads: 2\n"),
              HasSubstr("my.yaml:4: key 'threads' appears twice, at lines 1 and 4"));
  // A whole section given twice, and a repeated key in a flow map.
  EXPECT_THAT(errorOf("graph:\n  sigma_d: 20\nretrieval:\n  num_candidates: 5\ngraph:\n  max_nodes: 9\n"),
              HasSubstr("my.yaml:5: key 'graph' appears twice, at lines 1 and 5"));
  EXPECT_THAT(errorOf("labels:\n  preset: custom\n  custom_map: {50: 0, 70: 2, 50: 1}\n"),
              HasSubstr("my.yaml:3: key 'labels.custom_map.50' appears twice, at lines 3 and 3"));
  EXPECT_THAT(errorOf("labels:\n  custom_map: {50: 0, 050: 1}\n"), HasSubstr("id 50 is listed twice"));
}

TEST(ConfigRanges, TheLibraryNamesTheKeyAndTheRange) {
  Config config;
  config.verification.sigma_4 = 5.0;
  try {
    LoopDetector detector(config);
    FAIL() << "no error";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.key(), "verification.sigma_4");
    EXPECT_STREQ(e.what(), "verification.sigma_4 = 5 is out of range [0, 1]");
  }
  config = Config{};
  config.retrieval.num_candidates = 1000000000;
  EXPECT_THROW(comparePair(std::vector<Node>{}, std::vector<Node>{}, config), ConfigError);
  config = Config{};
  config.graph.sigma_d = std::nan("");
  EXPECT_THROW(config.validate(), ConfigError);
}

}  // namespace
}  // namespace sgtllc
