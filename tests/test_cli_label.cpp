// The labeller on the command line: `--labeller geometric` on pair, run and eval (scans only), `sgtllc label`, and
// `--labels-dir`; bad input gives a message naming the file and a non-zero exit.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "sgtllc/io/kitti.h"
#include "test_cli_support.h"
#include "test_support.h"

namespace sgtllc::test {
namespace {

const std::string kData = SGTLLC_DATA_DIR;
const std::string k00 = kData + "/kitti/00/velodyne/";
const std::string k07 = kData + "/kitti/07/velodyne/";

class CliLabel : public CliTempDirTest {
 protected:
  CliLabel() : CliTempDirTest("label") {}
  /// A sequence folder with the four bundled KITTI 00 scans as frames 0..3 and no labels/.
  std::string scanOnlySequence() {
    namespace fs = std::filesystem;
    const fs::path seq = dir_ / "seq";
    fs::create_directories(seq / "velodyne");
    const char* frames[] = {"000052", "000088", "000850", "004501"};
    for (int i = 0; i < 4; ++i) {
      fs::copy_file(k00 + frames[i] + ".bin", seq / "velodyne" / ("00000" + std::to_string(i) + ".bin"));
    }
    return seq.string();
  }
};

TEST_F(CliLabel, KittiSevenFrameThreeRevisitsFrameZeroFromScansAlone) {
  // data/kitti/07 has no labels/: a label file would be an error, so none is read.
  const CliRun r = run("pair " + k07 + "000003.bin " + k07 + "000000.bin --labeller geometric");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("loop: YES"), std::string::npos) << r.out;
}

TEST_F(CliLabel, KittiZeroRevisitFromScansAloneWithinTheAcceptedPoseError) {
  // The label-free target (BENCHMARKS.md "Geometric labeller"): 4501 → 52 from the scans alone (the label files
  // beside them unread) is a loop within 0.15 m and 1° of the ICP-refined reference. Guided matching makes it one (BENCHMARKS.md "Guided matching").
  const CliRun r = run("pair " + k00 + "004501.bin " + k00 + "000052.bin --labeller geometric --json");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["loop"].get<bool>()) << r.out;
  EXPECT_GT(j["guided_pairs"].get<int>(), 0) << r.out;
  Eigen::Matrix4d T;
  for (int row = 0; row < 4; ++row) {
    for (int col = 0; col < 4; ++col) T(row, col) = j["T_match_query"][row][col].get<double>();
  }
  const PoseError err = poseError(T, referencePose4501To52());
  EXPECT_LT(err.translation_m, 0.15);
  EXPECT_LT(err.rotation_deg, 1.0);
}

TEST_F(CliLabel, AnUnlabelledPcdGivesTheResultOfItsBinScan) {
  // A KITTI .bin holds float32 x y z intensity records, which is a binary PCD's data section for fields
  // x y z intensity: the same scans as PCD files without a label field must give the same pair output.
  auto asPcd = [&](const std::string& bin, const std::string& name) {
    std::ifstream in(bin, std::ios::binary);
    const std::string records((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string n = std::to_string(records.size() / 16);
    std::ofstream out(path(name), std::ios::binary);
    out << "VERSION 0.7\nFIELDS x y z intensity\nSIZE 4 4 4 4\nTYPE F F F F\nCOUNT 1 1 1 1\nWIDTH " << n
        << "\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " << n << "\nDATA binary\n"
        << records;
    return path(name);
  };
  // The output without the two lines naming the inputs and the timing line.
  auto decision = [](const std::string& out) {
    std::istringstream lines(out);
    std::string line, kept;
    while (std::getline(lines, line)) {
      if (line.rfind("query ", 0) == 0 || line.rfind("match ", 0) == 0 || line.rfind("time ", 0) == 0) continue;
      kept += line + "\n";
    }
    return kept;
  };
  const CliRun bin = run("pair " + k07 + "000003.bin " + k07 + "000000.bin --labeller geometric");
  const CliRun pcd = run("pair " + asPcd(k07 + "000003.bin", "q.pcd") + " " + asPcd(k07 + "000000.bin", "m.pcd") +
                         " --labeller geometric");
  ASSERT_EQ(bin.status, 0) << bin.out;
  ASSERT_EQ(pcd.status, 0) << pcd.out;
  EXPECT_NE(pcd.out.find("loop: YES"), std::string::npos) << pcd.out;
  EXPECT_EQ(decision(pcd.out), decision(bin.out));
  // Without the geometric labeller such a PCD lacks the label field, and the message says so.
  const CliRun labelled = run("pair " + path("q.pcd") + " " + path("m.pcd"));
  EXPECT_EQ(labelled.status, 1);
  EXPECT_NE(labelled.out.find("no field 'label'"), std::string::npos) << labelled.out;
  // `sgtllc label` reads it too.
  const CliRun label = run("label " + path("q.pcd") + " --out " + path("q.label"));
  EXPECT_EQ(label.status, 0) << label.out;
  EXPECT_EQ(io::readLabelFile(path("q.label")).size(), io::readKittiBin(k07 + "000003.bin").size());
}

TEST_F(CliLabel, DistantScansAreNoLoop) {
  const CliRun r = run("pair " + k00 + "000850.bin " + k00 + "000088.bin --labeller geometric");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("loop: no"), std::string::npos) << r.out;
}

TEST_F(CliLabel, GeometricRefusesLabelOptionsAndOtherFormats) {
  CliRun r = run("pair " + k00 + "004501.bin " + k00 + "000052.bin --labeller geometric --labels-query " + kData +
                 "/kitti/00/labels/004501.label");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.out.find("reads no label file"), std::string::npos) << r.out;
  r = run("pair " + k00 + "004501.bin " + k00 + "000052.bin --labeller nonsense");
  EXPECT_EQ(r.status, 2) << r.out;
}

TEST_F(CliLabel, LabelWritesSemanticKittiIdsAndNeverOverwrites) {
  const std::string out = path("g.label"), ply = path("g.ply");
  CliRun r = run("label " + k00 + "000052.bin --out " + out + " --export " + ply);
  ASSERT_EQ(r.status, 0) << r.out;
  const std::vector<uint32_t> ids = io::readLabelFile(out);
  EXPECT_EQ(ids.size(), io::readKittiBin(k00 + "000052.bin").size());
  size_t building = 0, ground = 0;
  for (uint32_t id : ids) {
    EXPECT_TRUE(id == 0 || id == 40 || id == 50 || id == 51 || id == 70 || id == 72 || id == 80 || id == 81) << id;
    building += id == 50;
    ground += id == 40;
  }
  EXPECT_GT(building, 20000u);
  EXPECT_GT(ground, 40000u);
  std::ifstream in(ply);
  std::string first;
  std::getline(in, first);
  EXPECT_EQ(first, "ply");
  // A second run refuses to overwrite, and says so; --force replaces.
  r = run("label " + k00 + "000052.bin --out " + out);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.out.find(out), std::string::npos) << r.out;
  EXPECT_EQ(run("label " + k00 + "000052.bin --out " + out + " --force").status, 0);
  EXPECT_EQ(io::readLabelFile(out), ids);  // deterministic
  r = run("label " + path("missing.bin") + " --out " + path("x.label"));
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.out.find("missing.bin"), std::string::npos) << r.out;
}

TEST_F(CliLabel, RunWithTheGeometricLabellerReadsScansOnly) {
  const std::string seq = scanOnlySequence();
  // Without labels/ the file labels are missing...
  CliRun r = run("run " + seq);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.out.find("missing label file"), std::string::npos) << r.out;
  // ... and the geometric labeller does not need them.
  r = run("run " + seq + " --labeller geometric --json");
  EXPECT_EQ(r.status, 0) << r.out;
}

TEST_F(CliLabel, TheGeometricLabellerLabelsAccumulatedScans) {
  // Raw Mid-70 scans without labels/: each frame merges 5 scans, then the merged cloud is labelled.
  const std::string seq = path("mid70");
  CliRun r = run("simulate --out " + seq + " --frames 12 --seed 3 --sensor mid70 --accumulate 1 --no-preview");
  ASSERT_EQ(r.status, 0) << r.out;
  std::filesystem::remove_all(seq + "/labels");
  r = run("run " + seq + " --accumulate 5 --labeller geometric");
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("accumulated 5 scans per frame"), std::string::npos) << r.out;
}

TEST_F(CliLabel, LabelsDirNamesTheMissingFrameAndRejectsWrongLengths) {
  namespace fs = std::filesystem;
  const std::string seq = scanOnlySequence();
  const fs::path preds = dir_ / "predictions";
  fs::create_directories(preds);
  const char* frames[] = {"000052", "000088", "000850", "004501"};
  for (int i = 0; i < 3; ++i) {
    fs::copy_file(kData + "/kitti/00/labels/" + frames[i] + ".label", preds / ("00000" + std::to_string(i) + ".label"));
  }
  CliRun r = run("run " + seq + " --labels-dir " + preds.string());
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.out.find((preds / "000003.label").string()), std::string::npos) << r.out;
  // The labels of another scan: a wrong length, named with both counts.
  fs::copy_file(kData + "/kitti/00/labels/000052.label", preds / "000003.label");
  r = run("run " + seq + " --labels-dir " + preds.string());
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.out.find("000003"), std::string::npos) << r.out;
  // The right files: it runs.
  fs::copy_file(kData + "/kitti/00/labels/004501.label", preds / "000003.label", fs::copy_options::overwrite_existing);
  r = run("run " + seq + " --labels-dir " + preds.string());
  EXPECT_EQ(r.status, 0) << r.out;
  // A missing folder, and the geometric labeller with it, are errors.
  r = run("run " + seq + " --labels-dir " + path("nope"));
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.out.find("nope"), std::string::npos) << r.out;
  r = run("run " + seq + " --labels-dir " + preds.string() + " --labeller geometric");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.out.find("exclude each other"), std::string::npos) << r.out;
}

TEST_F(CliLabel, UnknownLabelIdsGiveOneWarningPerRun) {
  namespace fs = std::filesystem;
  const std::string seq = scanOnlySequence();
  const fs::path preds = dir_ / "predictions";
  fs::create_directories(preds);
  const char* frames[] = {"000052", "000088", "000850", "004501"};
  size_t unknown = 0;
  for (int i = 0; i < 4; ++i) {
    std::vector<uint32_t> ids = io::readLabelFile(kData + "/kitti/00/labels/" + frames[i] + ".label");
    for (size_t k = 0; k < ids.size(); k += 100) {
      ids[k] = 12345;  // not a SemanticKITTI id
      ++unknown;
    }
    std::ofstream(preds / ("00000" + std::to_string(i) + ".label"), std::ios::binary)
        .write(reinterpret_cast<const char*>(ids.data()), static_cast<std::streamsize>(ids.size() * 4));
  }
  const CliRun r = run("run " + seq + " --labels-dir " + preds.string());
  ASSERT_EQ(r.status, 0) << r.out;
  size_t count = 0;
  for (size_t at = r.out.find("whose label id"); at != std::string::npos; at = r.out.find("whose label id", at + 1)) {
    ++count;
  }
  EXPECT_EQ(count, 1u) << r.out;
  EXPECT_NE(r.out.find("ignored " + std::to_string(unknown) + " points in 4 of 4 frames"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace sgtllc::test
