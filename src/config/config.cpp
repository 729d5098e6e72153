#include "sgtllc/config.h"

#include <map>
#include <string>

#include "config_ranges.h"
#include "retrieval/ivf_index.h"
#include "sgtllc/config/settings.h"
#include "sgtllc/labels.h"

namespace sgtllc {

using namespace detail;

namespace {

bool validClassName(const std::string& name) {
  if (name.empty() || name[0] < 'a' || name[0] > 'z') return false;
  for (char ch : name) {
    if (!((ch >= 'a' && ch <= 'z') || (ch >= '0' && ch <= '9') || ch == '-' || ch == '_')) return false;
  }
  return true;
}

/// Names unique and new, ids claimed once, the count bounded (LabelConfig::extra_classes).
void validateExtraClasses(const LabelConfig& labels) {
  const std::vector<ExtraClass>& extras = labels.extra_classes;
  if (extras.empty()) return;
  if (labels.numClasses() > kMaxClasses) {
    throw ConfigError("labels.extra_classes",
                      "labels.extra_classes: " + std::to_string(extras.size()) + " extra classes make " +
                          std::to_string(labels.numClasses()) + " in all, more than " + std::to_string(kMaxClasses) +
                          " (the G2 global descriptor has C³ entries per frame)");
  }
  LabelConfig base = labels;  // the preset's own classes, to find ids an extra class would take from them
  base.extra_classes.clear();
  const LabelMap preset(base);
  std::map<uint32_t, int> owner;  // id → extra class that claimed it
  for (size_t k = 0; k < extras.size(); ++k) {
    const std::string key = "labels.extra_classes[" + std::to_string(k) + "]";
    const std::string& name = extras[k].name;
    if (!validClassName(name)) {
      throw ConfigError(key + ".name", key + ".name: '" + name + "' is not a class name (a lower-case letter, then " +
                                           "letters a-z, digits, '-' or '_')");
    }
    for (int c = 0; c < kNumPaperClasses + static_cast<int>(k); ++c) {
      if (labels.className(c) == name) {
        throw ConfigError(key + ".name", key + ".name: '" + name + "' is " +
                                             (c < kNumPaperClasses ? "one of the paper's classes"
                                                                   : "already the name of class " + std::to_string(c)));
      }
    }
    if (extras[k].ids.empty() && labels.preset != LabelPreset::kCustom) {
      throw ConfigError(key + ".ids", key + ".ids: class '" + name + "' lists no raw ids");
    }
    for (uint32_t id : extras[k].ids) {
      const std::string at = key + ".ids: id " + std::to_string(id);
      if (id > 0xFFFFu) throw ConfigError(key + ".ids", at + " is out of range [0, 65535]");
      const auto [it, fresh] = owner.emplace(id, static_cast<int>(k));
      if (!fresh) {
        throw ConfigError(key + ".ids", at + " is mapped twice: already to '" + extras[it->second].name + "'");
      }
      if (labels.preset == LabelPreset::kCustom && labels.custom_map.count(id)) {
        throw ConfigError(key + ".ids", at + " is mapped twice: labels.custom_map lists it");
      }
      if (preset.classOf(id) != kDropped) {
        throw ConfigError(key + ".ids", at + " is mapped twice: the preset maps it to '" +
                                            labels.className(preset.classOf(id)) + "'");
      }
    }
  }
}

}  // namespace

std::string LabelConfig::className(int c) const {
  if (c >= 0 && c < kNumPaperClasses) return kClassNames[c];
  if (c >= kNumPaperClasses && c < numClasses()) return extra_classes[c - kNumPaperClasses].name;
  return "class-" + std::to_string(c);
}

int Config::addClass(ExtraClass extra, const ClassClusterConfig& params) {
  labels.extra_classes.push_back(std::move(extra));
  cluster.classes.push_back(params);
  return numClasses() - 1;
}

void Config::validate() const {
  // Each setting's own range comes from the settings table (config/settings.h); here are the rules that tie
  // settings together.
  validateExtraClasses(labels);
  const int num_classes = numClasses();
  for (const auto& [id, cls] : labels.custom_map) {
    checkInt("labels.custom_map[" + std::to_string(id) + "]", cls, -1, num_classes - 1);
  }
  if (static_cast<int>(cluster.classes.size()) != num_classes) {
    throw ConfigError("cluster", "cluster.classes has " + std::to_string(cluster.classes.size()) +
                                     " entries for " + std::to_string(num_classes) +
                                     " classes (one per class; Config::addClass appends both)");
  }
  checkSettingRanges(*this);
  if (retrieval.method == RetrievalMethod::kIvf && !internal::ivfAvailable()) {
    throw ConfigError("retrieval.method",
                      "retrieval.method: ivf needs sgtllc built with FAISS (install libfaiss-dev and configure again)");
  }
  // S is a share of slots with score ratio and a count of them (at most C² = 49 for the seven classes) with
  // score count.
  const bool count = association.score == NodeScore::kCount;
  const std::string slots = text(static_cast<long long>(num_classes) * num_classes);
  if (!inside(association.sigma_2, {0.0}, {count ? num_classes * num_classes : 1.0})) {
    outOfRange("association.sigma_2", text(association.sigma_2),
               count ? "[0, " + slots + "] (association.score: count)"
                     : "[0, 1] (association.score: ratio; [0, " + slots + "] with count)");
  }
  if (association.entries < 1 || association.entries > 7) {
    throw ConfigError("association.entries", "association.entries must keep at least one of the v_i, v_j, v_k entries");
  }
  const VerificationConfig& v = verification;
  if (v.offset_decay_end > 0.0 && v.offset_decay_end <= v.offset_decay_start) {
    throw ConfigError("verification.offset_decay_end",
                      "verification.offset_decay_end = " + text(v.offset_decay_end) +
                          " must be 0 (no decay) or greater than verification.offset_decay_start = " +
                          text(v.offset_decay_start));
  }
  for (uint32_t id : registration.ground_ids) {
    if (id > 0xFFFFu) {
      throw ConfigError("registration.ground_ids",
                        "registration.ground_ids: " + std::to_string(id) + " is not a raw id 0..65535");
    }
  }
  validateLabellerRules(labeller, labels);
}

/// The back end's settings alone, by the same table and messages as Config::validate().
void backend::BackendConfig::validate() const {
  Config config;
  config.backend = *this;
  checkSettingRanges(config, "backend.");
}

}  // namespace sgtllc
