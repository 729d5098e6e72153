// KITTI / TUM trajectory files (trajectory.h). KITTI rows are parsed by readKittiPoses (kitti.h) so both readers
// accept the same numbers; this file adds the format detection, the TUM rows and the checks on rotations.
#include "sgtllc/io/trajectory.h"

#include <cmath>
#include <cstdio>
#include <string_view>
#include <utility>

#include <Eigen/LU>

#include "sgtllc/io/output_file.h"
#include "file_util.h"
#include "sgtllc/io/kitti.h"
#include "sgtllc/io/kitti_write.h"
#include "sgtllc/types.h"

namespace sgtllc::io {
namespace {

constexpr size_t kKittiColumns = 12;
constexpr size_t kTumColumns = 8;
/// Largest |RᵀR − I| accepted in a KITTI row: files written with 6 significant digits (KITTI's own `%e` poses,
/// SemanticKITTI's `%g`) are off by ~1e-6; anything beyond 1e-3 is not a rotation (wrong column order, a scale).
constexpr double kOrthonormalTolerance = 1e-3;
/// Below this norm a TUM quaternion has no direction to normalise.
constexpr double kMinQuaternionNorm = 1e-6;

std::string where(const std::string& path, size_t line) { return path + ":" + std::to_string(line); }

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.3g", v);
  return buf;
}

/// A pose line: its line number and tokens.
struct Row {
  size_t line = 0;
  std::vector<std::string_view> tokens;
};

/// Splits @p text into pose rows, checking the layout shared by both formats: one column count for the whole file,
/// nothing after a blank line, `#` comments (TUM) only before or between poses.
std::vector<Row> poseRows(const std::string& path, const std::string& text, bool& has_comments) {
  std::vector<Row> rows;
  size_t pos = 0, line = 0, first_blank = 0;
  while (pos < text.size()) {
    ++line;
    std::vector<std::string_view> tokens = detail::splitBlanks(detail::nextLine(text, pos));
    if (tokens.empty()) {
      if (first_blank == 0) first_blank = line;
      continue;
    }
    if (tokens.front().front() == '#') {
      has_comments = true;
      continue;
    }
    if (first_blank != 0) {
      throw Error(where(path, line) + ": pose after blank line " + std::to_string(first_blank) +
                  " (pose i must be line i)");
    }
    const size_t n = tokens.size();
    if (n != kKittiColumns && n != kTumColumns) {
      throw Error(where(path, line) + ": " + std::to_string(n) +
                  " columns; expected 12 (KITTI: row-major 3x4 [R|t]) or 8 (TUM: t x y z qx qy qz qw)");
    }
    if (!rows.empty() && n != rows.front().tokens.size()) {
      throw Error(where(path, line) + ": " + std::to_string(n) + " columns, but line " +
                  std::to_string(rows.front().line) + " has " + std::to_string(rows.front().tokens.size()) +
                  " (one format per file)");
    }
    rows.push_back(Row{line, std::move(tokens)});
  }
  if (rows.empty()) throw Error(path + ": no poses (empty trajectory file)");
  return rows;
}

Eigen::Isometry3d isometry(const Eigen::Matrix4d& M) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = M.topLeftCorner<3, 3>();
  T.translation() = M.topRightCorner<3, 1>();
  return T;
}

void checkRotation(const Eigen::Matrix4d& M, const std::string& at) {
  const Eigen::Matrix3d R = M.topLeftCorner<3, 3>();
  const double err = (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (err > kOrthonormalTolerance) {
    throw Error(at + ": rotation is not orthonormal (|RᵀR − I| = " + number(err) + ", at most " +
                number(kOrthonormalTolerance) + ")");
  }
  if (R.determinant() <= 0.0) throw Error(at + ": rotation has determinant " + number(R.determinant()) + " (a reflection)");
}

Trajectory readKitti(const std::string& path, const std::vector<Row>& rows, const std::string& calib_path) {
  const std::vector<Eigen::Matrix4d> file_poses = readKittiPoses(path);  // no comments or blanks: pose i = row i
  for (size_t i = 0; i < file_poses.size(); ++i) checkRotation(file_poses[i], where(path, rows[i].line));
  Trajectory t;
  t.format = TrajectoryFormat::kKitti;
  std::vector<Eigen::Matrix4d> poses = file_poses;
  if (!calib_path.empty()) {
    t.calib_Tr = readKittiCalibTr(calib_path);
    poses = lidarPoses(file_poses, *t.calib_Tr);
    // An invertible but badly scaled Tr (say diag(1e300, 1e-300, 1)) overflows Tr⁻¹ · P · Tr: reject it rather
    // than return non-finite poses (fuzz_trajectory found this; fuzz/README.md).
    for (size_t i = 0; i < poses.size(); ++i) {
      if (!poses[i].allFinite()) {
        throw Error(calib_path + ": its Tr turns the pose of " + where(path, rows[i].line) +
                    " into non-finite numbers (not a rigid velodyne-to-cam0 transform)");
      }
    }
  }
  t.poses.reserve(poses.size());
  for (const Eigen::Matrix4d& M : poses) t.poses.push_back(isometry(M));
  return t;
}

Trajectory readTum(const std::string& path, const std::vector<Row>& rows) {
  Trajectory t;
  t.format = TrajectoryFormat::kTum;
  for (const Row& row : rows) {
    double v[kTumColumns];
    for (size_t k = 0; k < kTumColumns; ++k) {
      if (!detail::parseReal(row.tokens[k], v[k]) || !std::isfinite(v[k])) {
        throw Error(where(path, row.line) + ": '" + std::string(row.tokens[k]) + "' is not a finite number");
      }
    }
    if (!t.stamps.empty() && v[0] < t.stamps.back()) {
      throw Error(where(path, row.line) + ": time stamp " + std::string(row.tokens[0]) +
                  " is before the previous line's (poses must be in sequence order)");
    }
    Eigen::Quaterniond q(v[7], v[4], v[5], v[6]);  // file order qx qy qz qw; Eigen's constructor takes w first
    if (q.norm() < kMinQuaternionNorm) {
      throw Error(where(path, row.line) + ": quaternion (" + number(v[4]) + ", " + number(v[5]) + ", " +
                  number(v[6]) + ", " + number(v[7]) + ") has norm " + number(q.norm()) + " (not a rotation)");
    }
    q.normalize();
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = q.toRotationMatrix();
    T.translation() = Eigen::Vector3d(v[1], v[2], v[3]);
    t.stamps.push_back(v[0]);
    t.poses.push_back(T);
  }
  return t;
}

void appendTumRow(std::string& out, double stamp, const Eigen::Isometry3d& T) {
  Eigen::Quaterniond q(Eigen::Matrix3d(T.linear()));
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();  // one of the two signs, always the same one
  const double v[kTumColumns] = {stamp, T.translation().x(), T.translation().y(), T.translation().z(),
                                 q.x(),  q.y(),              q.z(),              q.w()};
  for (size_t k = 0; k < kTumColumns; ++k) {
    if (k > 0) out += ' ';
    detail::appendShortest(out, v[k]);
  }
  out += '\n';
}

}  // namespace

Trajectory readTrajectory(const std::string& path, const std::string& calib_path) {
  const std::string text = detail::readWholeFile(path);
  bool has_comments = false;
  const std::vector<Row> rows = poseRows(path, text, has_comments);
  if (rows.front().tokens.size() == kTumColumns) return readTum(path, rows);
  if (has_comments) throw Error(path + ": '#' comment lines in a KITTI pose file (pose i must be line i)");
  return readKitti(path, rows, calib_path);
}

std::string trajectoryText(const Trajectory& trajectory) {
  if (trajectory.format == TrajectoryFormat::kTum) {
    if (trajectory.stamps.size() != trajectory.poses.size()) {
      throw Error("TUM trajectory with " + std::to_string(trajectory.poses.size()) + " poses but " +
                  std::to_string(trajectory.stamps.size()) + " time stamps");
    }
    std::string text;
    for (size_t i = 0; i < trajectory.poses.size(); ++i) appendTumRow(text, trajectory.stamps[i], trajectory.poses[i]);
    return text;
  }
  std::vector<Eigen::Matrix4d> poses;
  poses.reserve(trajectory.poses.size());
  for (const Eigen::Isometry3d& T : trajectory.poses) poses.push_back(T.matrix());
  if (trajectory.calib_Tr) {
    const Eigen::Matrix4d& Tr = *trajectory.calib_Tr;
    const Eigen::Matrix4d Tr_inv = Tr.inverse();  // the full inverse, as lidarPoses uses
    for (Eigen::Matrix4d& M : poses) M = Tr * M * Tr_inv;
  }
  return kittiPosesText(poses);
}

void writeTrajectory(const std::string& path, const Trajectory& trajectory, Overwrite overwrite) {
  std::string text;
  try {
    text = trajectoryText(trajectory);
  } catch (const Error& e) {
    throw Error("cannot write " + path + ": " + e.what());
  }
  writeFileAtomically(path, text, overwrite);
}

Trajectory withPoses(const Trajectory& trajectory, std::vector<Eigen::Isometry3d> poses) {
  if (poses.size() != trajectory.poses.size()) {
    throw Error("trajectory has " + std::to_string(trajectory.poses.size()) + " poses, the replacement " +
                std::to_string(poses.size()));
  }
  Trajectory out = trajectory;
  out.poses = std::move(poses);
  return out;
}

void checkPoseCount(const std::string& path, const Trajectory& trajectory, size_t frames) {
  if (trajectory.poses.size() != frames) {
    throw Error(path + ": " + std::to_string(trajectory.poses.size()) + " poses but the sequence has " +
                std::to_string(frames) + " frames (one pose per frame, in sequence order)");
  }
}

}  // namespace sgtllc::io
