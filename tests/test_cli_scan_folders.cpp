// `sgtllc run|eval|localize SEQ` on folders of PCD and PLY scans (README "Your own data"): the planted-loop
// sequence of the real KITTI 00 scans, rewritten as ascii and binary PCD and PLY with a label field, gives the
// loops of its .bin files byte for byte; a bad scan in a folder is an error naming the file.
#include <filesystem>
#include <fstream>
#include <iterator>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "test_cli_support.h"
#include "test_scan_folder_support.h"
#include "test_kitti_support.h"

namespace sgtllc {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using test::CliRun;
using test::run;
using test::ScanFile;

std::string contents(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

class CliScanFolders : public test::CliTempDirTest {
 protected:
  CliScanFolders() : CliTempDirTest("scanfolders") {}
  void SetUp() override {
    CliTempDirTest::SetUp();
    test::makePlantedSequence(path("bin"));
  }
  /// The loops CSV of `run DIR ARGS`.
  std::string loops(const std::string& dir, const std::string& csv, const std::string& args = "") {
    const CliRun r = run("run " + path(dir) + " --quiet --out " + path(csv) + args);
    EXPECT_EQ(r.status, 0) << r.out;
    return contents(path(csv));
  }
};

TEST_F(CliScanFolders, PcdAndPlyFoldersGiveTheLoopsOfTheirBinFiles) {
  const std::string reference = loops("bin", "bin.csv");
  ASSERT_THAT(reference, HasSubstr("\n000053,000000,"));
  const struct {
    ScanFile kind;
    bool in_velodyne;
    const char* dir;
  } cases[] = {{ScanFile::kPcdAscii, false, "pcd_ascii"},
               {ScanFile::kPcdBinary, true, "pcd_binary"},
               {ScanFile::kPlyAscii, true, "ply_ascii"},
               {ScanFile::kPlyBinary, false, "ply_binary"}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.dir);
    test::convertSequence(path("bin"), path(c.dir), c.kind, c.in_velodyne);
    EXPECT_EQ(loops(c.dir, std::string(c.dir) + ".csv"), reference);
    EXPECT_EQ(loops(c.dir, std::string(c.dir) + "2.csv", " --threads 2"), reference);
  }
  // eval scores the PCD folder against its poses.txt exactly as the .bin folder.
  const CliRun a = run("eval " + path("bin") + " --threads 2");
  const CliRun b = run("eval " + path("pcd_binary") + " --threads 2");
  ASSERT_EQ(a.status, 0) << a.out;
  ASSERT_EQ(b.status, 0) << b.out;
  auto f1 = [](const std::string& out) { return out.substr(out.find("F1max"), 40); };
  EXPECT_EQ(f1(a.out), f1(b.out));
}

TEST_F(CliScanFolders, LocalizeReadsAPcdFolderAsItsBinFolder) {
  const CliRun saved = run("run " + path("bin") + " --quiet --save-map " + path("m.sgtmap"));
  ASSERT_EQ(saved.status, 0) << saved.out;
  // A second session of the same place: the same scans under other names (a map's own session is refused).
  for (const char* sub : {"velodyne", "labels"}) {
    fs::create_directories(path("q/") + sub);
    for (const auto& entry : fs::directory_iterator(path("bin/") + sub)) {
      fs::copy_file(entry.path(), path("q/") + sub + "/q" + entry.path().filename().string());
    }
  }
  test::convertSequence(path("q"), path("pcd"), ScanFile::kPcdBinary, false);
  const CliRun a = run("localize --map " + path("m.sgtmap") + " " + path("q") + " --quiet --out " + path("a.csv"));
  const CliRun b = run("localize --map " + path("m.sgtmap") + " " + path("pcd") + " --quiet --out " + path("b.csv"));
  ASSERT_EQ(a.status, 0) << a.out;
  ASSERT_EQ(b.status, 0) << b.out;
  EXPECT_EQ(contents(path("a.csv")), contents(path("b.csv")));
  EXPECT_GT(contents(path("a.csv")).size(), 100u);
}

TEST_F(CliScanFolders, TheGeometricLabellerReadsPcdScansWithoutLabels) {
  test::convertSequence(path("bin"), path("pcd"), ScanFile::kPcdBinary, false);
  EXPECT_EQ(loops("pcd", "pcd.csv", " --labeller geometric"), loops("bin", "bin.csv", " --labeller geometric"));
}

TEST_F(CliScanFolders, ABadOrMissingScanIsAnErrorNamingIt) {
  test::convertSequence(path("bin"), path("pcd"), ScanFile::kPcdBinary, false);
  const std::string bad = path("pcd/000020.pcd");
  std::ofstream(bad, std::ios::trunc) << "VERSION 0.7\nFIELDS x y z label\nSIZE 4 4 4\n";
  CliRun r = run("run " + path("pcd") + " --quiet");
  EXPECT_EQ(r.status, 1);
  EXPECT_THAT(r.out, HasSubstr(bad + ":"));
  // A folder mixing formats, named.
  fs::remove(bad);
  fs::copy_file(path("bin/velodyne/000020.bin"), path("pcd/000020.bin"));
  r = run("run " + path("pcd") + " --quiet");
  EXPECT_EQ(r.status, 1);
  EXPECT_THAT(r.out, HasSubstr(path("pcd") + ": mixes scan formats (1 .bin, 53 .pcd files)"));
  // No label field and no labels/: the usual hint.
  fs::remove(path("pcd/000020.bin"));
  for (const auto& entry : fs::directory_iterator(path("pcd"))) {
    if (entry.path().extension() == ".pcd") {
      test::writeScanFile(entry.path().string(), LabeledCloud{{{1, 2, 3}}, {}}, ScanFile::kPcdBinary, false);
    }
  }
  r = run("run " + path("pcd") + " --quiet");
  EXPECT_EQ(r.status, 1);
  EXPECT_THAT(r.out, HasSubstr("missing label file"));
  EXPECT_THAT(r.out, HasSubstr("no 'label' field"));
  EXPECT_THAT(r.out, HasSubstr("--labeller geometric"));
}

}  // namespace
}  // namespace sgtllc
