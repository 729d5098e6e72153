#include "sgtllc/labels.h"

#include <initializer_list>
#include <utility>

namespace sgtllc {
namespace {

constexpr size_t kTableSize = 1u << 16;

// Every id of the SemanticKITTI raw label space (semantic-kitti.yaml `labels`).
constexpr uint16_t kSemanticKittiRawIds[] = {0,  1,  10, 11, 13, 15, 16, 18, 20,  30,  31,  32,  40,  44,  48,  49, 50,
                                             51, 52, 60, 70, 71, 72, 80, 81, 99, 252, 253, 254, 255, 256, 257, 258, 259};

// MCD (Livox Mid-70) id → class, from the authors' 29-entry map (algorithm §8). Ids 0..28 are the label space.
constexpr std::pair<uint16_t, int> kMcdMap[] = {
    {2, kBuilding}, {17, kBuilding},                                                           //
    {5, kFence},    {7, kFence},     {19, kFence}, {23, kFence}, {28, kFence},                 //
    {25, kVegetation},                                                                         //
    {24, kTrunk},                                                                              //
    {4, kTerrain},  {6, kTerrain},   {13, kTerrain}, {18, kTerrain},                           //
    {10, kPole},    {15, kPole},                                                               //
    {0, kTrafficSign}, {3, kTrafficSign}, {8, kTrafficSign}, {9, kTrafficSign}, {21, kTrafficSign},
    {22, kTrafficSign}};

// nuScenes-lidarseg index → class (algorithm §1 "nuScenes"): 28 static.manmade holds buildings, walls, poles and
// signs alike, so it is building; 9 movable_object.barrier is fence-like. Ids 0..31 are its classes, 32..39 the
// moving objects of the KITTI-layout conversions; all others are dropped (no trunk, pole or traffic-sign exists).
constexpr std::pair<uint16_t, int> kNuScenesMap[] = {
    {28, kBuilding}, {9, kFence}, {30, kVegetation}, {27, kTerrain}};
constexpr uint16_t kNuScenesLastId = 39;

}  // namespace

LabelMap::LabelMap(const LabelConfig& config) : table_(kTableSize, kDropped), known_(kTableSize, 0) {
  auto set = [this](uint32_t id, int cls) { table_[id & 0xFFFFu] = static_cast<int8_t>(cls); };
  auto know_range = [this](uint32_t first, uint32_t last) {
    for (uint32_t id = first; id <= last; ++id) known_[id] = 1;
  };
  switch (config.preset) {
    case LabelPreset::kSemanticKittiRaw: {
      for (uint16_t id : kSemanticKittiRawIds) known_[id] = 1;
      const uint16_t stable[kNumPaperClasses] = {50, 51, 70, 71, 72, 80, 81};
      for (int c = 0; c < kNumPaperClasses; ++c) set(stable[c], c);
      break;
    }
    case LabelPreset::kSemanticKittiLearning:
      // Train ids 0..19; classes are train ids 13..19 (algorithm §1).
      know_range(0, 19);
      for (int c = 0; c < kNumPaperClasses; ++c) set(13 + c, c);
      break;
    case LabelPreset::kMulRan:
      // Train id = label + 1, so classes are labels 12..18; train ids > 19 (e.g. label 255) are dropped (algorithm §8).
      know_range(0, 255);
      for (int c = 0; c < kNumPaperClasses; ++c) set(12 + c, c);
      break;
    case LabelPreset::kMcd:
      know_range(0, 28);
      for (const auto& [id, cls] : kMcdMap) set(id, cls);
      break;
    case LabelPreset::kNuScenes:
      know_range(0, kNuScenesLastId);
      for (const auto& [id, cls] : kNuScenesMap) set(id, cls);
      break;
    case LabelPreset::kCustom:
      for (const auto& [id, cls] : config.custom_map) {
        known_[id & 0xFFFFu] = 1;
        set(id, cls);
      }
      break;
  }
  // Extra classes claim ids the preset knows but drops (car = 10 in SemanticKITTI) or declare new ones
  // (Config::validate rejects an id that already has a class).
  for (size_t k = 0; k < config.extra_classes.size(); ++k) {
    for (uint32_t id : config.extra_classes[k].ids) {
      known_[id & 0xFFFFu] = 1;
      set(id, kNumPaperClasses + static_cast<int>(k));
    }
  }
}

std::array<bool, kMaxClasses> presentClasses(const LabelConfig& labels) {
  const LabelMap map(labels);
  std::array<bool, kMaxClasses> present{};
  for (uint32_t id = 0; id < 0x10000u; ++id) {
    const int8_t c = map.classOf(id);
    if (c >= 0) present[static_cast<size_t>(c)] = true;
  }
  return present;
}

HybridSplits hybridSplits(const LabelConfig& labels) {
  const std::array<bool, kMaxClasses> present = presentClasses(labels);
  return {!present[kPole] && present[kBuilding], !present[kTrunk] && present[kVegetation]};
}

}  // namespace sgtllc
