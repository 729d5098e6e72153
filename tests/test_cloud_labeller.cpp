// labeller.source (docs/labeller.md §6): the label file as it is, the geometric labeller alone, and hybrid, which
// splits off the poles and trunks a label set lacks. Checked on a real KITTI 00 scan whose SemanticKITTI ground truth
// is folded into a nuScenes-like label set (poles and signs into building, trunks into vegetation).
#include <gtest/gtest.h>

#include "sgtllc/config.h"
#include "sgtllc/io/kitti.h"
#include "sgtllc/label/cloud_labeller.h"
#include "test_support.h"

namespace sgtllc {
namespace {

/// SemanticKITTI ids folded as nuScenes-lidarseg folds its classes: building, pole and sign → building (50),
/// vegetation and trunk → vegetation (70), fence, terrain as they are, everything else dropped.
LabelConfig foldedLabels() {
  LabelConfig labels;
  labels.preset = LabelPreset::kCustom;
  for (uint32_t id : {0u, 1u, 10u, 11u, 13u, 15u, 16u, 18u, 20u, 30u, 31u, 32u, 40u, 44u, 48u, 49u, 52u, 60u, 99u,
                      252u, 253u, 254u, 255u, 256u, 257u, 258u, 259u}) {
    labels.custom_map[id] = -1;
  }
  for (uint32_t id : {50u, 80u, 81u}) labels.custom_map[id] = kBuilding;
  for (uint32_t id : {70u, 71u}) labels.custom_map[id] = kVegetation;
  labels.custom_map[51] = kFence;
  labels.custom_map[72] = kTerrain;
  return labels;
}

LabellerConfig source(LabelSource s) {
  LabellerConfig l;
  l.source = s;
  return l;
}

TEST(CloudLabeller, SplitsWhatTheLabelSetLacks) {
  EXPECT_FALSE(hybridSplits(LabelConfig{}).any());
  const HybridSplits folded = hybridSplits(foldedLabels());
  EXPECT_TRUE(folded.pole);
  EXPECT_TRUE(folded.trunk);
  const std::array<bool, kMaxClasses> present = presentClasses(foldedLabels());
  EXPECT_TRUE(present[kBuilding] && present[kVegetation] && present[kFence] && present[kTerrain]);
  EXPECT_FALSE(present[kPole] || present[kTrunk] || present[kTrafficSign]);
}

TEST(CloudLabeller, HybridOnSemanticKittiIsTheLabelFile) {
  const LabeledCloud scan = io::readLabeledScan(test::dataPath("kitti/00/velodyne/004501.bin"),
                                                test::dataPath("kitti/00/labels/004501.label"));
  const label::CloudLabeller hybrid(LabelConfig{}, source(LabelSource::kHybrid));
  EXPECT_FALSE(hybrid.changesLabels());
  EXPECT_EQ(hybrid.apply(scan).labels, scan.labels);
  LabelConfig with_extra;
  with_extra.extra_classes.push_back({"car", {10}});
  Config config;
  config.labels = with_extra;
  config.labeller.source = LabelSource::kHybrid;
  EXPECT_THROW(config.validate(), ConfigError);  // hybrid gives the paper's seven classes only
}

TEST(CloudLabeller, HybridRecoversPolesAndTrunksOfARealScan) {
  const LabeledCloud scan = io::readLabeledScan(test::dataPath("kitti/00/velodyne/004501.bin"),
                                                test::dataPath("kitti/00/labels/004501.label"));
  LabeledCloud folded = scan;
  folded.labels.back() = 12345;  // an id the label set does not know stays unknown
  const label::CloudLabeller hybrid(foldedLabels(), source(LabelSource::kHybrid));
  ASSERT_TRUE(hybrid.changesLabels());
  EXPECT_EQ(hybrid.nodeLabels().preset, LabelPreset::kSemanticKittiRaw);
  const LabeledCloud out = hybrid.apply(folded);
  ASSERT_EQ(out.labels.size(), scan.labels.size());
  EXPECT_FALSE(LabelMap().isKnown(out.labels.back()));
  const LabelMap truth;
  const LabelConfig folded_labels = foldedLabels();
  size_t split = 0, split_right = 0, truth_thin = 0;
  for (size_t i = 0; i + 1 < scan.labels.size(); ++i) {
    const int t = truth.classOf(scan.labels[i]), o = truth.classOf(out.labels[i]);
    const auto it = folded_labels.custom_map.find(scan.labels[i] & 0xFFFF);
    const int f = it != folded_labels.custom_map.end() ? it->second : -1;
    if (t == kTrunk || t == kPole) ++truth_thin;
    if (o == kPole || o == kTrunk) {
      // Only building points become pole and only vegetation points trunk.
      EXPECT_EQ(f, o == kPole ? kBuilding : kVegetation) << i;
      ++split;
      split_right += t == kTrunk || t == kPole;
    } else {
      EXPECT_EQ(o, f) << i;  // every other point keeps its file class
    }
  }
  // The labeller's pole+trunk precision on this scan is about 0.76 (BENCHMARKS.md, "Geometric labeller"); inside the
  // label set's own building and vegetation points it can only be as good or better.
  ASSERT_GT(split, 1000u);
  EXPECT_GT(static_cast<double>(split_right) / split, 0.76);
  EXPECT_GT(static_cast<double>(split_right) / truth_thin, 0.5);
}

TEST(CloudLabeller, GeometricIgnoresTheLabels) {
  const LabeledCloud scan = io::readLabeledScan(test::dataPath("kitti/00/velodyne/000052.bin"),
                                                test::dataPath("kitti/00/labels/000052.label"));
  const label::CloudLabeller geometric(LabelConfig{}, source(LabelSource::kGeometric));
  EXPECT_FALSE(geometric.readsLabelFiles());
  const label::GeometricLabeller labeller;
  EXPECT_EQ(geometric.apply(scan).labels, label::labelCloud(scan.points, labeller).labels);
}

}  // namespace
}  // namespace sgtllc
