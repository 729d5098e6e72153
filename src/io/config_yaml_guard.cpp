// Checks around yaml-cpp for configuration files (config_yaml_guard.h): aliases refused before the node tree is
// built, and the nearest known key for an unknown one.
#include "config_yaml_guard.h"

#include <algorithm>
#include <set>
#include <sstream>

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/parser.h>
#include <yaml-cpp/yaml.h>

#include "sgtllc/types.h"

namespace sgtllc::io::detail {
namespace {

/// Stops at the first anchor or alias; every other event is ignored.
class AliasGuard : public YAML::EventHandler {
 public:
  explicit AliasGuard(const std::string& source) : source_(source) {}
  void OnDocumentStart(const YAML::Mark&) override {}
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& mark, YAML::anchor_t anchor) override { check(mark, anchor); }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t) override { refuse(mark); }
  void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor, const std::string&) override {
    check(mark, anchor);
  }
  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                       YAML::EmitterStyle::value) override {
    check(mark, anchor);
  }
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                  YAML::EmitterStyle::value) override {
    check(mark, anchor);
  }
  void OnMapEnd() override {}
  void OnAnchor(const YAML::Mark& mark, const std::string&) override { refuse(mark); }

 private:
  void check(const YAML::Mark& mark, YAML::anchor_t anchor) const {
    if (anchor != YAML::NullAnchor) refuse(mark);
  }
  [[noreturn]] void refuse(const YAML::Mark& mark) const {
    const std::string line = mark.line >= 0 ? ":" + std::to_string(mark.line + 1) : "";
    throw Error(source_ + line + ": YAML aliases and anchors are not supported in sgtllc configs");
  }
  const std::string& source_;
};

/// Optimal string alignment distance: insertions, deletions, substitutions and swaps of neighbours cost 1.
size_t editDistance(const std::string& a, const std::string& b) {
  const size_t n = a.size(), m = b.size();
  std::vector<std::vector<size_t>> d(n + 1, std::vector<size_t>(m + 1));
  for (size_t i = 0; i <= n; ++i) d[i][0] = i;
  for (size_t j = 0; j <= m; ++j) d[0][j] = j;
  for (size_t i = 1; i <= n; ++i) {
    for (size_t j = 1; j <= m; ++j) {
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
      }
    }
  }
  return d[n][m];
}

}  // namespace

void rejectAliases(const std::string& yaml, const std::string& source) {
  std::istringstream in(yaml);
  YAML::Parser parser(in);
  AliasGuard guard(source);
  // The first document only: YAML::Load reads no other. (yaml-cpp 0.7 can also return "another document" forever
  // after some malformed text, which fuzz_config_yaml found; fuzz/regressions/config_yaml.)
  parser.HandleNextDocument(guard);
}

std::string closestKey(const std::vector<Field>& fields, const std::string& prefix, const std::string& name) {
  // A key far longer than any known one is no typo; it also bounds the distance table.
  constexpr size_t kLongest = 128;
  if (name.empty() || name.size() > kLongest) return "";
  const std::string head = prefix.empty() ? "" : prefix + ".";
  std::set<std::string> names;  // the known names at this level, sorted: ties go to the first
  for (const Field& f : fields) {
    if (f.key.compare(0, head.size(), head) != 0) continue;
    names.insert(f.key.substr(head.size(), f.key.find('.', head.size()) - head.size()));
  }
  std::string best;
  size_t best_distance = std::max<size_t>(2, name.size() / 3) + 1;
  for (const std::string& known : names) {
    const size_t d = editDistance(name, known);
    if (d < best_distance && d < name.size()) {
      best = known;
      best_distance = d;
    }
  }
  return best.empty() ? "" : head + best;
}

}  // namespace sgtllc::io::detail
