// g2o pose graphs: text layout, round trips, the (δt, δθ) ↔ (δt, q_v) information conversion, bad input.
#include <random>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "sgtllc/io/g2o.h"
#include "sgtllc/types.h"
#include "test_io_support.h"
#include "test_trajectory_support.h"

namespace {

using sgtllc::Error;
using sgtllc::backend::Edge;
using sgtllc::backend::EdgeKind;
using sgtllc::backend::Matrix6d;
using sgtllc::backend::PoseGraph;
using ::testing::AllOf;
using ::testing::HasSubstr;

class G2oIo : public sgtllc::test::TempDirTest {
 protected:
  std::string readError(const std::string& text) {
    const std::string file = write("graph.g2o", text);
    return sgtllc::test::errorOf([&] { sgtllc::io::readG2o(file); });
  }
};

/// A random symmetric positive-definite information matrix.
Matrix6d randomInformation(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Matrix6d A;
  for (int k = 0; k < 36; ++k) A(k / 6, k % 6) = u(rng);
  return A * A.transpose() + 0.5 * Matrix6d::Identity();
}

PoseGraph randomGraph(unsigned seed) {
  std::mt19937 rng(seed);
  PoseGraph g;
  g.poses = sgtllc::test::randomPoses(6, seed);
  for (int i = 0; i + 1 < 6; ++i) {
    g.edges.push_back(Edge{i, i + 1, sgtllc::test::randomPose(rng, 2.0), randomInformation(rng), EdgeKind::kOdometry});
  }
  g.edges.push_back(Edge{0, 5, sgtllc::test::randomPose(rng, 2.0), randomInformation(rng), EdgeKind::kLoop});
  return g;
}

void expectEdgesNear(const std::vector<Edge>& a, const std::vector<Edge>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].from, b[k].from);
    EXPECT_EQ(a[k].to, b[k].to);
    EXPECT_EQ(a[k].kind, b[k].kind);
    EXPECT_LE((a[k].T_from_to.matrix() - b[k].T_from_to.matrix()).cwiseAbs().maxCoeff(), 1e-9) << k;
    EXPECT_LE((a[k].information - b[k].information).cwiseAbs().maxCoeff(), 1e-9) << k;
  }
}

TEST(G2oText, LayoutOfVerticesFixAndEdges) {
  PoseGraph g;
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = Eigen::Vector3d(1, 2, 3);
  g.poses = {Eigen::Isometry3d::Identity(), T};
  Matrix6d info = Matrix6d::Identity();
  info(0, 3) = info(3, 0) = 0.5;
  g.edges.push_back(Edge{0, 1, T, info, EdgeKind::kOdometry});
  EXPECT_EQ(sgtllc::io::g2oText(g),
            "VERTEX_SE3:QUAT 0 0 0 0 0 0 0 1\n"
            "VERTEX_SE3:QUAT 1 1 2 3 0 0 0 1\n"
            "FIX 0\n"
            // (δt, δθ) identity → rotation block ×4; the cross entry 0.5 → ×2
            "EDGE_SE3:QUAT 0 1 1 2 3 0 0 0 1 1 0 0 1 0 0 1 0 0 0 0 1 0 0 0 4 0 0 4 0 4\n");
}

TEST(G2oInformation, ConversionMatchesTheChiSquareOfG2osError) {
  // For a small error transform, ours is (δt, θ·axis), g2o's (δt, q_v) with q_v = sin(θ/2)·axis: the same χ²
  // under the converted information, to first order in the error.
  std::mt19937 rng(3);
  const Matrix6d ours = randomInformation(rng);
  const Matrix6d g2o = sgtllc::io::informationToG2o(ours);
  const Eigen::Vector3d dt(1e-4, -2e-4, 3e-4), axis = Eigen::Vector3d(1, 2, -1).normalized();
  const double theta = 2e-4;
  Eigen::Matrix<double, 6, 1> e_ours, e_g2o;
  e_ours << dt, theta * axis;
  e_g2o << dt, Eigen::Quaterniond(Eigen::AngleAxisd(theta, axis)).vec();
  const double chi2_ours = e_ours.dot(ours * e_ours), chi2_g2o = e_g2o.dot(g2o * e_g2o);
  EXPECT_NEAR(chi2_g2o / chi2_ours, 1.0, 1e-7);
  EXPECT_LE((sgtllc::io::informationFromG2o(g2o) - ours).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_DOUBLE_EQ(g2o(4, 4), 4 * ours(4, 4));
  EXPECT_DOUBLE_EQ(g2o(1, 5), 2 * ours(1, 5));
  EXPECT_DOUBLE_EQ(g2o(2, 0), ours(2, 0));
}

TEST_F(G2oIo, GraphRoundTrip) {
  const PoseGraph g = randomGraph(11);
  sgtllc::io::writeG2o(path("g.g2o"), g);
  const PoseGraph back = sgtllc::io::readG2o(path("g.g2o"));
  sgtllc::test::expectPosesNear(back.poses, g.poses, 1e-9);
  expectEdgesNear(back.edges, g.edges);  // kinds inferred: consecutive ids = odometry
}

TEST_F(G2oIo, EdgeListRoundTripWithoutVertices) {
  const PoseGraph g = randomGraph(12);
  const std::vector<Edge> loops = {g.edges.back()};
  sgtllc::io::writeG2oEdges(path("loops.g2o"), loops);
  const PoseGraph back = sgtllc::io::readG2o(path("loops.g2o"));
  EXPECT_TRUE(back.poses.empty());
  expectEdgesNear(back.edges, loops);
}

TEST_F(G2oIo, VerticesInAnyOrderAndComments) {
  const PoseGraph g = sgtllc::io::readG2o(write("g.g2o",
                                                "# made by hand\nVERTEX_SE3:QUAT 1 5 0 0 0 0 0 1\n\n"
                                                "VERTEX_SE3:QUAT 0 0 0 0 0 0 1 0\nFIX 0\n"));
  ASSERT_EQ(g.poses.size(), 2u);
  EXPECT_EQ(g.poses[1].translation().x(), 5.0);
  EXPECT_NEAR(g.poses[0].linear()(0, 0), -1.0, 1e-15);  // 180° about z
}

TEST_F(G2oIo, BadInputNamesLineAndProblem) {
  const std::string v0 = "VERTEX_SE3:QUAT 0 0 0 0 0 0 0 1\n", v1 = "VERTEX_SE3:QUAT 1 1 0 0 0 0 0 1\n";
  const std::string info = " 1 0 0 0 0 0 1 0 0 0 0 1 0 0 0 1 0 0 1 0 1";
  EXPECT_THAT(readError(v0 + "VERTEX_SE2 1 0 0 0\n"), HasSubstr("graph.g2o:2: unknown tag 'VERTEX_SE2'"));
  EXPECT_THAT(readError("VERTEX_SE3:QUAT 0 0 0 0 0 0 1\n"),
              HasSubstr("graph.g2o:1: VERTEX_SE3:QUAT needs 8 values, found 7"));
  EXPECT_THAT(readError("VERTEX_SE3:QUAT 0 0 nan 0 0 0 0 1\n"), HasSubstr("graph.g2o:1: 'nan' is not a finite"));
  EXPECT_THAT(readError("VERTEX_SE3:QUAT 0 0 0 0 0 0 0 0\n"), HasSubstr("graph.g2o:1: quaternion has norm 0"));
  EXPECT_THAT(readError("VERTEX_SE3:QUAT -1 0 0 0 0 0 0 1\n"), HasSubstr("'-1' is not a vertex id"));
  EXPECT_THAT(readError(v0 + v0), HasSubstr("graph.g2o:2: vertex 0 again (first on line 1)"));
  EXPECT_THAT(readError(v0 + "VERTEX_SE3:QUAT 2 0 0 0 0 0 0 1\n"), HasSubstr("1 is missing"));
  EXPECT_THAT(readError(v0 + v1 + "EDGE_SE3:QUAT 0 7 0 0 0 0 0 0 1" + info + "\n"),
              HasSubstr("graph.g2o:3: edge 0 -> 7 names a vertex that is not in the file"));
  EXPECT_THAT(readError(v0 + v1 + "EDGE_SE3:QUAT 1 1 0 0 0 0 0 0 1" + info + "\n"), HasSubstr("to itself"));
  EXPECT_THAT(readError(v0 + v1 + "EDGE_SE3:QUAT 0 1 0 0 0 0 0 0 1 -1 0 0 0 0 0 1 0 0 0 0 1 0 0 0 1 0 0 1 0 1\n"),
              HasSubstr("graph.g2o:3: information matrix is not positive semi-definite"));
  EXPECT_THAT(readError(v0 + v1 + "EDGE_SE3:QUAT 0 1 0 0 0 0 0 0 1 1\n"), HasSubstr("needs 30 values, found 10"));
}

}  // namespace
