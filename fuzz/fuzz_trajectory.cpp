// Trajectory files, KITTI-12 or TUM-8 (io::readTrajectory), without and with a KITTI calib, through the pose-frame
// rule too, and a write → re-read round trip of whatever was read (trajectory.h: "readTrajectory() gives back the
// same poses").
// Input layout: an even byte 0 reads the rest as the trajectory alone; an odd byte 0 splits the rest into a
// calib.txt part and the trajectory (byte 0 / 2 chooses where), so the calib conversion is fuzzed too.
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "fuzz_support.h"
#include "sgtllc/io/trajectory.h"

using namespace sgtllc;

namespace {

/// |a − b| within @p tol of the larger magnitude (round trips through a calib or a quaternion are not exact).
bool near(const Eigen::Matrix4d& a, const Eigen::Matrix4d& b, double tol) {
  const double scale = std::max({1.0, a.cwiseAbs().maxCoeff(), b.cwiseAbs().maxCoeff()});
  return (a - b).cwiseAbs().maxCoeff() <= tol * scale;
}

/// A calib Tr that is a rotation and a translation to a few digits, as every real KITTI calib is: the round trip
/// through Tr · T · Tr⁻¹ is then well conditioned (any other invertible Tr is accepted but amplifies rounding).
bool rigid(const Eigen::Matrix4d& Tr) {
  const Eigen::Matrix3d R = Tr.topLeftCorner<3, 3>();
  return (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() < 1e-6 &&
         Tr.topRightCorner<3, 1>().cwiseAbs().maxCoeff() < 1e3;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const fuzz::ScratchFile file("trajectory.txt"), calib("calib.txt"), copy("trajectory-copy.txt");
  if (size == 0) return 0;
  const std::string_view rest = fuzz::bytesOf(data + 1, size - 1);
  const bool with_calib = (data[0] & 1) != 0;
  const size_t split = with_calib ? rest.size() * (data[0] >> 1) / 127 : 0;
  calib.write(rest.substr(0, split));
  file.write(rest.substr(split));
  const std::string calib_path = with_calib ? calib.path() : "";

  io::Trajectory t;
  if (!fuzz::readsOrRejects([&] { t = io::readTrajectory(file.path(), calib_path); })) return 0;
  fuzz::require(!t.poses.empty(), "at least one pose");
  const bool tum = t.format == io::TrajectoryFormat::kTum;
  fuzz::require(tum ? t.stamps.size() == t.poses.size() : t.stamps.empty(), "one stamp per TUM pose, none for KITTI");
  fuzz::require(!(tum && t.calib_Tr) && (tum || t.calib_Tr.has_value() == with_calib), "calib only for KITTI");
  for (size_t i = 0; i < t.poses.size(); ++i) {
    fuzz::require(t.poses[i].matrix().allFinite(), "finite poses");
    if (tum) fuzz::require(std::isfinite(t.stamps[i]) && (i == 0 || t.stamps[i - 1] <= t.stamps[i]), "stamps in order");
  }

  // The pose-frame rule on the same bytes (io/trajectory_frame.h): it reads or rejects (a frame it cannot tell is
  // an error), and what it reads is what the plain reader gave, with or without the calib.
  io::FramedTrajectory framed;
  if (fuzz::readsOrRejects([&] { framed = io::readTrajectory(file.path(), calib_path, io::PoseFrame::kAuto); })) {
    const io::Trajectory& f = framed.trajectory;
    fuzz::require(f.poses.size() == t.poses.size() && f.format == t.format, "the rule keeps format and count");
    fuzz::require(f.calib_Tr.has_value() == t.calib_Tr.has_value(), "auto with a calib applies it");
    for (size_t i = 0; i < t.poses.size(); ++i) {
      fuzz::require(f.poses[i].matrix() == t.poses[i].matrix(), "the rule reads the plain reader's poses");
    }
  }

  // What was read writes and reads back: exactly for KITTI without calib (shortest exact decimals), to rounding
  // for TUM (quaternion ↔ matrix) and through a rigid calib.
  if (t.calib_Tr && !rigid(*t.calib_Tr)) return 0;
  // A rotation read at the reader's bound (|RᵀR − I| up to 1e-3) can land just above it once moved through the
  // calib and back: the reader then rightly refuses the copy, so such inputs skip the round trip.
  if (t.calib_Tr) {
    const Eigen::Matrix4d Tr = *t.calib_Tr, Tr_inv = Tr.inverse();
    for (const Eigen::Isometry3d& T : t.poses) {
      const Eigen::Matrix3d R = (Tr * T.matrix() * Tr_inv).topLeftCorner<3, 3>();
      if ((R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() > 1e-3 - 1e-6) return 0;
    }
  }
  copy.write(io::trajectoryText(t));
  const io::Trajectory again = io::readTrajectory(copy.path(), t.calib_Tr ? calib_path : "");
  fuzz::require(again.format == t.format && again.poses.size() == t.poses.size(), "round trip keeps format and count");
  fuzz::require(again.stamps == t.stamps, "round trip keeps the time stamps exactly");
  const double tol = (tum || t.calib_Tr) ? 1e-9 : 0.0;
  for (size_t i = 0; i < t.poses.size(); ++i) {
    fuzz::require(near(again.poses[i].matrix(), t.poses[i].matrix(), tol), "round trip gives back the poses");
  }
  return 0;
}
