// PCD headers whose sizes the data cannot back (BENCHMARKS.md, "Reliability checks"): every declared size is
// checked against the file and against the others before anything is allocated, so a 172-byte file that claims
// 4 GiB fails at once.
#include <sys/resource.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "sgtllc/io/pcd.h"
#include "test_pcd_support.h"

namespace {

using namespace sgtllc::test;  // the test PCD writer
using sgtllc::Error;
using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

/// x y z label (F4 F4 F4 U4: 16 bytes a point), @p points declared, then DATA @p data.
std::string xyzlHeader(size_t points, const std::string& data) {
  const std::string n = std::to_string(points);
  return "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z label\nSIZE 4 4 4 4\nTYPE F F F U\nCOUNT 1 1 1 1\nWIDTH " + n +
         "\nHEIGHT 1\nPOINTS " + n + "\nDATA " + data + "\n";
}

void putU32(std::string& out, uint32_t v) { put<uint32_t>(out, static_cast<double>(v)); }

/// 268435455 points × 16 bytes = 4294967280 bytes (4 GiB) declared, 16 bytes of "compressed" data: 172 bytes.
std::string compressedBomb() {
  std::string out = xyzlHeader(268435455, "binary_compressed");
  putU32(out, 16);
  putU32(out, 268435455u * 16u);
  out += '\x0f';  // an LZF literal run of 16 bytes
  out += std::string(15, 'A');
  return out;
}

void expectError(const std::string& path, const std::string& text) {
  EXPECT_THAT([&] { sgtllc::io::readPcd(path); }, ThrowsMessage<Error>(AllOf(HasSubstr(path), HasSubstr(text))));
}

TEST_F(PcdIo, CompressedBlockClaimingGigabytesFailsBeforeAllocating) {
  const std::string bomb = compressedBomb();
  ASSERT_EQ(bomb.size(), 172u);
  expectError(write("bomb.pcd", bomb),
              "binary_compressed block claims 4294967280 bytes from 16 compressed bytes (LZF expands at most 88 "
              "times): POINTS 268435455 does not match the data");
}

#if defined(__SANITIZE_ADDRESS__)
#define SGTLLC_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SGTLLC_ASAN 1
#endif
#endif

TEST_F(PcdIo, CompressedBombNeedsNoMoreThanAFewMegabytes) {
#ifdef SGTLLC_ASAN
  GTEST_SKIP() << "AddressSanitizer reserves terabytes of address space; an address-space limit cannot apply";
#else
  // In a child process with 512 MiB of address space beyond what the test already maps, reading the 172-byte file
  // must end in sgtllc::Error, not std::bad_alloc (the 4 GiB the header claims was allocated before the fix).
  const std::string path = write("bomb.pcd", compressedBomb());
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  // The "threadsafe" child runs the test again from the start, SetUp and its own folder included, and exits without
  // TearDown: it removes that folder itself, or every run would leave one in the temporary directory.
  const auto leave = [this](int code) {
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
    std::exit(code);
  };
  EXPECT_EXIT(
      {
        rlimit limit{};
        getrlimit(RLIMIT_AS, &limit);
        limit.rlim_cur = size_t{1} << 30;
        setrlimit(RLIMIT_AS, &limit);
        int code = 1;
        try {
          sgtllc::io::readPcd(path);
        } catch (const Error&) {
          code = 0;
        } catch (...) {
          code = 2;
        }
        leave(code);
      },
      ::testing::ExitedWithCode(0), "");
#endif
}

TEST_F(PcdIo, CompressedSizesAreCheckedAgainstTheFileAndEachOther) {
  // Compressed size beyond the end of the file: truncated, before the uncompressed size is looked at.
  std::string beyond = xyzlHeader(1000, "binary_compressed");
  putU32(beyond, 1u << 30);
  putU32(beyond, 16000);
  expectError(write("beyond.pcd", beyond), "truncated binary_compressed data");
  // Uncompressed size that disagrees with POINTS × 16.
  std::string disagree = xyzlHeader(2, "binary_compressed");
  putU32(disagree, 4);
  putU32(disagree, 0xFFFFFFF0u);
  disagree += "abcd";
  expectError(write("disagree.pcd", disagree), "block unpacks to 4294967280 bytes but 2 points of 16 bytes need 32");
}

TEST_F(PcdIo, BinaryWithAbsurdPointsFailsNamingTheSizes) {
  std::string text = xyzlHeader(268435455, "binary") + std::string(16, '\0');
  expectError(write("binary.pcd", text), "truncated binary data: 268435455 points need 4294967280 bytes, found 16");
  // POINTS × point size past 2^64: an error, not a wrapped size.
  std::string huge = xyzlHeader(size_t{1} << 62, "binary") + std::string(16, '\0');
  expectError(write("huge.pcd", huge), "POINTS is too large");
}

TEST_F(PcdIo, AsciiWithAbsurdPointsFailsBeforeReadingTheData) {
  expectError(write("ascii.pcd", xyzlHeader(1000000000, "ascii") + "1 2 3 4\n"),
              ": POINTS 1000000000 cannot fit in the 8 bytes of ascii data (4 values per point)");
  // The smallest data that can hold the points is accepted: one digit per value, no final newline.
  const sgtllc::LabeledCloud c = sgtllc::io::readPcd(write("tight.pcd", xyzlHeader(2, "ascii") + "1 2 3 4\n5 6 7 8"));
  ASSERT_EQ(c.points.size(), 2u);
  EXPECT_EQ(c.points[1].x(), 5.0f);
  EXPECT_EQ(c.labels[1], 8u);
}

}  // namespace
