// g2o pose graphs (io::readG2o): vertices, edges with information, FIX; then a write → re-read round trip of
// whatever was read (g2o.h: the writer applies the information conversion and the reader undoes it).
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "fuzz_support.h"
#include "sgtllc/io/g2o.h"

using namespace sgtllc;

namespace {

bool rotation(const Eigen::Matrix3d& R) {
  return R.allFinite() && (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() < 1e-9 &&
         R.determinant() > 0.0;
}

/// Equal to rounding: the rotations go matrix → quaternion → matrix, the information through ×4 and ×¼ (exact
/// unless subnormal), so a relative 1e-12 of the larger magnitude bounds both.
template <typename M>
bool near(const M& a, const M& b, double tol) {
  const double scale = std::max({1.0, a.cwiseAbs().maxCoeff(), b.cwiseAbs().maxCoeff()});
  return (a - b).cwiseAbs().maxCoeff() <= tol * scale;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const fuzz::ScratchFile file("graph.g2o"), copy("graph-copy.g2o");
  file.write(fuzz::bytesOf(data, size));
  backend::PoseGraph g;
  if (!fuzz::readsOrRejects([&] { g = io::readG2o(file.path()); })) return 0;
  const int n = static_cast<int>(g.poses.size());
  for (const Eigen::Isometry3d& T : g.poses) {
    fuzz::require(rotation(T.linear()) && T.translation().allFinite(), "vertex poses are finite rigid motions");
  }
  for (const backend::Edge& e : g.edges) {
    fuzz::require(e.from >= 0 && e.to >= 0 && e.from != e.to, "edge ids are distinct and not negative");
    fuzz::require(n == 0 || (e.from < n && e.to < n), "edges join vertices of the file");
    fuzz::require(rotation(e.T_from_to.linear()) && e.T_from_to.translation().allFinite(), "edge poses are rigid");
    fuzz::require(e.information.allFinite() && e.information == e.information.transpose(), "symmetric information");
    fuzz::require((e.kind == backend::EdgeKind::kOdometry) == (e.to == e.from + 1), "odometry iff consecutive");
  }

  copy.write(io::g2oText(g));
  const backend::PoseGraph again = io::readG2o(copy.path());
  fuzz::require(again.poses.size() == g.poses.size() && again.edges.size() == g.edges.size(), "round trip keeps counts");
  for (size_t i = 0; i < g.poses.size(); ++i) {
    fuzz::require(near(again.poses[i].matrix(), g.poses[i].matrix(), 1e-12), "round trip keeps the vertex poses");
  }
  for (size_t i = 0; i < g.edges.size(); ++i) {
    const backend::Edge &a = again.edges[i], &e = g.edges[i];
    fuzz::require(a.from == e.from && a.to == e.to && a.kind == e.kind, "round trip keeps the edge ends");
    fuzz::require(near(a.T_from_to.matrix(), e.T_from_to.matrix(), 1e-12), "round trip keeps the edge poses");
    fuzz::require(near(a.information, e.information, 1e-12), "round trip keeps the information");
  }
  return 0;
}
