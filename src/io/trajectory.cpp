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
#include "sgtllc/io/quote.h"
#include "sgtllc/types.h"

namespace sgtllc::io {
namespace {

constexpr size_t kKittiColumns = 12;
constexpr size_t kTumColumns = 8;
/// Largest |RᵀR − I| accepted in a KITTI row: files written with 6 significant digits (KITTI's own `%e` poses,
/// SemanticKITTI's `%g`) are off by ~1e-6; anything beyond 1e-3 is not a rotation (wrong column order, a scale).
constexpr double kOrthonormalTolerance = 1e-3;
/// Largest |‖q‖ − 1| accepted in a TUM row: 6 written digits give ~1e-6; a quaternion off by more is not a
/// rotation written by a tool (a scale, a wrong column), and normalising it would hide that.
constexpr double kQuaternionNormTolerance = 1e-3;

std::string where(const std::string& path, size_t line) { return path + ":" + std::to_string(line); }

std::string number(double v, int digits = 3) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.*g", digits, v);
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

}  // namespace

void checkRotation(const Eigen::Matrix3d& R, const std::string& at) {
  const double err = (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (err > kOrthonormalTolerance) {
    throw Error(at + ": rotation is not orthonormal (|RᵀR − I| = " + number(err) + ", at most " +
                number(kOrthonormalTolerance) + ")");
  }
  if (R.determinant() <= 0.0) throw Error(at + ": rotation has determinant " + number(R.determinant()) + " (a reflection)");
}

namespace {

/// The file's KITTI poses, rotations checked, in the file's own frame.
Trajectory readKitti(const std::string& path, const std::vector<Row>& rows) {
  const std::vector<Eigen::Matrix4d> file_poses = readKittiPoses(path);  // no comments or blanks: pose i = row i
  for (size_t i = 0; i < file_poses.size(); ++i) {
    checkRotation(file_poses[i].topLeftCorner<3, 3>(), where(path, rows[i].line));
  }
  Trajectory t;
  t.format = TrajectoryFormat::kKitti;
  t.poses.reserve(file_poses.size());
  for (const Eigen::Matrix4d& M : file_poses) t.poses.push_back(isometry(M));
  return t;
}

std::vector<Eigen::Matrix4d> matrices(const std::vector<Eigen::Isometry3d>& poses) {
  std::vector<Eigen::Matrix4d> out;
  out.reserve(poses.size());
  for (const Eigen::Isometry3d& T : poses) out.push_back(T.matrix());
  return out;
}

/// @p t (cam0 poses as read) converted to the LiDAR frame by @p Tr, the Tr of @p calib_path.
void throughCalib(const std::string& path, const std::vector<Row>& rows, const std::string& calib_path,
                  const Eigen::Matrix4d& Tr, Trajectory& t) {
  t.calib_Tr = Tr;
  const std::vector<Eigen::Matrix4d> poses = lidarPoses(matrices(t.poses), *t.calib_Tr);
  // An invertible but badly scaled Tr (say diag(1e300, 1e-300, 1)) overflows Tr⁻¹ · P · Tr: reject it rather
  // than return non-finite poses (fuzz_trajectory found this; fuzz/README.md).
  for (size_t i = 0; i < poses.size(); ++i) {
    if (!poses[i].allFinite()) {
      throw Error(calib_path + ": its Tr turns the pose of " + where(path, rows[i].line) +
                  " into non-finite numbers (not a rigid velodyne-to-cam0 transform)");
    }
    t.poses[i] = isometry(poses[i]);
  }
}

Trajectory readTum(const std::string& path, const std::vector<Row>& rows) {
  Trajectory t;
  t.format = TrajectoryFormat::kTum;
  for (const Row& row : rows) {
    double v[kTumColumns];
    for (size_t k = 0; k < kTumColumns; ++k) {
      if (!detail::parseReal(row.tokens[k], v[k]) || !std::isfinite(v[k])) {
        throw Error(where(path, row.line) + ": " + quoteContent(row.tokens[k]) + " is not a finite number");
      }
    }
    if (!t.stamps.empty() && v[0] < t.stamps.back()) {
      throw Error(where(path, row.line) + ": time stamp " + quoteContent(row.tokens[0]) +
                  " is before the previous line's (poses must be in sequence order)");
    }
    Eigen::Quaterniond q(v[7], v[4], v[5], v[6]);  // file order qx qy qz qw; Eigen's constructor takes w first
    if (!(std::abs(q.norm() - 1.0) <= kQuaternionNormTolerance)) {
      throw Error(where(path, row.line) + ": quaternion (" + number(v[4]) + ", " + number(v[5]) + ", " +
                  number(v[6]) + ", " + number(v[7]) + ") has norm " + number(q.norm(), 6) +
                  ", not 1 (a rotation's quaternion is a unit one)");
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
  Trajectory t = readKitti(path, rows);
  if (!calib_path.empty()) throughCalib(path, rows, calib_path, readKittiCalibTr(calib_path), t);
  return t;
}

FramedTrajectory readTrajectory(const std::string& path, const std::string& calib_path, PoseFrame frame) {
  const std::string text = detail::readWholeFile(path);
  bool has_comments = false;
  const std::vector<Row> rows = poseRows(path, text, has_comments);
  FramedTrajectory out;
  if (rows.front().tokens.size() == kTumColumns) {
    if (frame == PoseFrame::kCam0) {
      throw Error(path + ": a TUM file, read in the LiDAR frame as given; --pose-frame cam0 is for KITTI files");
    }
    out.trajectory = readTum(path, rows);
    return out;
  }
  if (has_comments) throw Error(path + ": '#' comment lines in a KITTI pose file (pose i must be line i)");
  out.trajectory = readKitti(path, rows);
  // A calib that may apply is read first: a broken one is an error even where the motion then overrides it.
  Eigen::Matrix4d Tr = Eigen::Matrix4d::Identity();
  if (!calib_path.empty() && frame != PoseFrame::kLidar) Tr = readKittiCalibTr(calib_path);
  out.choice = frameChoice(path, matrices(out.trajectory.poses), !calib_path.empty(), frame);
  if (out.choice.through_calib) throughCalib(path, rows, calib_path, Tr, out.trajectory);
  return out;
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
  std::vector<Eigen::Matrix4d> poses = matrices(trajectory.poses);
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
