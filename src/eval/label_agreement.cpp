#include "sgtllc/eval/label_agreement.h"

#include <string>

#include "sgtllc/types.h"

namespace sgtllc::eval {
namespace {

double ratio(uint64_t num, uint64_t den) { return den > 0 ? static_cast<double>(num) / static_cast<double>(den) : 0.0; }

int merged(int8_t c, const ClassMerge& merge) {
  if (c == kDropped) return kDropped;
  if (c < 0 || c >= kMaxClasses) throw Error("class " + std::to_string(c) + " is not a stable class index");
  return merge[static_cast<size_t>(c)];
}

}  // namespace

ClassMerge classMerge(const std::vector<std::pair<int, int>>& from_to) {
  ClassMerge merge{};
  for (int c = 0; c < kMaxClasses; ++c) merge[static_cast<size_t>(c)] = static_cast<int8_t>(c);
  for (const auto& [from, to] : from_to) merge.at(static_cast<size_t>(from)) = static_cast<int8_t>(to);
  return merge;
}

ClassMerge labellerMerge(const LabelConfig& reference) {
  // nuScenes folds poles and signs into static.manmade.
  const std::array<bool, kMaxClasses> present = presentClasses(reference);
  std::vector<std::pair<int, int>> from_to = {{kTrunk, kPole}};
  if (!present[kPole] && present[kBuilding]) {
    from_to = {{kTrunk, kBuilding}, {kPole, kBuilding}, {kTrafficSign, kBuilding}};
  } else if (!present[kTrafficSign]) {
    from_to.emplace_back(kTrafficSign, kPole);
  }
  return classMerge(from_to);
}

void ClassAgreement::add(const std::vector<int8_t>& predicted, const std::vector<int8_t>& reference,
                         const ClassMerge& merge) {
  if (predicted.size() != reference.size()) {
    throw Error("labellings differ in length: " + std::to_string(predicted.size()) + " predicted, " +
                std::to_string(reference.size()) + " reference points");
  }
  for (size_t i = 0; i < predicted.size(); ++i) {
    const int p = merged(predicted[i], merge), r = merged(reference[i], merge);
    if (p == r) {
      if (p >= 0) ++tp[static_cast<size_t>(p)];
      continue;
    }
    if (p >= 0) ++fp[static_cast<size_t>(p)];
    if (r >= 0) ++fn[static_cast<size_t>(r)];
  }
}

void ClassAgreement::add(const ClassAgreement& other) {
  for (size_t c = 0; c < tp.size(); ++c) {
    tp[c] += other.tp[c];
    fp[c] += other.fp[c];
    fn[c] += other.fn[c];
  }
}

double ClassAgreement::precision(int c) const { return ratio(tp.at(c), tp.at(c) + fp.at(c)); }
double ClassAgreement::recall(int c) const { return ratio(tp.at(c), tp.at(c) + fn.at(c)); }
double ClassAgreement::iou(int c) const { return ratio(tp.at(c), tp.at(c) + fp.at(c) + fn.at(c)); }

std::vector<int8_t> stableClasses(const std::vector<uint32_t>& ids, const LabelMap& map) {
  std::vector<int8_t> classes(ids.size());
  for (size_t i = 0; i < ids.size(); ++i) classes[i] = map.classOf(ids[i]);
  return classes;
}

}  // namespace sgtllc::eval
