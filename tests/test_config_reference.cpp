// The settings table's documents: docs/configuration.md is what `sgtllc config --markdown` prints today, and every
// key the README's configuration table names is a setting of the table.
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "sgtllc/config/settings.h"
#include "sgtllc/io/config_reference.h"

namespace sgtllc {
namespace {

std::string readSource(const std::string& relative) {
  std::ifstream in(std::string(SGTLLC_DATA_DIR) + "/../" + relative);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(ConfigReference, TheDocumentIsCurrent) {
  const std::string reference = io::configReference(Config{});
  EXPECT_EQ(readSource("docs/configuration.md"), reference)
      << "regenerate it: build/apps/sgtllc/sgtllc config --markdown > docs/configuration.md";
  // One row per setting, with the value and range the table gives.
  for (const Setting& s : settingsFor(LabelConfig{})) {
    EXPECT_NE(reference.find("| `" + s.key + "` |"), std::string::npos) << s.key;
  }
  EXPECT_NE(reference.find("| `verification.sigma_4` | `0.3` | [0, 1] |"), std::string::npos);
  EXPECT_NE(reference.find("| `cluster.building.voxel` | `0.4` | 0 (no downsampling) or [0.001, 10] | voxel leaf (m) |"),
            std::string::npos);
}

/// The keys of the README's configuration table: `a.b.c / d` names a.b.c and a.b.d, `x.*` every key under x,
/// `cluster.<class>.k` that key of every class.
std::vector<std::string> readmeKeys() {
  const std::string readme = readSource("README.md");
  const size_t from = readme.find("## Configuration\n");
  const size_t to = readme.find("\n## ", from + 1);
  std::vector<std::string> keys;
  std::istringstream table(readme.substr(from, to - from));
  const std::regex row("^\\| `([^`]+)`");
  for (std::string line; std::getline(table, line);) {
    std::smatch m;
    if (!std::regex_search(line, m, row)) continue;
    std::string cell = m[1];
    cell = std::regex_replace(cell, std::regex("<class>"), "building");
    std::string prefix;
    std::stringstream parts(cell);
    for (std::string part; std::getline(parts, part, '/');) {
      part = std::regex_replace(part, std::regex("^ +| +$"), "");
      if (part.find('.') != std::string::npos || prefix.empty()) {
        prefix = part.substr(0, part.rfind('.') + 1);
        keys.push_back(part);
      } else {
        keys.push_back(prefix + part);
      }
    }
  }
  return keys;
}

TEST(ConfigReference, TheReadmeTableNamesOnlySettingsOfTheTable) {
  std::set<std::string> table;
  for (const Setting& s : settingsFor(LabelConfig{})) table.insert(s.key);
  const std::vector<std::string> keys = readmeKeys();
  ASSERT_GE(keys.size(), 40u);
  for (const std::string& key : keys) {
    bool found = table.count(key) > 0;
    if (key.back() == '*') {  // a group: some setting must start with it
      const std::string head = key.substr(0, key.size() - 1);
      for (const std::string& k : table) found = found || k.rfind(head, 0) == 0;
    }
    EXPECT_TRUE(found) << "README names " << key << ", which is not a setting";
  }
}

}  // namespace
}  // namespace sgtllc
