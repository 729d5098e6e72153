// Shared by the libFuzzer harnesses of fuzz/ (README "Reliability checks"). The readers of sgtllc_io and
// sgtllc_eval take paths, so each harness writes its input to a scratch file of its own process and reads that
// back; /dev/shm keeps it in memory. A reader may reject the input with sgtllc::Error (the documented outcome for
// bad input); any other exception, a crash, a sanitizer report or a broken invariant (require) is a finding.
#pragma once

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "sgtllc/types.h"

namespace sgtllc::fuzz {

/// A file named after the process, removed when the harness exits normally.
class ScratchFile {
 public:
  /// @p name ends the file name and keeps two files of one harness apart ("scan.bin", "scan.label").
  explicit ScratchFile(const std::string& name) {
    const char* dir = std::getenv("SGTLLC_FUZZ_TMPDIR");
    path_ = std::string(dir ? dir : "/dev/shm") + "/sgtllc-fuzz-" + std::to_string(::getpid()) + "-" + name;
  }
  ~ScratchFile() { std::remove(path_.c_str()); }
  ScratchFile(const ScratchFile&) = delete;
  ScratchFile& operator=(const ScratchFile&) = delete;

  /// Replaces the file's contents with @p bytes; returns its path. Aborts if the file cannot be written, since a
  /// harness that reads a stale file would test nothing.
  const std::string& write(std::string_view bytes) const {
    std::FILE* f = std::fopen(path_.c_str(), "wb");
    if (!f || std::fwrite(bytes.data(), 1, bytes.size(), f) != bytes.size() || std::fclose(f) != 0) {
      std::perror(path_.c_str());
      std::abort();
    }
    return path_;
  }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

/// The fuzzer's input as bytes.
inline std::string_view bytesOf(const uint8_t* data, size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

/// Runs @p read; sgtllc::Error is a normal outcome (returns false), anything else escapes to libFuzzer.
template <typename Read>
bool readsOrRejects(Read read) {
  try {
    read();
    return true;
  } catch (const Error&) {
    return false;
  }
}

/// A broken invariant of a reader's result: a silently wrong result is a finding like a crash.
inline void require(bool condition, const char* what) {
  if (!condition) {
    std::fprintf(stderr, "sgtllc fuzz: invariant broken: %s\n", what);
    std::abort();
  }
}

/// The checks of a point-cloud reader pair (PCD, PLY): @p with_labels reads points and labels, @p points_only the
/// points. As many labels as points; the points-only read needs a subset of the fields, so where the labelled
/// read succeeds it must too, with the same points to the bit (NaN coordinates are kept); no more points than
/// input bytes.
template <typename WithLabels, typename PointsOnly>
void checkCloudReaders(size_t size, WithLabels with_labels, PointsOnly points_only) {
  std::vector<Eigen::Vector3f> labelled;
  const bool read_labelled = readsOrRejects([&] {
    const LabeledCloud cloud = with_labels();
    require(cloud.points.size() == cloud.labels.size(), "as many labels as points");
    labelled = cloud.points;
  });
  const bool read_points = readsOrRejects([&] {
    const std::vector<Eigen::Vector3f> points = points_only();
    require(points.size() <= size, "no more points than input bytes");
    if (read_labelled) {
      require(points.size() == labelled.size() &&
                  (points.empty() ||
                   std::memcmp(points.data(), labelled.data(), points.size() * sizeof(Eigen::Vector3f)) == 0),
              "the points-only read gives the labelled read's points");
    }
  });
  require(!read_labelled || read_points, "a file read with labels is read without them too");
}

}  // namespace sgtllc::fuzz
