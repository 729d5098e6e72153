// The YAML configuration: printed defaults read back to the same Config, every enum name, and clear errors
// that name the source, the line and the key.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <map>

#include "retrieval/ivf_index.h"
#include "sgtllc/io/config_yaml.h"
#include "test_config_support.h"
#include "test_io_support.h"

namespace sgtllc {
namespace {

using ::testing::HasSubstr;

std::string errorOf(const std::string& yaml) { return test::configErrorOf(yaml); }

TEST(ConfigYaml, DefaultsRoundTrip) {
  const std::string text = io::configToYaml(Config{});
  EXPECT_EQ(io::configToYaml(io::parseConfig(text)), text);
  EXPECT_THAT(text, HasSubstr("sigma_d: 30.0"));
  EXPECT_THAT(text, HasSubstr("  building:\n    voxel: 0.4"));
  EXPECT_THAT(text, HasSubstr("global_mode: G2"));
  EXPECT_THAT(text, HasSubstr("score_formula: overlap"));
}

TEST(ConfigYaml, EveryChangedFieldRoundTrips) {
  Config c;
  c.labels.preset = LabelPreset::kCustom;
  c.labels.custom_map = {{10, -1}, {50, 0}, {81, 6}};
  c.cluster.classes[kPole].min_size = 7;
  c.cluster.classes[kTerrain].voxel = 0.25;
  c.cluster.centre = CentreSource::kVoxels;
  c.graph.sigma_d = 42.5;
  c.graph.allow_k_equals_i = true;
  c.graph.max_nodes = 77;
  c.descriptor.order = SubVectorOrder::kCode;
  c.descriptor.global_mode = GlobalMode::kG1;
  c.retrieval.method = RetrievalMethod::kKdTree;
  c.retrieval.key = RetrievalKey::kGlobalDescriptor;
  c.retrieval.histogram_bins = 12;
  c.retrieval.histogram_range = 25.5;
  c.retrieval.warmup_frames = 150;
  c.association.score = NodeScore::kCount;
  c.association.sigma_2 = 3.0;
  c.association.entries = 0b101;
  c.descriptor.kind = SubVectorKind::kAngles;
  c.verification.use_ransac = false;
  c.verification.score_formula = ScoreFormula::kLegacy;
  c.verification.sample_with_replacement = false;
  c.verification.seed = 4000000000u;
  c.verification.sigma_4 = 0.1;
  c.threads = 2;
  const Config back = io::parseConfig(io::configToYaml(c));
  EXPECT_EQ(back.labels.preset, LabelPreset::kCustom);
  EXPECT_EQ(back.labels.custom_map, c.labels.custom_map);
  EXPECT_EQ(back.cluster.classes[kPole].min_size, 7);
  EXPECT_EQ(back.cluster.classes[kTerrain].voxel, 0.25);
  EXPECT_EQ(back.cluster.centre, CentreSource::kVoxels);
  EXPECT_EQ(back.graph.sigma_d, 42.5);
  EXPECT_TRUE(back.graph.allow_k_equals_i);
  EXPECT_EQ(back.graph.max_nodes, 77);
  EXPECT_EQ(back.descriptor.order, SubVectorOrder::kCode);
  EXPECT_EQ(back.descriptor.global_mode, GlobalMode::kG1);
  EXPECT_EQ(back.retrieval.method, RetrievalMethod::kKdTree);
  EXPECT_EQ(back.retrieval.key, RetrievalKey::kGlobalDescriptor);
  EXPECT_EQ(back.retrieval.histogram_bins, 12);
  EXPECT_EQ(back.retrieval.histogram_range, 25.5);
  EXPECT_EQ(back.retrieval.warmup_frames, 150);
  EXPECT_EQ(back.association.score, NodeScore::kCount);
  EXPECT_EQ(back.association.sigma_2, 3.0);
  EXPECT_EQ(back.association.entries, 0b101u);
  EXPECT_EQ(back.descriptor.kind, SubVectorKind::kAngles);
  EXPECT_FALSE(back.verification.use_ransac);
  EXPECT_EQ(back.verification.score_formula, ScoreFormula::kLegacy);
  EXPECT_FALSE(back.verification.sample_with_replacement);
  EXPECT_EQ(back.verification.seed, 4000000000u);
  EXPECT_EQ(back.verification.sigma_4, 0.1);
  EXPECT_EQ(back.threads, 2);
  EXPECT_EQ(io::configToYaml(back), io::configToYaml(c));
}

TEST(ConfigYaml, PartialDocumentKeepsOtherDefaults) {
  const Config c = io::parseConfig("verification:\n  sigma_4: 0.1\nlabels:\n  preset: mulran\n");
  EXPECT_EQ(c.verification.sigma_4, 0.1);
  EXPECT_EQ(c.labels.preset, LabelPreset::kMulRan);
  EXPECT_EQ(c.graph.sigma_d, 30.0);
  EXPECT_EQ(io::parseConfig("").graph.sigma_d, 30.0);
}

TEST(ConfigYaml, UnknownKeyIsNamedWithItsLine) {
  const std::string e = errorOf("graph:\n  sigma_d: 20\ncluster:\n  bulding:\n    voxel: 0.3\n");
  EXPECT_THAT(e, HasSubstr("my.yaml:4"));
  EXPECT_THAT(e, HasSubstr("unknown key 'cluster.bulding'"));
  EXPECT_THAT(errorOf("sigma_4: 0.2\n"), HasSubstr("unknown key 'sigma_4'"));
}

TEST(ConfigYaml, WrongTypesAreNamed) {
  EXPECT_THAT(errorOf("graph:\n  sigma_d: far\n"), HasSubstr("my.yaml:2: graph.sigma_d: expected a finite number"));
  EXPECT_THAT(errorOf("retrieval:\n  num_candidates: 2.5\n"), HasSubstr("retrieval.num_candidates: expected an integer"));
  EXPECT_THAT(errorOf("graph:\n  allow_k_equals_i: maybe\n"), HasSubstr("expected true or false"));
  EXPECT_THAT(errorOf("descriptor:\n  global_mode: G4\n"), HasSubstr("expected one of G1 | G2 | G3"));
  EXPECT_THAT(errorOf("graph: 3\n"), HasSubstr("graph: expected a map"));
  EXPECT_THAT(errorOf("verification:\n  seed: -1\n"), HasSubstr("verification.seed"));
  EXPECT_THAT(errorOf("labels:\n  custom_map: {50: 9}\n"), HasSubstr("classes must be integers -1..6"));
  for (const char* bad : {"ii", "iq", "\"\""}) {
    EXPECT_THAT(errorOf(std::string("association:\n  entries: ") + bad + "\n"),
                HasSubstr("association.entries: expected distinct letters from i, j, k"))
        << bad;
  }
}

// Every key's range is tested in test_config_ranges.cpp; this checks that a file's name and line reach the message.
using ConfigFile = test::TempDirTest;

TEST_F(ConfigFile, OutOfRangeValueNamesTheFileLineKeyAndRange) {
  const std::string file = write("my.yaml", "# thresholds\nverification:\n  sigma_3: 0.3\n  sigma_4: 5\n");
  try {
    io::loadConfig(file);
    FAIL() << "no error";
  } catch (const ConfigError& e) {
    EXPECT_EQ(std::string(e.what()), file + ":4: verification.sigma_4 = 5 is out of range [0, 1]");
    EXPECT_EQ(e.key(), "verification.sigma_4");
  }
}

TEST(ConfigYaml, MalformedYamlAndMissingFile) {
  EXPECT_THAT(errorOf("graph:\n  sigma_d: [1, 2\n"), HasSubstr("malformed YAML"));
  EXPECT_THAT(errorOf("- 1\n- 2\n"), HasSubstr("expected a map of configuration keys"));
  try {
    io::loadConfig("/nonexistent/dir/cfg.yaml");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("/nonexistent/dir/cfg.yaml"));
  }
}

}  // namespace
}  // namespace sgtllc

namespace sgtllc {
namespace {

TEST(ConfigYaml, BundledConfigsLoad) {
  const std::string dir = std::string(SGTLLC_DATA_DIR) + "/../configs/";
  EXPECT_EQ(io::loadConfig(dir + "mulran.yaml").labels.preset, LabelPreset::kMulRan);
  EXPECT_EQ(io::loadConfig(dir + "mulran.yaml").verification.sigma_4, 0.1);
  EXPECT_EQ(io::loadConfig(dir + "mcd.yaml").labels.preset, LabelPreset::kMcd);
  const Config paper = io::loadConfig(dir + "paper.yaml");
  EXPECT_EQ(paper.descriptor.global_mode, GlobalMode::kG1);
  EXPECT_EQ(paper.retrieval.key, RetrievalKey::kGlobalDescriptor);  // the paper retrieves by Des^G
  EXPECT_EQ(paper.verification.score_formula, ScoreFormula::kPaper);
  EXPECT_EQ(paper.verification.sigma_3, 0.35);  // the paper's gates and top-1, not our defaults
  EXPECT_EQ(paper.verification.min_associations, 7);
  EXPECT_EQ(paper.verification.min_inliers, 5);
  EXPECT_EQ(paper.verification.select_margin, 0.0);
  EXPECT_EQ(paper.verification.neighbour_frames, 0);
  const Config code = io::loadConfig(dir + "authors-code.yaml");
  EXPECT_EQ(code.descriptor.global_mode, GlobalMode::kG2);
  EXPECT_EQ(code.retrieval.key, RetrievalKey::kGlobalDescriptor);
  EXPECT_EQ(code.verification.score_formula, ScoreFormula::kLegacy);
  EXPECT_EQ(code.verification.ransac_confidence, 1.0);
  EXPECT_EQ(code.verification.sigma_3, 0.35);
  EXPECT_EQ(code.verification.min_inliers, 5);
  const Config objects = io::loadConfig(dir + "kitti00-objects.yaml");
  EXPECT_EQ(objects.labels.preset, LabelPreset::kCustom);
  EXPECT_EQ(objects.labels.custom_map, (std::map<uint32_t, int>{{71, 3}, {80, 5}}));
  ASSERT_EQ(objects.labels.extra_classes.size(), 1u);  // vehicles: an eighth class (README "Extra classes")
  EXPECT_EQ(objects.labels.extra_classes[0].name, "vehicle");
  EXPECT_EQ(objects.labels.extra_classes[0].ids, (std::vector<uint32_t>{10}));
  EXPECT_EQ(objects.numClasses(), 8);
  // The million-frame settings need the inverted file, which a build without FAISS refuses by name.
  if (internal::ivfAvailable()) {
    const Config large = io::loadConfig(dir + "large-map.yaml");
    EXPECT_EQ(large.retrieval.method, RetrievalMethod::kIvf);
    EXPECT_EQ(large.retrieval.histogram_bins, 10);
    EXPECT_EQ(large.retrieval.histogram_range, 20.0);
  } else {
    EXPECT_THROW(io::loadConfig(dir + "large-map.yaml"), ConfigError);
  }
}

}  // namespace
}  // namespace sgtllc
