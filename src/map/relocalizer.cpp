#include "sgtllc/map/relocalizer.h"

#include <chrono>
#include <cmath>
#include <string>
#include <utility>

#include <Eigen/LU>
#include <Eigen/SVD>

#include "sgtllc/frame.h"
#include "sgtllc/point_kdtree.h"
#include "sgtllc/retrieval/retrieval_key.h"
#include "sgtllc/types.h"

namespace sgtllc::map {
namespace {

const Config& validated(const Config& config) {
  config.validate();
  return config;
}

/// The configuration the relocalizer searches with: the detector's, with the relocalizer's own shortlist size.
Config withCandidates(const Config& config, int num_candidates) {
  if (num_candidates < 0 || num_candidates > 1000) {
    throw Error("relocalizer: num_candidates = " + std::to_string(num_candidates) + " is out of range [0, 1000]");
  }
  Config c = config;
  if (num_candidates > 0) c.retrieval.num_candidates = num_candidates;
  return c;
}

constexpr double kPi = 3.14159265358979323846;

/// The second singular value an answer's centred inlier centres need (RelocalizerOptions).
double inlierSpreadNeeded(const Config& config, const RelocalizerOptions& options) {
  const double deg = options.max_rotation_uncertainty_deg;
  if (!(deg >= 0.0 && deg < 90.0)) {
    throw Error("relocalizer: max_rotation_uncertainty_deg = " + std::to_string(deg) + " is out of range [0, 90)");
  }
  if (deg == 0.0) return 0.0;
  return config.verification.inlier_threshold / std::tan(deg * kPi / 180.0);
}

}  // namespace

Relocalizer::Relocalizer(Map map, const Config& config, const std::string& source, RelocalizerOptions options)
    : map_(std::move(map)),
      config_(withCandidates(validated(config), options.num_candidates)),
      min_inlier_spread_(inlierSpreadNeeded(config_, options)),
      extractor_(config.cluster, effectiveLabelConfig(config), config.graph.max_nodes, config.threads) {
  checkCompatible(map_, config_, source);
  if (map_.hasPoses()) positions_ = std::make_shared<const PositionIndex>(map_.poses);
  map_.database.setSearch(config_.retrieval, config_.threads);
}

Relocalization Relocalizer::localize(const LabeledCloud& cloud) const {
  const auto start = std::chrono::steady_clock::now();
  Footprint footprint;
  NodeExtractionResult extracted = extractor_.extract(cloud, config_.verification, &footprint);
  const double extraction_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  Relocalization r = localize(std::move(extracted.nodes), std::move(footprint));
  r.search.extraction = extracted.stats;
  r.search.timing.extraction_ms = extraction_ms;
  return r;
}

struct Relocalizer::PositionIndex {
  explicit PositionIndex(const std::vector<Eigen::Matrix4d>& poses) : xyz(positionsOf(poses)), tree(&xyz) {}
  static std::vector<float> positionsOf(const std::vector<Eigen::Matrix4d>& poses) {
    std::vector<float> out;
    out.reserve(poses.size() * 3);
    for (const Eigen::Matrix4d& T : poses) {
      for (int k = 0; k < 3; ++k) out.push_back(static_cast<float>(T(k, 3)));
    }
    return out;
  }
  std::vector<float> xyz;  ///< before tree: the tree is built over it
  PointKdTree tree;
};

int Relocalizer::nearestMapFrame(const Eigen::Vector3d& at) const {
  // The tree ranks in float; the few nearest are ranked again in double with ties to the lower frame, so the
  // answer is the exact scan's.
  const float query[3] = {static_cast<float>(at.x()), static_cast<float>(at.y()), static_cast<float>(at.z())};
  std::vector<uint32_t> near;
  positions_->tree.knn(query, 8, &near);
  int nearest = -1;
  double nearest_d2 = 0.0;
  for (uint32_t f : near) {
    const double d2 = (map_.poses[f].topRightCorner<3, 1>() - at).squaredNorm();
    const int frame = static_cast<int>(f);
    if (nearest < 0 || d2 < nearest_d2 || (d2 == nearest_d2 && frame < nearest)) nearest = frame, nearest_d2 = d2;
  }
  return nearest;
}

Relocalization Relocalizer::localize(std::vector<Node> nodes, Footprint footprint) const {
  FrameResult search;
  const auto start = std::chrono::steady_clock::now();
  // The query is described exactly as the detector describes a frame (LoopDetector::processNodes).
  DescribedFrame query = describeFrame(std::move(nodes), config_.graph, config_.descriptor,
                                        /*with_global=*/false, config_.numClasses());
  query.footprint = std::move(footprint);
  const std::vector<float> key = retrieval::computeRetrievalKey(query.graph, config_);
  search.num_nodes = query.numNodes();
  search.timing.description_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  searchDatabase(query, key, map_.database, map_.size() - 1, config_, &search,
                 map_.footprints.empty() ? nullptr : &map_.footprints);
  const int best = search.best;
  return answerWith(std::move(search), best);
}

Relocalization Relocalizer::answerWith(FrameResult search, int candidate) const {
  Relocalization r;
  r.search = std::move(search);
  if (candidate < 0) return r;
  if (static_cast<size_t>(candidate) >= r.search.candidates.size()) {
    throw Error("relocalizer: candidate " + std::to_string(candidate) + " of " +
                std::to_string(r.search.candidates.size()));
  }
  const Candidate& chosen = r.search.candidates[static_cast<size_t>(candidate)];
  r.map_frame = chosen.frame;
  r.weak_rotation = !rotationSupported(chosen);
  r.localized = r.search.is_loop && !r.weak_rotation;
  r.score = chosen.match.score;
  r.T_mapframe_query = chosen.match.T_match_query;
  if (!map_.hasPoses()) return r;
  r.T_world_query = map_.poses[static_cast<size_t>(chosen.frame)] * r.T_mapframe_query;
  // The verified frame may be a neighbour of the place along the old pass or across the street (the top-1 choice
  // is among near-equal scores); with poses, the answer is the map frame nearest to where the query is estimated
  // to be, ties to the lower frame.
  const int nearest = nearestMapFrame(r.T_world_query->topRightCorner<3, 1>());
  r.map_frame = nearest;
  r.T_mapframe_query = map_.poses[static_cast<size_t>(nearest)].inverse() * *r.T_world_query;
  return r;
}

bool Relocalizer::rotationSupported(const Candidate& c) const {
  if (min_inlier_spread_ <= 0.0) return true;
  const std::vector<Node>& nodes = map_.database.nodes(c.frame);
  Eigen::MatrixXd centres(static_cast<Eigen::Index>(c.match.inliers.size()), 3);
  Eigen::Index row = 0;
  for (int k : c.match.inliers) {
    const int node = k >= 0 && static_cast<size_t>(k) < c.match.associations.size()
                         ? c.match.associations[static_cast<size_t>(k)].match
                         : -1;
    if (node < 0 || static_cast<size_t>(node) >= nodes.size()) {
      throw Error("relocalizer: candidate " + std::to_string(c.frame) + "'s inlier " + std::to_string(k) +
                  " names no node of the map frame");
    }
    centres.row(row++) = nodes[static_cast<size_t>(node)].centre.transpose();
  }
  if (centres.rows() < 3) return false;
  centres.rowwise() -= centres.colwise().mean();
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(centres);
  return svd.singularValues()(1) >= min_inlier_spread_;
}

}  // namespace sgtllc::map
