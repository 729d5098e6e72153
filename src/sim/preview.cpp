#include "sgtllc/sim/preview.h"

#include <algorithm>
#include <map>
#include <numeric>

#include <Eigen/LU>

#include "sgtllc/plot/figure.h"

namespace sgtllc::sim {
namespace {

using plot::Color;

struct ClassStyle {
  uint16_t id;
  const char* name;
  Color color;
};

Color rgb(int r, int g, int b) { return Color{r / 255.0, g / 255.0, b / 255.0, 1.0}; }

// SemanticKITTI's colour map (semantic-kitti.yaml lists BGR; these are RGB).
const ClassStyle kStyles[] = {
    {0, "unlabeled", rgb(0, 0, 0)},          {10, "car", rgb(100, 150, 245)},
    {18, "truck", rgb(80, 30, 180)},         {20, "other-vehicle", rgb(0, 0, 255)},
    {30, "person", rgb(255, 30, 30)},        {40, "road", rgb(255, 0, 255)},
    {44, "parking", rgb(255, 150, 255)},     {48, "sidewalk", rgb(75, 0, 75)},
    {49, "other-ground", rgb(175, 0, 75)},   {50, "building", rgb(255, 200, 0)},
    {51, "fence", rgb(255, 120, 50)},        {52, "other-structure", rgb(255, 150, 0)},
    {70, "vegetation", rgb(0, 175, 0)},      {71, "trunk", rgb(135, 60, 0)},
    {72, "terrain", rgb(150, 240, 80)},      {80, "pole", rgb(255, 240, 150)},
    {81, "traffic-sign", rgb(255, 0, 0)},    {99, "other-object", rgb(50, 255, 255)},
    {252, "moving-car", rgb(100, 150, 245)}, {254, "moving-person", rgb(255, 30, 30)},
};

const ClassStyle kUnknown = {0xFFFF, "other", rgb(128, 128, 128)};

const ClassStyle& styleOf(uint16_t id) {
  for (const ClassStyle& s : kStyles) {
    if (s.id == id) return s;
  }
  return kUnknown;
}

Color kindColor(VisitKind k) {
  switch (k) {
    case VisitKind::kSameDirection: return rgb(0, 158, 115);
    case VisitKind::kOppositeDirection: return rgb(213, 94, 0);
    case VisitKind::kLaneShift1: return rgb(0, 114, 178);
    case VisitKind::kLaneShift2: return rgb(204, 121, 167);
    default: return rgb(150, 150, 150);
  }
}

}  // namespace

const char* semanticName(uint16_t id) { return styleOf(id).name; }

void writeScanPreview(const std::string& path, const SimFrame& frame, const std::string& title,
                      io::Overwrite overwrite) {
  constexpr double kHalf = 50.0;
  // Low points first, so poles, trunks and signs stay visible over the ground.
  std::vector<size_t> order(frame.points.size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return frame.points[a].z() < frame.points[b].z(); });
  std::vector<double> x, y;
  std::vector<Color> colors;
  std::map<uint16_t, size_t> counts;
  for (size_t i : order) {
    const Eigen::Vector3f& p = frame.points[i];
    if (std::abs(p.x()) > kHalf || std::abs(p.y()) > kHalf) continue;
    const uint16_t id = static_cast<uint16_t>(frame.labels[i] & 0xFFFF);
    x.push_back(p.x());
    y.push_back(p.y());
    colors.push_back(styleOf(id).color);
    ++counts[id];
  }
  plot::Figure fig(1400, 1400);
  fig.title(title);
  fig.xlabel("x (m, forward)");
  fig.ylabel("y (m, left)");
  fig.xlim(-kHalf, kHalf);
  fig.ylim(-kHalf, kHalf);
  fig.equalAspect();
  fig.coloredPoints(x, y, colors, 1.1);
  std::vector<std::pair<size_t, uint16_t>> by_count;
  for (const auto& [id, c] : counts) by_count.push_back({c, id});
  std::sort(by_count.rbegin(), by_count.rend());
  const double total = static_cast<double>(x.size());
  for (const auto& [c, id] : by_count) {
    char share[32];
    std::snprintf(share, sizeof(share), " %.1f%%", 100.0 * c / std::max(1.0, total));
    fig.legendEntry(styleOf(id).name + std::string(share), styleOf(id).color);
  }
  io::writeThroughTemporary(path, overwrite, [&](const std::string& tmp) { fig.savePng(tmp); });
}

void writeTrajectoryPreview(const std::string& path, const Simulator& sim,
                            const std::vector<Eigen::Matrix4d>& lidar_poses, const std::vector<LoopPair>& pairs,
                            io::Overwrite overwrite) {
  plot::Figure fig(1400, 1400);
  const Eigen::Matrix4d to0 = sim.T_world_origin().inverse();
  auto local = [&](const Eigen::Vector2d& w) {
    const Eigen::Vector4d p = to0 * Eigen::Vector4d(w.x(), w.y(), 0.0, 1.0);
    return Eigen::Vector2d(p.x(), p.y());
  };
  std::vector<std::array<double, 4>> roads;
  for (const RoadEdge& e : sim.world().roads.edges()) {
    for (size_t k = 0; k + 1 < e.line.size(); ++k) {
      const Eigen::Vector2d a = local(e.line[k]), b = local(e.line[k + 1]);
      roads.push_back({a.x(), a.y(), b.x(), b.y()});
    }
  }
  fig.segments(roads, "roads", rgb(215, 215, 215), 6.0);
  if (sim.isSecondSession()) {
    std::vector<double> fx, fy;
    for (const Eigen::Matrix4d& T : sim.firstSessionPoses()) {
      const Eigen::Vector2d p = local(T.topRightCorner<2, 1>());
      fx.push_back(p.x());
      fy.push_back(p.y());
    }
    fig.line(fx, fy, "first session", rgb(150, 190, 235), 5.0);
  }
  // The route in runs of one visit kind.
  const int n = static_cast<int>(lidar_poses.size());
  std::map<VisitKind, bool> labelled;
  for (int start = 0; start < n;) {
    const VisitKind kind = isRevisit(sim.poses()[start].kind) ? sim.poses()[start].kind : VisitKind::kExplore;
    int end = start;
    std::vector<double> x, y;
    while (end < n && (isRevisit(sim.poses()[end].kind) ? sim.poses()[end].kind : VisitKind::kExplore) == kind) {
      x.push_back(lidar_poses[end](0, 3));
      y.push_back(lidar_poses[end](1, 3));
      ++end;
    }
    if (end < n) {  // join the next run
      x.push_back(lidar_poses[end](0, 3));
      y.push_back(lidar_poses[end](1, 3));
    }
    const bool first = !labelled[kind];
    labelled[kind] = true;
    fig.line(x, y, first ? (kind == VisitKind::kExplore ? "driven" : std::string("revisit: ") + visitKindName(kind)) : "",
             kindColor(kind), kind == VisitKind::kExplore ? 1.5 : 3.0);
    start = end;
  }
  std::vector<double> qx, qy;
  int last_query = -1;
  for (const LoopPair& p : pairs) {
    if (!p.loop || p.query == last_query) continue;  // pairs are sorted by query
    last_query = p.query;
    qx.push_back(lidar_poses[p.query](0, 3));
    qy.push_back(lidar_poses[p.query](1, 3));
  }
  fig.points(qx, qy, "frames with a loop within 3 m", rgb(0, 0, 0), 1.6);
  // A first session starts at the origin by construction; a second one wherever it is in the first one's frame.
  const bool second = sim.isSecondSession() && n > 0;
  fig.points({second ? lidar_poses[0](0, 3) : 0.0}, {second ? lidar_poses[0](1, 3) : 0.0}, "start", rgb(230, 0, 0),
             6.0);
  fig.title(std::string("simulated ") + sceneName(sim.config().scene) +
            (sim.isSecondSession() ? " second session: " : " sequence: ") + std::to_string(n) +
            " frames, " + std::to_string(qx.size()) + " loop queries");
  // A second session's poses are in its first session's frame 0.
  const std::string frame = sim.isSecondSession() ? "first session's frame 0" : "frame 0";
  fig.xlabel("x (m, " + frame + ")");
  fig.ylabel("y (m, " + frame + ")");
  fig.equalAspect();
  fig.legendAt("upper left");
  // Frame the route, not the whole road network.
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (const Eigen::Matrix4d& T : lidar_poses) {
    x0 = std::min(x0, T(0, 3));
    x1 = std::max(x1, T(0, 3));
    y0 = std::min(y0, T(1, 3));
    y1 = std::max(y1, T(1, 3));
  }
  fig.xlim(x0 - 40, x1 + 40);
  fig.ylim(y0 - 40, y1 + 40);
  io::writeThroughTemporary(path, overwrite, [&](const std::string& tmp) { fig.savePng(tmp); });
}

}  // namespace sgtllc::sim
