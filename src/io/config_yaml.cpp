#include "sgtllc/io/config_yaml.h"

#include <algorithm>
#include <map>
#include <sstream>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "config_fields.h"
#include "config_yaml_guard.h"
#include "file_util.h"
#include "sgtllc/io/quote.h"

namespace sgtllc::io {
namespace {

using detail::Field;
using detail::fieldsFor;

const Field* findField(const std::vector<Field>& fields, const std::string& key) {
  for (const Field& f : fields) {
    if (f.key == key) return &f;
  }
  return nullptr;
}

bool isSection(const std::vector<Field>& fields, const std::string& prefix) {
  for (const Field& f : fields) {
    if (f.key.compare(0, prefix.size() + 1, prefix + ".") == 0) return true;
  }
  return false;
}

/// 1-based line of @p node, or 0 if yaml-cpp has no mark for it.
int lineOf(const YAML::Node& node) { return node.Mark().line >= 0 ? node.Mark().line + 1 : 0; }

std::string where(const std::string& source, int line) {
  return line > 0 ? source + ":" + std::to_string(line) : source;
}

std::string where(const std::string& source, const YAML::Node& node) { return where(source, lineOf(node)); }

/// yaml-cpp 0.7 keeps both pairs of a repeated key and a plain lookup silently takes one, so every map of the
/// document, at any depth, is scanned for a key that appears twice.
void rejectDuplicateKeys(const YAML::Node& node, const std::string& prefix, const std::string& source) {
  if (node.IsSequence()) {
    for (size_t i = 0; i < node.size(); ++i) {
      rejectDuplicateKeys(node[i], prefix + "[" + std::to_string(i) + "]", source);
    }
    return;
  }
  if (!node.IsMap()) return;
  std::map<std::string, int> seen;  // key text → line of its first appearance
  for (const auto& kv : node) {
    const std::string name = kv.first.IsScalar() ? kv.first.Scalar() : YAML::Dump(kv.first);
    const std::string key = prefix.empty() ? name : prefix + "." + name;
    const auto [first, fresh] = seen.emplace(name, lineOf(kv.first));
    if (!fresh) {
      throw Error(where(source, kv.first) + ": key " + quoteContent(key, 256) + " appears twice, at lines " +
                  std::to_string(first->second) + " and " + std::to_string(lineOf(kv.first)) + "; keep one");
    }
    rejectDuplicateKeys(kv.second, key, source);
  }
}

/// Line of each key the document set, for range errors found after parsing.
using KeyLines = std::map<std::string, int>;

void apply(Config& config, const std::vector<Field>& fields, const YAML::Node& map, const std::string& prefix,
           const std::string& source, KeyLines& lines) {
  for (const auto& kv : map) {
    const std::string name = kv.first.IsScalar() ? kv.first.Scalar() : std::string("?");
    const std::string key = prefix.empty() ? name : prefix + "." + name;
    if (const Field* field = findField(fields, key)) {
      lines[key] = lineOf(kv.second);
      const std::string err = field->set(config, kv.second);
      if (!err.empty()) {
        const std::string got = kv.second.IsScalar() ? kv.second.Scalar() : YAML::Dump(kv.second);
        throw Error(where(source, kv.second) + ": " + key + ": " + err + ", got " + quoteContent(got));
      }
    } else if (isSection(fields, key)) {
      if (!kv.second.IsMap()) throw Error(where(source, kv.second) + ": " + key + ": expected a map of keys");
      apply(config, fields, kv.second, key, source, lines);
    } else {
      const std::string close = detail::closestKey(fields, prefix, name);
      const std::string mean = close.empty() ? "" : "did you mean `" + close + "`? ";
      const char* hint = prefix == "cluster" ? "; a new class is declared in labels.extra_classes" : "";
      throw Error(where(source, kv.first) + ": unknown key " + quoteContent(key, 256) + " (" + mean +
                  "run `sgtllc config` for the valid keys" + hint + ")");
    }
  }
}

/// Config::validate, with the file and line of the offending key in the message.
void validate(const Config& config, const KeyLines& lines, const std::string& source) {
  try {
    config.validate();
  } catch (const ConfigError& e) {
    // The key is a field key, or one part of one: "labels.custom_map[ID]", "labels.extra_classes[K].ids".
    std::string key = e.key();
    while (!key.empty() && !lines.count(key)) {
      const size_t cut = key.find_last_of(".[");
      key.resize(cut == std::string::npos ? 0 : cut);
    }
    throw ConfigError(e.key(), where(source, key.empty() ? 0 : lines.at(key)) + ": " + e.what());
  }
}

/// Reads labels.extra_classes and the rest of `labels` (custom_map targets the extra classes) and sizes
/// cluster.classes to the class count, so that the document's cluster.NAME keys exist.
void applyClassSet(Config& config, const YAML::Node& root, const std::string& source, KeyLines& lines) {
  const YAML::Node labels = root["labels"];
  if (!labels || !labels.IsMap()) return;
  const std::vector<Field> fields = fieldsFor(config.labels);
  if (const YAML::Node extra = labels["extra_classes"]) {
    YAML::Node only(YAML::NodeType::Map);
    only["extra_classes"] = extra;
    apply(config, fields, only, "labels", source, lines);
    for (size_t k = 0; extra.IsSequence() && k < extra.size(); ++k) {
      const std::string key = "labels.extra_classes[" + std::to_string(k) + "]";
      lines[key] = lineOf(extra[k]);
      for (const char* part : {"name", "ids"}) {
        if (extra[k][part]) lines[key + "." + part] = lineOf(extra[k][part]);
      }
    }
  }
  apply(config, fields, labels, "labels", source, lines);
  config.cluster.classes.resize(static_cast<size_t>(std::min(config.numClasses(), kMaxClasses + 1)));
  validate(config, lines, source);  // the class set, before its names become keys
}

}  // namespace

std::string configToYaml(const Config& config) {
  std::ostringstream out;
  out << "# sgtllc configuration. Keys mirror sgtllc::Config (include/sgtllc/config.h); omitted keys keep\n"
         "# the defaults printed by `sgtllc config`. Symbols follow the SGT-LLC paper and the sections of docs/algorithm.md.\n";
  std::vector<std::string> open;  // current section path
  for (const Field& f : fieldsFor(config.labels)) {
    std::vector<std::string> parts;
    std::stringstream ss(f.key);
    for (std::string part; std::getline(ss, part, '.');) parts.push_back(part);
    size_t common = 0;
    while (common < open.size() && common + 1 < parts.size() && open[common] == parts[common]) ++common;
    open.resize(common);
    for (size_t d = common; d + 1 < parts.size(); ++d) {
      out << std::string(2 * d, ' ') << parts[d] << ":\n";
      open.push_back(parts[d]);
    }
    out << std::string(2 * (parts.size() - 1), ' ') << parts.back() << ": " << f.print(config) << "  # "
        << f.comment << "\n";
  }
  return out.str();
}

std::vector<std::pair<std::string, std::string>> configValues(const Config& config) {
  std::vector<std::pair<std::string, std::string>> values;
  for (const Field& f : fieldsFor(config.labels)) values.emplace_back(f.key, f.print(config));
  return values;
}

Config parseConfig(const std::string& yaml, const std::string& source) {
  YAML::Node root;
  try {
    detail::rejectAliases(yaml, source);  // before YAML::Load: walking an alias bomb's tree never ends
    root = YAML::Load(yaml);
  } catch (const YAML::Exception& e) {
    throw Error(source + ":" + std::to_string(e.mark.line + 1) + ": malformed YAML: " + escapeControls(e.msg));
  }
  Config config;
  if (root.IsNull()) return config;
  if (!root.IsMap()) throw Error(source + ": expected a map of configuration keys at the top level");
  rejectDuplicateKeys(root, "", source);
  KeyLines lines;
  applyClassSet(config, root, source, lines);
  apply(config, fieldsFor(config.labels), root, "", source, lines);
  validate(config, lines, source);
  return config;
}

Config loadConfig(const std::string& path) {
  // detail::readWholeFile names the file and the reason (missing, a directory, unreadable).
  return parseConfig(detail::readWholeFile(path), path);
}

}  // namespace sgtllc::io
