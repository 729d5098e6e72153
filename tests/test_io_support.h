// Shared by the file-format test suites (test_io_*.cpp): a fixture that gives each test its own empty directory.
#pragma once

#include <unistd.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <utility>

#include <gtest/gtest.h>

#include "sgtllc/types.h"

namespace sgtllc::test {

/// The message of the sgtllc::Error that @p f throws; a test failure (and "") if it throws none.
template <typename F>
std::string errorOf(F&& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  ADD_FAILURE() << "no sgtllc::Error thrown";
  return "";
}

/// Gives each test its own empty directory, named after the suite, the test and the pid (so parallel ctest runs
/// never share one), and removes it afterwards.
class TempDirTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string(info->test_suite_name()) + "_" + info->name();
    for (char& ch : name) {
      if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';  // parameterised names hold '/'
    }
    dir_ = std::filesystem::path(::testing::TempDir()) / ("sgtllc_" + name + "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  /// dir_/relative as a string (the file need not exist).
  std::string path(const std::string& relative) const { return (dir_ / relative).string(); }
  /// Creates dir_/relative (parent directories included) holding @p bytes; returns its path.
  std::string write(const std::string& relative, const std::string& bytes = "") const {
    const std::filesystem::path p = dir_ / relative;
    std::filesystem::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << bytes;
    return p.string();
  }
  std::filesystem::path dir_;
};

/// Width and height from a PNG's IHDR chunk (big-endian at bytes 16..23), 0×0 if the signature is wrong.
inline std::pair<int, int> pngSize(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  unsigned char h[24] = {};
  in.read(reinterpret_cast<char*>(h), 24);
  if (h[1] != 'P' || h[2] != 'N' || h[3] != 'G') return {0, 0};
  const auto be = [&](int k) { return (h[k] << 24) | (h[k + 1] << 16) | (h[k + 2] << 8) | h[k + 3]; };
  return {be(16), be(20)};
}

}  // namespace sgtllc::test
