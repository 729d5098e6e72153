// SemanticKITTI sequence directories: the real data/kitti/00 layout plus synthetic broken layouts.
#include <filesystem>
#include <fstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "sgtllc/io/sequence.h"
#include "test_io_support.h"

namespace {

namespace fs = std::filesystem;
using sgtllc::Error;
using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

const fs::path kSeq00 = fs::path(SGTLLC_DATA_DIR) / "kitti" / "00";

class SequenceIo : public sgtllc::test::TempDirTest {
 protected:
  /// Creates dir_/relative with @p bytes (parents included).
  void touch(const std::string& relative, const std::string& bytes = "") const { write(relative, bytes); }
};

TEST_F(SequenceIo, RealSequenceListsScansInNameOrderWithLabels) {
  const sgtllc::io::SequenceDir seq(kSeq00.string());
  ASSERT_EQ(seq.size(), 4u);
  EXPECT_EQ(seq.dir(), kSeq00.string());
  const char* names[] = {"000052", "000088", "000850", "004501"};
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(seq.frameName(i), names[i]);
    EXPECT_EQ(seq.binPath(i), (kSeq00 / "velodyne" / (std::string(names[i]) + ".bin")).string());
    EXPECT_EQ(seq.labelPath(i), (kSeq00 / "labels" / (std::string(names[i]) + ".label")).string());
  }
  const sgtllc::LabeledCloud scan = seq.load(0);
  EXPECT_EQ(scan.points.size(), 120796u);
  EXPECT_EQ(scan.labels.size(), 120796u);
  EXPECT_EQ(seq.load(3).points.size(), 123013u);
  EXPECT_THROW(seq.binPath(4), std::out_of_range);
}

TEST_F(SequenceIo, IgnoresOtherFilesAndSortsByName) {
  for (const char* name : {"000010", "000002", "000100"}) {
    touch(std::string("velodyne/") + name + ".bin");
    touch(std::string("labels/") + name + ".label");
  }
  touch("velodyne/readme.txt");
  fs::create_directories(dir_ / "velodyne" / "sub.bin");  // a directory, not a scan
  const sgtllc::io::SequenceDir seq(dir_.string());
  ASSERT_EQ(seq.size(), 3u);
  EXPECT_EQ(seq.frameName(0), "000002");
  EXPECT_EQ(seq.frameName(1), "000010");
  EXPECT_EQ(seq.frameName(2), "000100");
  EXPECT_TRUE(seq.load(1).points.empty());  // empty scans are valid
}

TEST_F(SequenceIo, AFolderWithoutScansIsAnError) {
  // Without velodyne/ the folder itself is searched for scans (test_io_scan_folders.cpp reads them).
  EXPECT_THAT([&] { sgtllc::io::SequenceDir seq((dir_ / "none").string()); },
              ThrowsMessage<Error>(HasSubstr((dir_ / "none").string() + ": no such directory")));
  touch("notes.txt");
  EXPECT_THAT([&] { sgtllc::io::SequenceDir seq(dir_.string()); },
              ThrowsMessage<Error>(HasSubstr(dir_.string() + ": no scans (.bin, .pcd or .ply) and no velodyne/ folder")));
  fs::create_directories(dir_ / "velodyne");
  touch("velodyne/notes.txt");
  EXPECT_THAT([&] { sgtllc::io::SequenceDir seq(dir_.string()); },
              ThrowsMessage<Error>(HasSubstr((dir_ / "velodyne").string() + ": no scans (.bin, .pcd or .ply)")));
}

TEST_F(SequenceIo, MissingLabelsNameTheFirstAndCountThem) {
  for (const char* name : {"a", "b", "c"}) touch(std::string("velodyne/") + name + ".bin");
  touch("labels/b.label");
  EXPECT_THAT([&] { sgtllc::io::SequenceDir seq(dir_.string()); },
              ThrowsMessage<Error>(AllOf(HasSubstr((dir_ / "labels" / "a.label").string() + ": missing label file"),
                                         HasSubstr("2 of 3 scans"))));
}

TEST_F(SequenceIo, LoadChecksCounts) {
  touch("velodyne/x.bin", std::string(32, '\0'));   // 2 points
  touch("labels/x.label", std::string(4, '\0'));    // 1 label
  const sgtllc::io::SequenceDir seq(dir_.string());
  EXPECT_THAT([&] { seq.load(0); }, ThrowsMessage<Error>(HasSubstr("has 2 points but")));
}

}  // namespace
