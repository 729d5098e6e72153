// g2o pose-graph files (g2o.h): VERTEX_SE3:QUAT, EDGE_SE3:QUAT, FIX.
#include "sgtllc/io/g2o.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <string_view>

#include <Eigen/Eigenvalues>

#include "sgtllc/io/output_file.h"
#include "file_util.h"
#include "sgtllc/io/quote.h"
#include "sgtllc/types.h"

namespace sgtllc::io {
namespace {

constexpr const char* kVertexTag = "VERTEX_SE3:QUAT";
constexpr const char* kEdgeTag = "EDGE_SE3:QUAT";
constexpr const char* kFixTag = "FIX";
constexpr size_t kPoseValues = 7;          // x y z qx qy qz qw
constexpr size_t kInformationValues = 21;  // upper triangle of 6×6, row by row

/// J = diag(I, 2·I) maps g2o's error (δt, q_v) to ours (δt, δθ); see g2o.h.
backend::Matrix6d errorMap(double rotation_scale) {
  backend::Matrix6d J = backend::Matrix6d::Identity();
  J.bottomRightCorner<3, 3>() *= rotation_scale;
  return J;
}

void appendNumber(std::string& out, double v) {
  out += ' ';
  detail::appendShortest(out, v);
}

void appendPose(std::string& out, const Eigen::Isometry3d& T) {
  Eigen::Quaterniond q(Eigen::Matrix3d(T.linear()));
  q.normalize();
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();
  for (int k = 0; k < 3; ++k) appendNumber(out, T.translation()[k]);
  appendNumber(out, q.x());
  appendNumber(out, q.y());
  appendNumber(out, q.z());
  appendNumber(out, q.w());
}

void appendEdge(std::string& out, const backend::Edge& e) {
  out += std::string(kEdgeTag) + " " + std::to_string(e.from) + " " + std::to_string(e.to);
  appendPose(out, e.T_from_to);
  const backend::Matrix6d info = informationToG2o(e.information);
  for (int r = 0; r < 6; ++r) {
    for (int c = r; c < 6; ++c) appendNumber(out, info(r, c));
  }
  out += '\n';
}

/// Parses the tokens of one line, with the line's location for messages.
class LineParser {
 public:
  LineParser(std::string at, const std::vector<std::string_view>& tokens) : at_(std::move(at)), tokens_(tokens) {}

  void expectCount(size_t values) const {
    if (tokens_.size() != values + 1) {
      throw Error(at_ + ": " + std::string(tokens_[0]) + " needs " + std::to_string(values) + " values, found " +
                  std::to_string(tokens_.size() - 1));
    }
  }
  int id(size_t k) const {
    int v = 0;
    if (!detail::parseInteger(tokens_[k], v) || v < 0) {
      throw Error(at_ + ": " + quoteContent(tokens_[k]) + " is not a vertex id (an integer ≥ 0)");
    }
    return v;
  }
  double real(size_t k) const {
    double v = 0.0;
    if (!detail::parseReal(tokens_[k], v) || !std::isfinite(v)) {
      throw Error(at_ + ": " + quoteContent(tokens_[k]) + " is not a finite number");
    }
    return v;
  }
  Eigen::Isometry3d pose(size_t first) const {
    const Eigen::Vector3d t(real(first), real(first + 1), real(first + 2));
    Eigen::Quaterniond q(real(first + 6), real(first + 3), real(first + 4), real(first + 5));
    if (q.norm() < 1e-6) throw Error(at_ + ": quaternion has norm " + std::to_string(q.norm()) + " (not a rotation)");
    q.normalize();
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = q.toRotationMatrix();
    T.translation() = t;
    return T;
  }
  backend::Matrix6d information(size_t first) const {
    backend::Matrix6d info;
    size_t k = first;
    for (int r = 0; r < 6; ++r) {
      for (int c = r; c < 6; ++c) info(r, c) = info(c, r) = real(k++);
    }
    const double min_eig = Eigen::SelfAdjointEigenSolver<backend::Matrix6d>(info, Eigen::EigenvaluesOnly)
                               .eigenvalues()
                               .minCoeff();
    if (min_eig < -1e-9 * std::max(1.0, info.diagonal().cwiseAbs().maxCoeff())) {
      throw Error(at_ + ": information matrix is not positive semi-definite (smallest eigenvalue " +
                  std::to_string(min_eig) + ")");
    }
    return informationFromG2o(info);
  }
  const std::string& at() const { return at_; }

 private:
  std::string at_;
  const std::vector<std::string_view>& tokens_;
};

}  // namespace

backend::Matrix6d informationToG2o(const backend::Matrix6d& ours) {
  const backend::Matrix6d J = errorMap(2.0);
  return J.transpose() * ours * J;
}

backend::Matrix6d informationFromG2o(const backend::Matrix6d& g2o) {
  const backend::Matrix6d J_inv = errorMap(0.5);
  return J_inv.transpose() * g2o * J_inv;
}

std::string g2oText(const backend::PoseGraph& graph) {
  std::string out;
  for (size_t i = 0; i < graph.poses.size(); ++i) {
    out += std::string(kVertexTag) + " " + std::to_string(i);
    appendPose(out, graph.poses[i]);
    out += '\n';
  }
  if (!graph.poses.empty()) out += std::string(kFixTag) + " 0\n";
  out += g2oEdgesText(graph.edges);
  return out;
}

std::string g2oEdgesText(const std::vector<backend::Edge>& edges) {
  std::string out;
  for (const backend::Edge& e : edges) appendEdge(out, e);
  return out;
}

void writeG2o(const std::string& path, const backend::PoseGraph& graph, Overwrite overwrite) {
  writeFileAtomically(path, g2oText(graph), overwrite);
}

void writeG2oEdges(const std::string& path, const std::vector<backend::Edge>& edges, Overwrite overwrite) {
  writeFileAtomically(path, g2oEdgesText(edges), overwrite);
}

backend::PoseGraph readG2o(const std::string& path) {
  const std::string text = detail::readWholeFile(path);
  std::map<int, Eigen::Isometry3d> vertices;
  std::map<int, size_t> vertex_line;
  std::vector<std::pair<size_t, backend::Edge>> edges;  // with their line numbers, checked once all vertices are in
  size_t pos = 0, line_no = 0;
  while (pos < text.size()) {
    ++line_no;
    const std::vector<std::string_view> tokens = detail::splitBlanks(detail::nextLine(text, pos));
    if (tokens.empty() || tokens[0].front() == '#') continue;
    const LineParser p(path + ":" + std::to_string(line_no), tokens);
    if (tokens[0] == kVertexTag) {
      p.expectCount(1 + kPoseValues);
      const int id = p.id(1);
      if (vertex_line.count(id)) {
        throw Error(p.at() + ": vertex " + std::to_string(id) + " again (first on line " +
                    std::to_string(vertex_line[id]) + ")");
      }
      vertex_line[id] = line_no;
      vertices[id] = p.pose(2);
    } else if (tokens[0] == kEdgeTag) {
      p.expectCount(2 + kPoseValues + kInformationValues);
      backend::Edge e;
      e.from = p.id(1);
      e.to = p.id(2);
      if (e.from == e.to) throw Error(p.at() + ": edge from vertex " + std::to_string(e.from) + " to itself");
      e.T_from_to = p.pose(3);
      e.information = p.information(3 + kPoseValues);
      e.kind = e.to == e.from + 1 ? backend::EdgeKind::kOdometry : backend::EdgeKind::kLoop;
      edges.emplace_back(line_no, e);
    } else if (tokens[0] == kFixTag) {
      for (size_t k = 1; k < tokens.size(); ++k) p.id(k);  // our graphs fix vertex 0 themselves
    } else {
      throw Error(p.at() + ": unknown tag " + quoteContent(tokens[0]) + " (expected " + kVertexTag + ", " +
                  kEdgeTag + " or " + kFixTag + ")");
    }
  }
  backend::PoseGraph graph;
  for (const auto& [id, T] : vertices) {
    if (id != static_cast<int>(graph.poses.size())) {
      throw Error(path + ": vertex ids must be 0.." + std::to_string(vertices.size() - 1) + " (one per frame); " +
                  std::to_string(graph.poses.size()) + " is missing");
    }
    graph.poses.push_back(T);
  }
  for (const auto& [line, e] : edges) {
    const int n = static_cast<int>(graph.poses.size());
    if (n > 0 && (e.from >= n || e.to >= n)) {
      throw Error(path + ":" + std::to_string(line) + ": edge " + std::to_string(e.from) + " -> " +
                  std::to_string(e.to) + " names a vertex that is not in the file (ids 0.." + std::to_string(n - 1) +
                  ")");
    }
    graph.edges.push_back(e);
  }
  return graph;
}

}  // namespace sgtllc::io
