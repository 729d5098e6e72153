/// @file detector.h
/// @brief The online loop detector (one frame at a time) and the pairwise comparison of two frames.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "sgtllc/config.h"
#include "sgtllc/database.h"
#include "sgtllc/footprint.h"
#include "sgtllc/frame.h"
#include "sgtllc/node_extraction.h"
#include "sgtllc/registration/cloud_store.h"
#include "sgtllc/verification.h"

namespace sgtllc {
namespace internal {
class DescribedCache;
}  // namespace internal

/// Wall-clock time per stage of one frame or pair (milliseconds, steady clock).
struct StageTimes {
  double extraction_ms = 0.0;    ///< class split, voxel downsampling, clustering, centres (0 when nodes are given)
  double description_ms = 0.0;   ///< graph, local and global descriptors
  double retrieval_ms = 0.0;     ///< K-nearest-neighbour search over global descriptors
  double verification_ms = 0.0;  ///< candidate descriptors, association, RANSAC and pose
  /// Fine registration: the frame's compact cloud and the ICP of its loop (0 unless registration.online; for a
  /// pair, the ICP of comparePair when registration.pair)
  double refinement_ms = 0.0;
  double total_ms() const { return extraction_ms + description_ms + retrieval_ms + verification_ms + refinement_ms; }
};

/// One retrieved candidate frame and its verification.
struct Candidate {
  int frame = -1;           ///< database index of the candidate
  float distance2 = 0.0f;   ///< squared L2 distance of the global descriptors
  /// false: not returned by retrieval but a database neighbour of the top-1 (verification.neighbour_frames);
  /// the retrieval and pairwise protocols count only the retrieved candidates.
  bool retrieved = true;
  MatchResult match;        ///< association, scores and pose (query → candidate)
  /// ICP of the declared loop (registration.online, points input only); when used(), match.T_match_query is the
  /// refined pose and the seed is kept here.
  std::optional<Refinement> refinement;
};

/// Whether a frame's query searched the database, or why not (algorithm §5).
enum class Search {
  kSearched,   ///< frames at least retrieval.exclude_recent older existed and were searched
  kTooRecent,  ///< no stored frame is retrieval.exclude_recent or more frames older: frame < exclude_recent
  kWarmup,     ///< frame < retrieval.warmup_frames: no query during the warm-up
};

/// What the detector found for one frame.
struct FrameResult {
  int frame = -1;                     ///< index given to this frame (0, 1, 2, … in processing order)
  int num_nodes = 0;                  ///< nodes of this frame
  ExtractionStats extraction;         ///< point bookkeeping (zeros when nodes were given)
  Search search = Search::kSearched;  ///< whether the database was searched; candidates is empty unless kSearched
  /// The retrieved candidates, and the top-1's database neighbours that the neighbour check added
  /// (Candidate::retrieved false), in ascending frame index, each verified.
  std::vector<Candidate> candidates;
  int best = -1;                      ///< index into candidates of the chosen one (selectCandidate), or −1
  bool is_loop = false;               ///< candidates[best].match.score > σ_4
  bool lateral = false;               ///< candidates[best] is estimated ≥ verification.lateral_distance away
  StageTimes timing;

  /// The loop closure, or nullptr.
  const Candidate* loop() const { return is_loop ? &candidates[best] : nullptr; }
};

/// Online SGT-LLC: every processed frame is described, queried against the frames at least
/// `retrieval.exclude_recent` older, verified and then stored. Not thread-safe; uses `config.threads` internally.
class LoopDetector {
 public:
  /// Throws sgtllc::Error if the configuration is invalid.
  explicit LoopDetector(const Config& config = {});
  ~LoopDetector();
  LoopDetector(LoopDetector&&) noexcept;
  LoopDetector& operator=(LoopDetector&&) noexcept;
  /// Resumes a detector over the frames of @p database (e.g. a loaded map, map/map.h): the next frame is numbered
  /// database.size(), and searching proceeds exactly as if those frames had been processed by this detector. The
  /// resumed frames have no registration clouds, so with registration.online their loops keep the SVD pose. Their
  /// @p footprints (one per frame, empty where none, or none at all: map/map.h) keep the footprint check. Throws
  /// sgtllc::Error if the database's key length differs from the configuration's (retrievalKeySize), or the
  /// footprints are neither none nor one per frame.
  LoopDetector(const Config& config, FrameDatabase database, std::vector<Footprint> footprints = {});

  /// Processes a labelled scan (points in the sensor frame). Throws sgtllc::Error if the points and labels
  /// differ in length.
  FrameResult process(const LabeledCloud& cloud);
  /// Processes a frame given as ready-made nodes (centre + stable class), e.g. from an instance segmentation.
  /// Throws sgtllc::Error for more than graph.max_nodes nodes, a label outside 0..C−1 or a non-finite centre; the
  /// frame is then not stored.
  FrameResult process(std::vector<Node> nodes);
  /// The same with the frame's registration clouds (clouds().prepare of its scan) and footprint (footprint() of
  /// its scan), for callers that extract nodes themselves, e.g. in parallel: the frame is verified and its loop
  /// refined as by process(cloud).
  FrameResult process(std::vector<Node> nodes, RegistrationClouds clouds, Footprint footprint = {});

  /// The footprint process(cloud) makes of a labelled scan (footprint.h); empty with the check off. A pure
  /// function of the scan (safe in parallel).
  Footprint footprint(const LabeledCloud& cloud) const;

  /// Index of the first frame whose query searches the database: max(retrieval.exclude_recent,
  /// retrieval.warmup_frames). A sequence of at most this many frames gets no candidate at all, so it cannot have a
  /// loop; every earlier frame's FrameResult::search says why.
  int firstSearchedFrame() const;

  int numFrames() const { return database_.size(); }
  const FrameDatabase& database() const { return database_; }
  const Config& config() const { return config_; }
  const NodeExtractor& extractor() const { return extractor_; }
  /// Compact clouds of the stored frames (registration.online; empty otherwise).
  const CloudStore& clouds() const { return clouds_; }
  /// Footprints of the stored frames (empty ones for node input and resumed frames), in frame order.
  const std::vector<Footprint>& footprints() const { return footprints_; }
  /// Bytes the stored footprints hold.
  size_t footprintBytes() const { return footprint_bytes_; }

 private:
  FrameResult processNodes(std::vector<Node> nodes, Footprint footprint, FrameResult result);

  Config config_;
  NodeExtractor extractor_;
  std::vector<Footprint> footprints_;
  size_t footprint_bytes_ = 0;
  FrameDatabase database_;
  CloudStore clouds_;
  /// Descriptions of recently verified frames (src/internal/described_cache.h); never changes a result.
  std::unique_ptr<internal::DescribedCache> described_;
};

/// Retrieval, verification and top-1 choice of one query frame (algorithm §5–§7.4) against the frames 0..@p last of
/// @p database: fills result->candidates (ascending frame index), best, lateral, is_loop and the retrieval and
/// verification times; nothing is stored. @p query is describeFrame of the query without its global descriptor
/// and @p key its retrieval key (computeRetrievalKey). The online detector and the relocalizer (map/relocalizer.h)
/// both search through it. Uses config.threads; the result does not depend on it. @p footprints: the stored
/// frames' footprints (one per database frame, empty where a frame has none) for the footprint check and the
/// consistency path (algorithm §7.7, §7.8), with query.footprint; nullptr = none.
void searchDatabase(const DescribedFrame& query, const std::vector<float>& key, const FrameDatabase& database,
                    int last, const Config& config, FrameResult* result,
                    const std::vector<Footprint>* footprints = nullptr);

/// Result of comparing two frames directly.
struct PairResult {
  MatchResult match;             ///< query → match
  bool is_loop = false;          ///< isLoop(match, σ_4)
  std::vector<Node> query_nodes;  ///< the nodes that NodeMatch::query indexes
  std::vector<Node> match_nodes;  ///< the nodes that NodeMatch::match indexes
  ExtractionStats extraction_query;
  ExtractionStats extraction_match;
  StageTimes timing;             ///< both frames' extraction and description; verification of the pair
  /// ICP of the pose (registration.pair, scans given, a pose found); when used(), match.T_match_query is the
  /// refined pose and the object-level SVD pose is refinement->T_match_query_seed.
  std::optional<Refinement> refinement;
};

/// Compares two labelled scans: is @p query a revisit of @p match, and where is it in @p match's frame?
PairResult comparePair(const LabeledCloud& query, const LabeledCloud& match, const Config& config = {});
/// The same for ready-made node sets (no points: no refinement), with the scans' footprints (computeFootprint)
/// where the caller has them: the footprint check runs only when both are given.
PairResult comparePair(std::vector<Node> query, std::vector<Node> match, const Config& config = {},
                       Footprint query_footprint = {}, Footprint match_footprint = {});

/// Refines @p result's pose by ICP of @p query_points onto @p match_points (registrationPoints of the two scans)
/// if registration.pair is on and verification found a pose; sets PairResult::refinement and, when it is used,
/// match.T_match_query. comparePair of two scans calls it; a caller that extracts nodes itself calls it after.
void refinePair(PairResult* result, const std::vector<Eigen::Vector3f>& query_points,
                const std::vector<Eigen::Vector3f>& match_points, const Config& config);

}  // namespace sgtllc
