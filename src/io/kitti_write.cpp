// KITTI / SemanticKITTI writers; the formats are those of kitti.h (data/README.md "Formats (short)").
#include "sgtllc/io/kitti_write.h"

#include <cstdio>
#include <cstring>
#include <string_view>
#include <utility>

#include "file_util.h"
#include "sgtllc/types.h"

namespace sgtllc::io {
namespace {

/// Writes 4-byte words in little-endian order.
template <typename T>
void writeWords(const std::string& path, std::vector<T> words, Overwrite overwrite) {
  detail::swapWordsIfBigEndian(words);
  writeFileAtomically(path, std::string_view(reinterpret_cast<const char*>(words.data()), 4 * words.size()), overwrite);
}

/// A 3×4 matrix as 12 row-major numbers in KITTI calib.txt's notation.
void appendRow12(std::string& out, const Eigen::Matrix<double, 3, 4>& M) {
  char buf[64];
  for (int k = 0; k < 12; ++k) {
    std::snprintf(buf, sizeof(buf), "%.12e", M(k / 4, k % 4));
    if (k > 0) out += ' ';
    out += buf;
  }
  out += '\n';
}

// calib.txt of KITTI odometry sequences 00–02, as data/kitti/00/calib.txt.
constexpr double kP[4][12] = {
    {7.188560000000e+02, 0, 6.071928000000e+02, 0, 0, 7.188560000000e+02, 1.852157000000e+02, 0, 0, 0, 1, 0},
    {7.188560000000e+02, 0, 6.071928000000e+02, -3.861448000000e+02, 0, 7.188560000000e+02, 1.852157000000e+02, 0, 0,
     0, 1, 0},
    {7.188560000000e+02, 0, 6.071928000000e+02, 4.538225000000e+01, 0, 7.188560000000e+02, 1.852157000000e+02,
     -1.130887000000e-01, 0, 0, 1, 3.779761000000e-03},
    {7.188560000000e+02, 0, 6.071928000000e+02, -3.372877000000e+02, 0, 7.188560000000e+02, 1.852157000000e+02,
     2.369057000000e+00, 0, 0, 1, 4.915215000000e-03},
};
constexpr double kTr[12] = {4.276802385584e-04,  -9.999672484946e-01, -8.084491683471e-03, -1.198459927713e-02,
                            -7.210626507497e-03, 8.081198471645e-03,  -9.999413164504e-01, -5.403984729748e-02,
                            9.999738645903e-01,  4.859485810390e-04,  -7.206933692422e-03, -2.921968648686e-01};

}  // namespace

void writeKittiBin(const std::string& path, const std::vector<Eigen::Vector3f>& points,
                   const std::vector<float>& intensity, Overwrite overwrite) {
  if (points.size() != intensity.size()) {
    throw Error("cannot write " + path + ": " + std::to_string(points.size()) + " points but " +
                std::to_string(intensity.size()) + " intensities");
  }
  std::vector<float> words(4 * points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    words[4 * i] = points[i].x();
    words[4 * i + 1] = points[i].y();
    words[4 * i + 2] = points[i].z();
    words[4 * i + 3] = intensity[i];
  }
  writeWords(path, std::move(words), overwrite);
}

void writeLabelFile(const std::string& path, const std::vector<uint32_t>& labels, Overwrite overwrite) {
  writeWords(path, labels, overwrite);
}

std::string kittiPosesText(const std::vector<Eigen::Matrix4d>& poses) {
  std::string text;
  for (const Eigen::Matrix4d& T : poses) {
    for (int k = 0; k < 12; ++k) {
      if (k > 0) text += ' ';
      detail::appendShortest(text, T(k / 4, k % 4));
    }
    text += '\n';
  }
  return text;
}

void writeKittiPoses(const std::string& path, const std::vector<Eigen::Matrix4d>& poses, Overwrite overwrite) {
  writeFileAtomically(path, kittiPosesText(poses), overwrite);
}

void writeKittiCalib(const std::string& path, const std::array<Eigen::Matrix<double, 3, 4>, 4>& P,
                     const Eigen::Matrix4d& Tr, Overwrite overwrite) {
  std::string text;
  for (int k = 0; k < 4; ++k) {
    text += "P" + std::to_string(k) + ": ";
    appendRow12(text, P[k]);
  }
  text += "Tr: ";
  appendRow12(text, Tr.topRows<3>());
  writeFileAtomically(path, text, overwrite);
}

void writeKittiTimes(const std::string& path, const std::vector<double>& times, Overwrite overwrite) {
  std::string text;
  char buf[32];
  for (double t : times) {
    std::snprintf(buf, sizeof(buf), "%e\n", t);
    text += buf;
  }
  writeFileAtomically(path, text, overwrite);
}

std::array<Eigen::Matrix<double, 3, 4>, 4> kittiProjections() {
  std::array<Eigen::Matrix<double, 3, 4>, 4> P;
  for (int k = 0; k < 4; ++k) {
    for (int e = 0; e < 12; ++e) P[k](e / 4, e % 4) = kP[k][e];
  }
  return P;
}

Eigen::Matrix4d kittiVelodyneToCam0() {
  Eigen::Matrix4d Tr = Eigen::Matrix4d::Identity();
  for (int e = 0; e < 12; ++e) Tr(e / 4, e % 4) = kTr[e];
  return Tr;
}

}  // namespace sgtllc::io
