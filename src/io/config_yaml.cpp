#include "sgtllc/io/config_yaml.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <charconv>
#include <cstdlib>
#include <functional>
#include <limits>
#include <map>
#include <sstream>
#include <utility>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "file_util.h"

namespace sgtllc::io {
namespace {

/// One configuration leaf: its dotted key, its comment, and how to print and set it.
struct Field {
  std::string key;
  std::string comment;
  std::function<std::string(const Config&)> print;
  /// Sets the value from a YAML node; returns an error text ("" on success).
  std::function<std::string(Config&, const YAML::Node&)> set;
};

std::string formatDouble(double v) {
  char buf[32];
  const auto res = std::to_chars(buf, buf + sizeof(buf), v);
  std::string s(buf, res.ptr);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";  // keep floats recognisable as floats
  return s;
}

bool parseDouble(const std::string& s, double* out) {
  if (s.empty()) return false;
  char* end = nullptr;
  errno = 0;
  *out = std::strtod(s.c_str(), &end);
  return errno == 0 && end == s.c_str() + s.size() && std::isfinite(*out);
}

bool parseInt(const std::string& s, long long lo, long long hi, long long* out) {
  if (s.empty()) return false;
  const auto res = std::from_chars(s.data(), s.data() + s.size(), *out);
  return res.ec == std::errc() && res.ptr == s.data() + s.size() && *out >= lo && *out <= hi;
}

std::string scalarText(const YAML::Node& node) { return node.IsScalar() ? node.Scalar() : std::string(); }

using DoubleRef = std::function<double&(Config&)>;

Field number(std::string key, std::string comment, DoubleRef ref) {
  return Field{std::move(key), std::move(comment),
               [ref](const Config& c) { return formatDouble(ref(const_cast<Config&>(c))); },
               [ref](Config& c, const YAML::Node& n) -> std::string {
                 double v = 0.0;
                 if (!parseDouble(scalarText(n), &v)) return "expected a finite number";
                 ref(c) = v;
                 return "";
               }};
}

template <typename T>
Field integer(std::string key, std::string comment, std::function<T&(Config&)> ref) {
  return Field{std::move(key), std::move(comment),
               [ref](const Config& c) { return std::to_string(ref(const_cast<Config&>(c))); },
               [ref](Config& c, const YAML::Node& n) -> std::string {
                 long long v = 0;
                 const long long lo = std::numeric_limits<T>::min(), hi = std::numeric_limits<T>::max();
                 if (!parseInt(scalarText(n), lo, hi, &v)) {
                   return "expected an integer in " + std::to_string(lo) + ".." + std::to_string(hi);
                 }
                 ref(c) = static_cast<T>(v);
                 return "";
               }};
}

Field boolean(std::string key, std::string comment, std::function<bool&(Config&)> ref) {
  return Field{std::move(key), std::move(comment),
               [ref](const Config& c) { return std::string(ref(const_cast<Config&>(c)) ? "true" : "false"); },
               [ref](Config& c, const YAML::Node& n) -> std::string {
                 const std::string s = scalarText(n);
                 if (s != "true" && s != "false") return "expected true or false";
                 ref(c) = (s == "true");
                 return "";
               }};
}

template <typename E>
Field choice(std::string key, std::string comment, std::function<E&(Config&)> ref,
             std::vector<std::pair<std::string, E>> names) {
  std::string options;
  for (const auto& [name, value] : names) options += (options.empty() ? "" : " | ") + name;
  comment += " (" + options + ")";
  return Field{std::move(key), std::move(comment),
               [ref, names](const Config& c) {
                 const E v = ref(const_cast<Config&>(c));
                 for (const auto& [name, value] : names) {
                   if (value == v) return name;
                 }
                 return std::string("?");
               },
               [ref, names, options](Config& c, const YAML::Node& n) -> std::string {
                 const std::string s = scalarText(n);
                 for (const auto& [name, value] : names) {
                   if (name == s) {
                     ref(c) = value;
                     return "";
                   }
                 }
                 return "expected one of " + options;
               }};
}

Field customMap() {
  return Field{
      "labels.custom_map",
      "raw id: class index 0..C-1 (building … traffic-sign, then extra classes) or -1 (known, dropped); "
      "used with preset custom",
      [](const Config& c) {
        std::string s = "{";
        for (const auto& [id, cls] : c.labels.custom_map) {
          s += (s.size() > 1 ? ", " : "") + std::to_string(id) + ": " + std::to_string(cls);
        }
        return s + "}";
      },
      [](Config& c, const YAML::Node& n) -> std::string {
        if (!n.IsMap() && !n.IsNull()) return "expected a map of id: class";
        c.labels.custom_map.clear();
        if (n.IsNull()) return "";
        const int last = c.labels.numClasses() - 1;  // labels.extra_classes is read first (parseConfig)
        for (const auto& kv : n) {
          long long id = 0, cls = 0;
          if (!parseInt(scalarText(kv.first), 0, 0xFFFF, &id)) return "ids must be integers 0..65535";
          if (!parseInt(scalarText(kv.second), -1, last, &cls)) {
            return "classes must be integers -1.." + std::to_string(last) + " (id " + std::to_string(id) + ")";
          }
          // Spellings such as 50 and 050 pass the duplicate-key scan but name the same id.
          if (c.labels.custom_map.count(static_cast<uint32_t>(id))) {
            return "id " + std::to_string(id) + " is listed twice";
          }
          c.labels.custom_map[static_cast<uint32_t>(id)] = static_cast<int>(cls);
        }
        return "";
      }};
}

/// One entry of labels.extra_classes, `{name: NAME, ids: [ID, …]}`; returns an error text ("" on success).
std::string readExtraClass(const YAML::Node& n, ExtraClass* out) {
  if (!n.IsMap()) return "expected a map {name: NAME, ids: [ID, ...]}";
  bool has_name = false;
  for (const auto& kv : n) {
    const std::string key = scalarText(kv.first);
    if (key == "name") {
      if (!kv.second.IsScalar()) return "name: expected a class name";
      out->name = kv.second.Scalar();
      has_name = true;
    } else if (key == "ids") {
      if (!kv.second.IsSequence()) return "ids: expected a list of raw ids, e.g. [10, 252]";
      for (const auto& id : kv.second) {
        long long v = 0;
        if (!parseInt(scalarText(id), 0, 0xFFFF, &v)) return "ids must be integers 0..65535";
        out->ids.push_back(static_cast<uint32_t>(v));
      }
    } else {
      return "unknown key '" + key + "' (expected name and ids)";
    }
  }
  return has_name ? "" : "missing name";
}

Field extraClasses() {
  return Field{
      "labels.extra_classes",
      "classes beyond the seven, indices 7, 8, …: [{name: vehicle, ids: [10, 252]}] with cluster.NAME below; "
      "at most 16 classes C in all (descriptors: C² slots × 3 per node, G1/G3 2·C², G2 C³ floats per frame)",
      [](const Config& c) {
        std::string s = "[";
        for (const ExtraClass& e : c.labels.extra_classes) {
          s += (s.size() > 1 ? ", " : "") + std::string("{name: ") + e.name + ", ids: [";
          for (size_t k = 0; k < e.ids.size(); ++k) s += (k ? ", " : "") + std::to_string(e.ids[k]);
          s += "]}";
        }
        return s + "]";
      },
      [](Config& c, const YAML::Node& n) -> std::string {
        if (!n.IsSequence() && !n.IsNull()) return "expected a list of {name: NAME, ids: [ID, ...]}";
        c.labels.extra_classes.clear();
        if (n.IsNull()) return "";
        for (size_t k = 0; k < n.size(); ++k) {
          ExtraClass extra;
          const std::string err = readExtraClass(n[k], &extra);
          if (!err.empty()) return "entry " + std::to_string(k) + ": " + err;
          c.labels.extra_classes.push_back(std::move(extra));
        }
        return "";
      }};
}

/// association.entries as the letters of the kept vertices, e.g. "ijk" or "ik".
Field entriesField() {
  return Field{"association.entries", "sub-vector entries compared, by vertex: any of i, j, k (ablation)",
               [](const Config& c) {
                 std::string s;
                 for (int v = 0; v < 3; ++v) {
                   if (c.association.entries & (1u << v)) s += "ijk"[v];
                 }
                 return s;
               },
               [](Config& c, const YAML::Node& n) -> std::string {
                 const std::string s = scalarText(n);
                 unsigned mask = 0;
                 for (char ch : s) {
                   const size_t v = std::string("ijk").find(ch);
                   if (v == std::string::npos || (mask & (1u << v))) return "expected distinct letters from i, j, k";
                   mask |= 1u << v;
                 }
                 if (mask == 0) return "expected distinct letters from i, j, k";
                 c.association.entries = mask;
                 return "";
               }};
}

/// Every key, in print order, for the class set of @p labels (one cluster.NAME section per class).
std::vector<Field> fieldsFor(const LabelConfig& labels) {
  std::vector<Field> f;
  f.push_back(choice<LabelPreset>("labels.preset", "id convention of the input labels (spec §1, §8)",
                                  [](Config& c) -> LabelPreset& { return c.labels.preset; },
                                  {{"semantickitti", LabelPreset::kSemanticKittiRaw},
                                   {"semantickitti_learning", LabelPreset::kSemanticKittiLearning},
                                   {"mulran", LabelPreset::kMulRan},
                                   {"mcd", LabelPreset::kMcd},
                                   {"custom", LabelPreset::kCustom}}));
  f.push_back(customMap());
  f.push_back(extraClasses());
  for (int k = 0; k < labels.numClasses(); ++k) {
    const std::string p = "cluster." + labels.className(k) + ".";
    f.push_back(number(p + "voxel", "voxel leaf (m); 0 = no downsampling",
                       [k](Config& c) -> double& { return c.cluster.classes.at(k).voxel; }));
    f.push_back(number(p + "radius", "FEC radius r (m)",
                       [k](Config& c) -> double& { return c.cluster.classes.at(k).radius; }));
    f.push_back(integer<int>(p + "min_size", "minimum cluster size (voxels if voxel > 0, else points)",
                        [k](Config& c) -> int& { return c.cluster.classes.at(k).min_size; }));
  }
  f.push_back(integer<int>("cluster.max_neighbors", "FEC neighbour cap per radius query, seed included",
                      [](Config& c) -> int& { return c.cluster.max_neighbors; }));
  f.push_back(number("cluster.duplicate_radius", "skip a cluster this close to an accepted same-class centre (m)",
                     [](Config& c) -> double& { return c.cluster.duplicate_radius; }));
  f.push_back(choice<CentreSource>("cluster.centre", "node centre: mean of original points or of voxel centroids",
                                   [](Config& c) -> CentreSource& { return c.cluster.centre; },
                                   {{"points", CentreSource::kPoints}, {"voxels", CentreSource::kVoxels}}));
  f.push_back(number("graph.sigma_d", "σ_d: edge iff centre distance < σ_d (m)",
                     [](Config& c) -> double& { return c.graph.sigma_d; }));
  f.push_back(integer<int>("graph.max_nodes", "most nodes per frame (a scan keeps its largest clusters)",
                           [](Config& c) -> int& { return c.graph.max_nodes; }));
  f.push_back(boolean("graph.allow_k_equals_i", "allow the path i→j→i (authors' code)",
                      [](Config& c) -> bool& { return c.graph.allow_k_equals_i; }));
  f.push_back(choice<SubVectorKind>("descriptor.kind", "slot entries: dot products, angles only, lengths only",
                                    [](Config& c) -> SubVectorKind& { return c.descriptor.kind; },
                                    {{"dot", SubVectorKind::kDotProducts},
                                     {"angle", SubVectorKind::kAngles},
                                     {"length", SubVectorKind::kLengths}}));
  f.push_back(choice<SubVectorOrder>("descriptor.order", "sub-vector entries: (a_i,a_j,a_k) or (a_i,a_k,-a_j)",
                                     [](Config& c) -> SubVectorOrder& { return c.descriptor.order; },
                                     {{"paper", SubVectorOrder::kPaper}, {"code", SubVectorOrder::kCode}}));
  f.push_back(choice<GlobalMode>("descriptor.global_mode", "global descriptor (spec §5)",
                                 [](Config& c) -> GlobalMode& { return c.descriptor.global_mode; },
                                 {{"G1", GlobalMode::kG1}, {"G2", GlobalMode::kG2}, {"G3", GlobalMode::kG3}}));
  f.push_back(integer<int>("retrieval.num_candidates", "K: candidates retrieved per query",
                      [](Config& c) -> int& { return c.retrieval.num_candidates; }));
  f.push_back(integer<int>("retrieval.exclude_recent", "G: query q searches frames <= q - G",
                      [](Config& c) -> int& { return c.retrieval.exclude_recent; }));
  f.push_back(integer<int>("retrieval.warmup_frames", "no query before this many frames (authors' code: 150)",
                      [](Config& c) -> int& { return c.retrieval.warmup_frames; }));
  f.push_back(choice<RetrievalMethod>("retrieval.method", "nearest-neighbour search",
                                      [](Config& c) -> RetrievalMethod& { return c.retrieval.method; },
                                      {{"brute_force", RetrievalMethod::kBruteForce},
                                       {"kdtree", RetrievalMethod::kKdTree}}));
  f.push_back(number("association.sigma_1", "σ_1: a slot matches iff cos(u, v) > σ_1",
                     [](Config& c) -> double& { return c.association.sigma_1; }));
  f.push_back(number("association.max_delta_aj", "... and |Δa_j| < this (m²)",
                     [](Config& c) -> double& { return c.association.max_delta_aj; }));
  f.push_back(number("association.sigma_2", "σ_2: accept the best node pair iff S >= σ_2",
                     [](Config& c) -> double& { return c.association.sigma_2; }));
  f.push_back(choice<NodeScore>("association.score", "node similarity S",
                                [](Config& c) -> NodeScore& { return c.association.score; },
                                {{"ratio", NodeScore::kRatio}, {"count", NodeScore::kCount}}));
  f.push_back(entriesField());
  f.push_back(number("verification.sigma_3", "σ_3: skip a candidate iff score_c < σ_3",
                     [](Config& c) -> double& { return c.verification.sigma_3; }));
  f.push_back(integer<int>("verification.min_associations", "... or |LA| < this",
                      [](Config& c) -> int& { return c.verification.min_associations; }));
  f.push_back(integer<int>("verification.ransac_iterations", "RANSAC hypotheses per candidate",
                      [](Config& c) -> int& { return c.verification.ransac_iterations; }));
  f.push_back(integer<int>("verification.ransac_sample_size", "node pairs per hypothesis",
                      [](Config& c) -> int& { return c.verification.ransac_sample_size; }));
  f.push_back(boolean("verification.sample_with_replacement", "draw pairs with replacement (authors' code)",
                      [](Config& c) -> bool& { return c.verification.sample_with_replacement; }));
  f.push_back(number("verification.inlier_threshold", "inlier iff ‖R s + t − t′‖ < this (m)",
                     [](Config& c) -> double& { return c.verification.inlier_threshold; }));
  f.push_back(integer<int>("verification.min_inliers", "accept a hypothesis only with >= this many inliers",
                      [](Config& c) -> int& { return c.verification.min_inliers; }));
  f.push_back(number("verification.min_inlier_fraction", "... and >= this share of |LA|",
                     [](Config& c) -> double& { return c.verification.min_inlier_fraction; }));
  f.push_back(boolean("verification.use_ransac", "false = score_c as the score, pose from all associations",
                      [](Config& c) -> bool& { return c.verification.use_ransac; }));
  f.push_back(number("verification.ransac_confidence",
                     "stop RANSAC once an all-inlier sample is drawn with this probability; 1 = all iterations",
                     [](Config& c) -> double& { return c.verification.ransac_confidence; }));
  f.push_back(choice<ScoreFormula>("verification.score_formula",
                                   "score_t: n_in/|LA|, (n_in - 1)/|LA| or n_in/max(M, N)",
                                   [](Config& c) -> ScoreFormula& { return c.verification.score_formula; },
                                   {{"paper", ScoreFormula::kPaper},
                                    {"legacy", ScoreFormula::kLegacy},
                                    {"overlap", ScoreFormula::kOverlap}}));
  f.push_back(number("verification.sigma_4", "σ_4: loop iff best score_t > σ_4 (0.1 for MulRan/MCD)",
                     [](Config& c) -> double& { return c.verification.sigma_4; }));
  f.push_back(integer<uint32_t>("verification.seed", "RANSAC seed (std::mt19937)",
                                [](Config& c) -> uint32_t& { return c.verification.seed; }));
  f.push_back(integer<int>("threads", "worker threads for candidate verification; results do not depend on it",
                      [](Config& c) -> int& { return c.threads; }));
  return f;
}

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
      throw Error(where(source, kv.first) + ": key '" + key + "' appears twice, at lines " +
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
        throw Error(where(source, kv.second) + ": " + key + ": " + err + ", got '" + YAML::Dump(kv.second) + "'");
      }
    } else if (isSection(fields, key)) {
      if (!kv.second.IsMap()) throw Error(where(source, kv.second) + ": " + key + ": expected a map of keys");
      apply(config, fields, kv.second, key, source, lines);
    } else {
      const char* hint = prefix == "cluster" ? "; a new class is declared in labels.extra_classes" : "";
      throw Error(where(source, kv.first) + ": unknown key '" + key + "' (run `sgtllc config` for the valid keys" +
                  hint + ")");
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
         "# the defaults printed by `sgtllc config`. Symbols follow the SGT-LLC paper and the spec sections.\n";
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

Config parseConfig(const std::string& yaml, const std::string& source) {
  YAML::Node root;
  try {
    root = YAML::Load(yaml);
  } catch (const YAML::Exception& e) {
    throw Error(source + ":" + std::to_string(e.mark.line + 1) + ": malformed YAML: " + e.msg);
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
