// Config ranges: every numeric key rejects a value outside its range in the settings table with a message naming
// the file, the line, the YAML key and the range, and accepts the range's boundaries.
#include <algorithm>
#include <map>
#include <cmath>
#include <cstdlib>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "config/config_ranges.h"
#include "sgtllc/config/settings.h"
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

/// One key: values that must load, values that must not, and the range the message states.
struct Range {
  std::string key;
  std::vector<std::string> good;  ///< the boundaries (and, for open ends, a value just inside)
  std::vector<std::string> bad;   ///< written as the message prints them (shortest round-trip text)
  std::string range;              ///< "[0, 1]"; or, for a check made while parsing, the parser's message
  bool parse_level = false;       ///< the YAML reader rejects the value before Config::validate() sees it
  std::string prelude = {};       ///< YAML before the key (the declaration of an extra class)
};

/// The rows of one numeric setting, from its range in the settings table: the closed ends and values just inside
/// the open ones load; values just outside the closed ends, the open ends themselves and far values do not.
std::vector<Range> rowsOf(const Setting& s, const std::string& prelude) {
  const bool integer = s.type == SettingType::kInteger;
  const SettingRange& r = s.range;
  const double step = integer ? 1.0 : std::max((r.hi - r.lo) * 1e-3, 1e-6);
  auto show = [integer](double v) { return integer ? detail::text(static_cast<long long>(v)) : detail::text(v); };
  Range in{s.key, {}, {}, r.text(), false, prelude};
  Range parse{s.key, {}, {}, "", true, prelude};  // integers beyond what the member holds
  in.good.push_back(show(r.lo_open ? r.lo + step : r.lo));
  in.good.push_back(show(r.hi_open ? r.hi - step : r.hi));
  if (!r.zero_means.empty()) in.good.push_back("0");
  for (double bad : {r.lo_open ? r.lo : r.lo - step, r.hi_open ? r.hi : r.hi + step, r.hi + 1000 * (r.hi - r.lo)}) {
    if (integer && (bad < s.storage_lo || bad > s.storage_hi)) {
      parse.bad.push_back(show(bad));
      parse.range = "expected an integer in " + show(s.storage_lo) + ".." + show(s.storage_hi);
    } else if (!(bad == 0.0 && !r.zero_means.empty())) {
      in.bad.push_back(show(bad));
    }
  }
  std::vector<Range> rows = {in};
  if (!parse.bad.empty()) rows.push_back(parse);
  return rows;
}

std::vector<Range> ranges() {
  std::vector<Range> r;
  // Every checked number of the table, with one extra class so that cluster.NAME of an extra class is tested too.
  for (const Setting& s : settingsFor(io::parseConfig(kVehiclePrelude).labels)) {
    if ((s.type != SettingType::kReal && s.type != SettingType::kInteger) || !s.range.checked) continue;
    const std::string prelude = s.key.rfind("cluster.vehicle.", 0) == 0 ? kVehiclePrelude : "";
    for (Range& row : rowsOf(s, prelude)) r.push_back(std::move(row));
  }
  // What the parser checks itself: ids, and the classes of the id map.
  r.push_back({"registration.ground_ids", {"[]", "[0, 40, 65535]"}, {"[65536]", "[-1]"},
               "ids must be integers 0..65535", true});
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
      // A rule between two settings may still refuse a boundary (pole_slice_low 100 is never below
      // pole_slice_high); the range itself must not.
      const std::string error = errorOf(yamlFor(row.key, good, nullptr, row.prelude));
      EXPECT_TRUE(error == "(no error)" || error.find(" must be ") != std::string::npos) << row.key << ": " << error;
      EXPECT_EQ(error.find("out of range"), std::string::npos) << row.key << ": " << error;
    }
  }
}

TEST(ConfigRanges, TheRowsCoverEveryNumericKey) {
  // Every key that `sgtllc config` prints with a number (or the id map, or the id lists) has a row, so a setting
  // cannot lose its range check; σ_2's range is a rule of its own (below). The printed configuration has one
  // extra class.
  std::set<std::string> tested;
  std::map<std::string, std::string> range_of;
  for (const Range& row : ranges()) {
    tested.insert(row.key);
    if (!row.parse_level) range_of[row.key] = row.range;
  }
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
    if (key != "association.sigma_2") {
      EXPECT_TRUE(tested.count(key)) << "no range row for " << key;
    }
    ++numeric;
  }
  EXPECT_EQ(numeric, 8 * 3 + 43 + 23 + 16 + 28);  // 8 classes incl. vehicle, backend.*, registration.*, labeller.*
  // A few of the table's ranges, pinned: a range changed by mistake shows here.
  EXPECT_EQ(range_of["verification.sigma_4"], "[0, 1]");
  EXPECT_EQ(range_of["graph.sigma_d"], "(0, 1000]");
  EXPECT_EQ(range_of["cluster.vehicle.voxel"], "0 (no downsampling) or [0.001, 10]");
  EXPECT_EQ(range_of["labeller.ground.min_range"], "[0, 20)");
  EXPECT_EQ(range_of["threads"], "[1, 256]");
  EXPECT_EQ(range_of["backend.max_loop_chi2"], "(0, 1000000000000]");
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
