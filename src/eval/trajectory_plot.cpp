// Top view of trajectories and loop edges (trajectory_plot.h), on the report's Cairo figure (src/plot/figure.h).
#include "sgtllc/eval/trajectory_plot.h"

#include <array>
#include <cstdio>

#include "sgtllc/plot/figure.h"
#include "sgtllc/types.h"

namespace sgtllc::eval {
namespace {

/// The two plotted coordinates of a pose: (x, y) in the LiDAR frame, (x, z) in KITTI's cam0 frame (y points down,
/// so x–z is the ground plane seen from above, as the KITTI devkit plots it).
std::array<double, 2> planar(const Eigen::Isometry3d& T, bool cam0_axes) {
  const Eigen::Vector3d& t = T.translation();
  return {t.x(), cam0_axes ? t.z() : t.y()};
}

void addTrajectory(plot::Figure& fig, const std::vector<Eigen::Isometry3d>& poses, bool cam0_axes,
                   const std::string& label, plot::Color color, double width, bool dashed) {
  if (poses.empty()) return;
  std::vector<double> x, y;
  x.reserve(poses.size());
  y.reserve(poses.size());
  for (const Eigen::Isometry3d& T : poses) {
    const auto p = planar(T, cam0_axes);
    x.push_back(p[0]);
    y.push_back(p[1]);
  }
  fig.line(x, y, label, color, width, dashed);
}

std::string ateText(double v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.3f m", v);
  return buf;
}

}  // namespace

std::string ateLabel(const std::string& name, const PlotAte& ate) {
  if (ate.aligned < 0.0) return name;
  std::string label = name + ": ATE " + ateText(ate.aligned) + " aligned";
  if (ate.unaligned >= 0.0) label += ", " + ateText(ate.unaligned) + " as drawn";
  return label;
}

void plotTrajectories(const std::string& path, const TrajectoryPlotData& data) {
  const std::vector<Eigen::Isometry3d>& anchor = !data.ground_truth.empty() ? data.ground_truth
                                                 : !data.corrected.empty()  ? data.corrected
                                                                            : data.odometry;
  std::vector<std::array<double, 4>> accepted, rejected;
  for (const PlotLoop& l : data.loops) {
    const int n = static_cast<int>(anchor.size());
    if (l.from < 0 || l.to < 0 || l.from >= n || l.to >= n) {
      throw Error("cannot write " + path + ": loop " + std::to_string(l.from) + " -> " + std::to_string(l.to) +
                  " names a frame outside the trajectory's " + std::to_string(n) + " poses");
    }
    const auto a = planar(anchor[static_cast<size_t>(l.from)], data.cam0_axes);
    const auto b = planar(anchor[static_cast<size_t>(l.to)], data.cam0_axes);
    (l.accepted ? accepted : rejected).push_back({a[0], a[1], b[0], b[1]});
  }

  plot::Figure fig(1400, 900);  // wide enough for the ATE legend beside a square map
  std::string title = data.title;
  if (data.odometry_ate.aligned >= 0.0 && data.corrected_ate.aligned >= 0.0 && !data.odometry.empty() &&
      !data.corrected.empty()) {
    title += ": aligned ATE " + ateText(data.odometry_ate.aligned) + " \u2192 " + ateText(data.corrected_ate.aligned);
  }
  fig.title(title);
  fig.legendAt("outside right");  // beside the axes: never over a trajectory
  fig.xlabel("x (m)");
  fig.ylabel(data.cam0_axes ? "z (m)" : "y (m)");
  fig.equalAspect();
  // The ground truth first and wide, in a light colour none of the others uses: a corrected trajectory within a metre
  // of it runs inside the band instead of covering it.
  addTrajectory(fig, data.ground_truth, data.cam0_axes, "ground truth", plot::Color{0.70, 0.70, 0.70}, 8.0, false);
  addTrajectory(fig, data.odometry, data.cam0_axes, ateLabel("odometry", data.odometry_ate),
                plot::Color{0.90, 0.55, 0.0}, 1.5, true);
  addTrajectory(fig, data.corrected, data.cam0_axes, ateLabel("corrected", data.corrected_ate),
                plot::Color{0.0, 0.35, 0.75}, 1.5, false);
  if (!accepted.empty()) {
    fig.segments(accepted, "accepted loop (" + std::to_string(accepted.size()) + ")", plot::Color{0.0, 0.65, 0.2},
                 1.5);
  }
  if (!rejected.empty()) {
    fig.segments(rejected, "rejected loop (" + std::to_string(rejected.size()) + ")", plot::Color{0.9, 0.0, 0.0},
                 1.5);
  }
  if (!anchor.empty()) {
    const auto s = planar(anchor.front(), data.cam0_axes);
    fig.points({s[0]}, {s[1]}, "start", plot::Color{0.0, 0.0, 0.0}, 6.0);
  } else {
    fig.note("no poses");
  }
  fig.savePng(path);
}

}  // namespace sgtllc::eval
