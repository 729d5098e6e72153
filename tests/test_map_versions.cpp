// Map files across versions and sizes (docs/map-format.md, "Versions" and "Reading"): a map of an older format
// version is refused by name with what to do; the recorded configuration fields belong to the format version; a
// huge (sparse) file is refused before anything is allocated; a POSE section that is not rigid is refused; a file
// read section by section fails as the in-memory bytes do.
#include <gtest/gtest.h>

#include <zlib.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "sgtllc/io/kitti.h"
#include "sgtllc/map/map_file.h"
#include "test_cli_support.h"
#include "test_map_support.h"

namespace sgtllc {
namespace {

namespace fs = std::filesystem;
using map::MapError;
using map::MapProblem;

/// crc32 of the keys mapConfig() records in format version 5, one per line.
constexpr uint32_t kVersion5KeysCrc = 2721989332u;

const std::string kV1Map = std::string(SGTLLC_DATA_DIR) + "/../tests/fixtures/map_v1_three_frames.sgtmap";

uint32_t crcOf(std::string_view b) {
  return static_cast<uint32_t>(crc32_z(0, reinterpret_cast<const Bytef*>(b.data()), b.size()));
}

/// The MapError that @p f throws (a test failure if none).
template <typename F>
MapError mapErrorOf(F&& f) {
  try {
    f();
  } catch (const MapError& e) {
    return e;
  }
  ADD_FAILURE() << "no MapError";
  return MapError(MapProblem::kInvalid, "");
}

class MapVersions : public test::CliTempDirTest {
 protected:
  MapVersions() : CliTempDirTest("map_versions") {}
  std::string writeBytes(const std::string& name, const std::string& bytes) const {
    std::ofstream(path(name), std::ios::binary) << bytes;
    return path(name);
  }
  static map::Map threeFrames() {
    const test::NodeSequence s = test::circleSequence(3);
    return map::makeMap(test::runNodes(s, Config{}).database(), Config{}, s.names, s.poses);
  }
};

TEST_F(MapVersions, AMapOfAnOlderFormatVersionSaysSoAndHowToRebuildIt) {
  const std::string expected = kV1Map + ": written by an older version of the map format (1; this build reads " +
                               std::to_string(map::kFormatVersion) + "): rebuild it with `sgtllc run --save-map`";
  const MapError e = mapErrorOf([&] { map::readMapFile(kV1Map, Config{}); });
  EXPECT_EQ(e.problem(), MapProblem::kOlderVersion);
  EXPECT_EQ(std::string(e.what()), expected);
  EXPECT_EQ(mapErrorOf([&] { map::readMapFile(kV1Map); }).problem(), MapProblem::kOlderVersion);
  const test::CliRun info = test::run("map info " + kV1Map);
  EXPECT_NE(info.status, 0);
  EXPECT_NE(info.out.find(expected), std::string::npos) << info.out;
}

// What a map records is the format: a change of the stored configuration fields (a new labeller.source, a
// renamed key) must come with a new kFormatVersion, so an older map is refused as older rather than failing on
// the first field that differs.
TEST_F(MapVersions, TheRecordedFieldsAreThoseOfThisFormatVersion) {
  std::string keys;
  for (const auto& [key, value] : map::mapConfig(Config{})) keys += key + "\n";
  EXPECT_EQ(map::kFormatVersion, 5u);
  EXPECT_NE(keys.find("\nlabeller.source\n"), std::string::npos) << keys;  // what version 1 lacked
  EXPECT_EQ(crcOf(keys), kVersion5KeysCrc)
      << "the fields a map records changed: raise map::kFormatVersion (docs/map-format.md, \"Versions\"), then "
         "record the new list's crc here. The fields now:\n"
      << keys;
}

TEST_F(MapVersions, AHugeSparseFileIsRefusedByNameBeforeAnythingIsAllocated) {
  constexpr uint64_t kTiB = uint64_t{1} << 40;
  std::string head("SGTLLMAP", 8);
  const auto put = [&head](auto v) { head.append(reinterpret_cast<const char*>(&v), sizeof v); };
  put(uint32_t{map::kFormatVersion});
  put(uint32_t{4});
  put(kTiB);
  put(map::fingerprint(map::mapConfig(Config{})));
  put(uint32_t{0});
  put(crcOf(head));
  const std::string huge = writeBytes("huge.sgtmap", head);
  fs::resize_file(huge, kTiB);  // sparse: no disk is used
  for (const bool with_config : {false, true}) {
    const MapError e = mapErrorOf([&] {
      if (with_config) {
        map::readMapFile(huge, Config{});
      } else {
        map::readMapFile(huge);
      }
    });
    EXPECT_EQ(e.problem(), MapProblem::kTooLarge);
    EXPECT_EQ(std::string(e.what()).rfind(huge + ": a map of 1099511627776 bytes (1024.0 GiB) is more than this "
                                                 "machine can load (", 0),
              0u)
        << e.what();
  }
  const test::CliRun info = test::run("map info " + huge);
  EXPECT_EQ(info.status, 1);
  EXPECT_NE(info.out.find(huge + ": a map of 1099511627776 bytes"), std::string::npos) << info.out;
  // Within the machine's memory, the same header over zeros fails at its first section, read 16 bytes at a time.
  fs::resize_file(huge, 64u << 20);
  std::string small = head;
  const uint64_t size = 64u << 20;
  std::memcpy(&small[16], &size, 8);
  const uint32_t crc = crcOf(std::string_view(small).substr(0, 36));
  std::memcpy(&small[36], &crc, 4);
  std::fstream(huge, std::ios::in | std::ios::out | std::ios::binary).write(small.data(), 40);
  EXPECT_EQ(std::string(mapErrorOf([&] { map::readMapFile(huge); }).what()),
            huge + ": corrupted map: section 1 of 4: checksum mismatch");
}

// The text readers read their files whole (sgtllc/io/input_file.h): a file beyond this machine's memory is refused by name
// before any allocation, not with std::bad_alloc.
TEST_F(MapVersions, AHugeSparseTextFileIsRefusedByNameToo) {
  const std::string huge = writeBytes("poses.txt", "1 0 0 0 0 1 0 0 0 0 1 0\n");
  fs::resize_file(huge, uint64_t{1} << 40);
  try {
    io::readKittiPoses(huge);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("cannot read " + huge + ": 1099511627776 bytes, more than this machine can "
                                          "load (", 0),
              0u)
        << e.what();
  }
}

TEST_F(MapVersions, APoseSectionThatIsNotRigidIsRefusedNamingTheFile) {
  const map::Map m = threeFrames();
  std::string bytes = map::encodeMap(m);
  map::MapLayout layout;
  map::decodeMap(bytes, "m", RetrievalMethod::kBruteForce, &layout);
  ASSERT_EQ(layout.sections[2].tag, "POSE");
  const size_t pose = 40 + layout.sections[0].bytes + layout.sections[1].bytes;
  const size_t payload = layout.sections[2].bytes - 20;
  for (const double r00 : {1.01, -1.0}) {  // a scale; a reflection (orthonormal, det −1)
    std::string scaled = bytes;
    std::memcpy(&scaled[pose + 16 + 8 + 12 * 8], &r00, 8);  // frame 1's R(0,0)
    const uint32_t crc = crcOf(std::string_view(scaled).substr(pose, 16 + payload));
    std::memcpy(&scaled[pose + 16 + payload], &crc, 4);
    const std::string file = writeBytes("scaled.sgtmap", scaled);
    const MapError e = mapErrorOf([&] { map::readMapFile(file, Config{}); });
    EXPECT_EQ(e.problem(), MapProblem::kCorrupted);
    EXPECT_EQ(std::string(e.what()).rfind(file + ": corrupted map: the pose of frame '000001' is not a rigid motion", 0),
              0u)
        << e.what();
  }
  // Nor is such a map written.
  map::Map bad = threeFrames();
  bad.poses[0](0, 0) = 2.0;
  EXPECT_EQ(mapErrorOf([&] { map::encodeMap(bad, "out.sgtmap"); }).problem(), MapProblem::kInvalid);
}

TEST_F(MapVersions, AFileReadBySectionsFailsAsItsBytesDo) {
  const std::string bytes = map::encodeMap(threeFrames());
  const std::string whole = writeBytes("m.sgtmap", bytes);
  const map::Map loaded = map::readMapFile(whole, Config{});
  EXPECT_EQ(map::encodeMap(loaded), bytes);
  for (size_t n = 0; n < bytes.size(); n += 31) {
    const std::string cut = writeBytes("cut.sgtmap", bytes.substr(0, n));
    const MapError e = mapErrorOf([&] { map::readMapFile(cut); });
    EXPECT_EQ(e.problem(), MapProblem::kTruncated) << n << ": " << e.what();
  }
  for (size_t i = 8; i < bytes.size(); i += 23) {
    std::string damaged = bytes;
    damaged[i] = static_cast<char>(damaged[i] ^ 0x55);
    const std::string file = writeBytes("damaged.sgtmap", damaged);
    const MapError from_file = mapErrorOf([&] { map::readMapFile(file); });
    const MapError from_memory = mapErrorOf([&] { map::decodeMap(damaged, file); });
    EXPECT_EQ(from_file.problem(), MapProblem::kCorrupted) << i;
    EXPECT_EQ(std::string(from_file.what()), std::string(from_memory.what())) << i;
  }
}

}  // namespace
}  // namespace sgtllc
