// Label presets (algorithm §1, §8): every preset is checked exhaustively over all 2^16 ids against a table written out
// here from docs/algorithm.md §1, plus the SemanticKITTI instance bits in the high half of the word.
#include <cstdint>
#include <map>
#include <set>

#include <gtest/gtest.h>

#include "sgtllc/labels.h"

namespace {

using sgtllc::kDropped;
using sgtllc::LabelConfig;
using sgtllc::LabelMap;
using sgtllc::LabelPreset;

LabelMap mapFor(LabelPreset preset) {
  LabelConfig config;
  config.preset = preset;
  return LabelMap(config);
}

/// Checks classOf / isKnown for every 16-bit id, and again with instance bits set in the high half.
void expectTable(const LabelMap& map, const std::map<uint32_t, int>& classes, const std::set<uint32_t>& known) {
  for (uint32_t id = 0; id < (1u << 16); ++id) {
    const auto it = classes.find(id);
    const int want = it == classes.end() ? kDropped : it->second;
    const bool want_known = known.count(id) != 0;
    ASSERT_EQ(map.classOf(id), want) << "id " << id;
    ASSERT_EQ(map.isKnown(id), want_known) << "id " << id;
    for (uint32_t instance : {1u, 0x1234u, 0xFFFFu}) {
      const uint32_t word = (instance << 16) | id;
      ASSERT_EQ(map.classOf(word), want) << "id " << id << " instance " << instance;
      ASSERT_EQ(map.isKnown(word), want_known) << "id " << id << " instance " << instance;
    }
  }
}

std::set<uint32_t> range(uint32_t first, uint32_t last) {
  std::set<uint32_t> s;
  for (uint32_t id = first; id <= last; ++id) s.insert(id);
  return s;
}

// SemanticKITTI raw label space (semantic-kitti.yaml `labels`), algorithm §1 "Dropped labels".
const std::set<uint32_t> kKittiRawIds = {0,  1,  10, 11, 13, 15, 16, 18, 20,  30,  31,  32,  40,  44,  48,  49, 50,
                                         51, 52, 60, 70, 71, 72, 80, 81, 99, 252, 253, 254, 255, 256, 257, 258, 259};

TEST(Labels, DefaultPresetIsSemanticKittiRaw) {
  const LabelMap map;
  EXPECT_EQ(map.classOf(50), sgtllc::kBuilding);
  EXPECT_EQ(map.classOf(81), sgtllc::kTrafficSign);
  EXPECT_EQ(map.classOf(13), kDropped);  // bus in the raw space, not the train id of building
}

TEST(Labels, SemanticKittiRawEveryId) {
  const std::map<uint32_t, int> classes = {{50, sgtllc::kBuilding}, {51, sgtllc::kFence}, {70, sgtllc::kVegetation},
                                           {71, sgtllc::kTrunk},    {72, sgtllc::kTerrain}, {80, sgtllc::kPole},
                                           {81, sgtllc::kTrafficSign}};
  expectTable(mapFor(LabelPreset::kSemanticKittiRaw), classes, kKittiRawIds);
}

TEST(Labels, SemanticKittiRawSpotChecks) {
  const LabelMap map = mapFor(LabelPreset::kSemanticKittiRaw);
  // A real .label word: instance 37 of class building.
  EXPECT_EQ(map.classOf((37u << 16) | 50u), sgtllc::kBuilding);
  EXPECT_EQ(map.classOf((37u << 16) | 10u), kDropped);  // car instance
  // Dropped but known: road, parking, sidewalk, other-structure, moving car.
  for (uint32_t id : {40u, 44u, 48u, 52u, 252u}) {
    EXPECT_EQ(map.classOf(id), kDropped) << id;
    EXPECT_TRUE(map.isKnown(id)) << id;
  }
  // Unknown ids.
  for (uint32_t id : {2u, 12345u, 260u, 65535u}) {
    EXPECT_EQ(map.classOf(id), kDropped) << id;
    EXPECT_FALSE(map.isKnown(id)) << id;
  }
}

TEST(Labels, SemanticKittiLearningEveryId) {
  std::map<uint32_t, int> classes;
  for (int c = 0; c < sgtllc::kNumPaperClasses; ++c) classes[13 + c] = c;  // c = train id − 13
  expectTable(mapFor(LabelPreset::kSemanticKittiLearning), classes, range(0, 19));
}

TEST(Labels, SemanticKittiLearningSpotChecks) {
  const LabelMap map = mapFor(LabelPreset::kSemanticKittiLearning);
  EXPECT_EQ(map.classOf(13), sgtllc::kBuilding);
  EXPECT_EQ(map.classOf(19), sgtllc::kTrafficSign);
  EXPECT_EQ(map.classOf(9), kDropped);  // road
  EXPECT_TRUE(map.isKnown(2));          // bicycle is a learning id
  EXPECT_FALSE(map.isKnown(20));
  EXPECT_FALSE(map.isKnown(12345));
}

TEST(Labels, MulRanEveryId) {
  // Train id = label + 1, so labels 12..18 are the classes; a uint8 label space, 255 (train id 256 > 19) dropped.
  std::map<uint32_t, int> classes;
  for (int c = 0; c < sgtllc::kNumPaperClasses; ++c) classes[12 + c] = c;
  expectTable(mapFor(LabelPreset::kMulRan), classes, range(0, 255));
}

TEST(Labels, MulRanSpotChecks) {
  const LabelMap map = mapFor(LabelPreset::kMulRan);
  EXPECT_EQ(map.classOf(12), sgtllc::kBuilding);
  EXPECT_EQ(map.classOf(18), sgtllc::kTrafficSign);
  EXPECT_EQ(map.classOf(11), kDropped);
  EXPECT_EQ(map.classOf(19), kDropped);   // train id 20 > 19
  EXPECT_EQ(map.classOf(255), kDropped);  // algorithm §8: 255 is dropped
  EXPECT_FALSE(map.isKnown(12345));
}

TEST(Labels, McdEveryListedId) {
  // Spec §8, the authors' 29-entry map; ids 0..28 are the label space, the unlisted ones are dropped.
  const std::map<uint32_t, int> classes = {
      {2, sgtllc::kBuilding},     {17, sgtllc::kBuilding},    {5, sgtllc::kFence},        {7, sgtllc::kFence},
      {19, sgtllc::kFence},       {23, sgtllc::kFence},       {28, sgtllc::kFence},       {25, sgtllc::kVegetation},
      {24, sgtllc::kTrunk},       {4, sgtllc::kTerrain},      {6, sgtllc::kTerrain},      {13, sgtllc::kTerrain},
      {18, sgtllc::kTerrain},     {10, sgtllc::kPole},        {15, sgtllc::kPole},        {0, sgtllc::kTrafficSign},
      {3, sgtllc::kTrafficSign},  {8, sgtllc::kTrafficSign},  {9, sgtllc::kTrafficSign},  {21, sgtllc::kTrafficSign},
      {22, sgtllc::kTrafficSign}};
  ASSERT_EQ(classes.size(), 21u);
  expectTable(mapFor(LabelPreset::kMcd), classes, range(0, 28));
}

TEST(Labels, McdDroppedAndUnknown) {
  const LabelMap map = mapFor(LabelPreset::kMcd);
  for (uint32_t id : {1u, 11u, 12u, 14u, 16u, 20u, 26u, 27u}) {  // in the map, no stable class
    EXPECT_EQ(map.classOf(id), kDropped) << id;
    EXPECT_TRUE(map.isKnown(id)) << id;
  }
  for (uint32_t id : {29u, 50u, 12345u}) {
    EXPECT_EQ(map.classOf(id), kDropped) << id;
    EXPECT_FALSE(map.isKnown(id)) << id;
  }
}

TEST(Labels, NuScenesEveryId) {
  // docs/algorithm.md §1 "nuScenes": manmade, barrier, vegetation, terrain are kept; ids 0..39 are the label space
  // (32..39 the moving objects of the KITTI-layout conversions).
  const std::map<uint32_t, int> classes = {
      {28, sgtllc::kBuilding}, {9, sgtllc::kFence}, {30, sgtllc::kVegetation}, {27, sgtllc::kTerrain}};
  expectTable(mapFor(LabelPreset::kNuScenes), classes, range(0, 39));
}

TEST(Labels, NuScenesExtraClassClaimsDroppedCar) {
  LabelConfig config;
  config.preset = LabelPreset::kNuScenes;
  config.extra_classes = {{"vehicle", {17, 32}}};
  const LabelMap map(config);
  EXPECT_EQ(map.classOf(17), sgtllc::kNumPaperClasses);
  EXPECT_EQ(map.classOf(32), sgtllc::kNumPaperClasses);
  EXPECT_EQ(map.classOf(24), kDropped);  // driveable surface
  EXPECT_TRUE(map.isKnown(31));          // ego vehicle: known, dropped
  EXPECT_FALSE(map.isKnown(40));
}

TEST(Labels, CustomMap) {
  LabelConfig config;
  config.preset = LabelPreset::kCustom;
  config.custom_map = {{100, sgtllc::kBuilding}, {7, sgtllc::kPole}, {200, sgtllc::kTrafficSign}, {300, -1}};
  const LabelMap map(config);
  // 300 → -1: known but dropped; nothing of the KITTI preset leaks in (50 is unknown here).
  const std::map<uint32_t, int> classes = {{100, sgtllc::kBuilding}, {7, sgtllc::kPole}, {200, sgtllc::kTrafficSign}};
  expectTable(map, classes, {7, 100, 200, 300});
  EXPECT_EQ(map.classOf(300), kDropped);
  EXPECT_TRUE(map.isKnown(300));
  EXPECT_FALSE(map.isKnown(50));
  EXPECT_EQ(map.classOf((9u << 16) | 100u), sgtllc::kBuilding);
}

TEST(Labels, CustomMapIgnoredByOtherPresets) {
  LabelConfig config;  // kSemanticKittiRaw
  config.custom_map = {{100, sgtllc::kBuilding}, {40, sgtllc::kTerrain}};
  const LabelMap map(config);
  EXPECT_EQ(map.classOf(100), kDropped);
  EXPECT_FALSE(map.isKnown(100));
  EXPECT_EQ(map.classOf(40), kDropped);
}

}  // namespace
