/// @file relocalization_tracker.h
/// @brief Relocalizing a stream: a weaker verified answer is accepted when it agrees with the last accepted one
///        (docs/relocalization.md, "Tracking a stream").
#pragma once

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "sgtllc/map/relocalizer.h"

namespace sgtllc::map {

/// When a weaker answer may be accepted. The defaults were chosen on the tuning world of docs/relocalization.md.
struct TrackingOptions {
  /// A verified candidate scoring score > this (but not above verification.sigma_4) is accepted when its estimated
  /// position agrees with the track [0, 1].
  double weak_sigma = 0.2;
  /// Agreement: the candidate's estimated position lies within gate_m + max_speed_m_per_frame · (frames since the
  /// last accepted answer) of that answer's estimated position (m) (0, 1000].
  double gate_m = 3.0;
  double max_speed_m_per_frame = 2.0;  ///< (m per query frame) [0, 1000]; 2 m at 10 Hz is 72 km/h
  /// The track is lost after this many query frames without an accepted answer; then only σ_4 accepts [1, 1000000].
  int window = 10;

  /// Throws sgtllc::Error naming the first field out of range.
  void validate() const;
};

/// Relocalizes consecutive frames of one sequence, in order, in a Relocalizer's map that has poses. A frame whose best
/// candidate passes σ_4 is answered as Relocalizer::localize answers it. Otherwise, while the track is held, the
/// best-scoring verified candidate above TrackingOptions::weak_sigma whose estimated position agrees with the last
/// accepted answer is accepted (Relocalization::tracked): a place seen again with more change (parked cars moved,
/// trees cut) scores lower, but two consecutive frames of a vehicle cannot be far apart, and a false match that
/// scores above weak_sigma almost never lands next to the previous answer. Without map poses nothing is tracked.
class RelocalizationTracker {
 public:
  /// Keeps a reference to @p relocalizer (which must outlive the tracker); throws sgtllc::Error for bad options.
  explicit RelocalizationTracker(const Relocalizer& relocalizer, TrackingOptions options = {});

  /// The next frame of the stream (with its scan's footprint where the caller has one: Relocalizer::localize).
  Relocalization localize(std::vector<Node> nodes, Footprint footprint = {});
  /// The same for an answer already computed by the relocalizer for the next frame.
  Relocalization track(Relocalization answer);

  /// Forgets the track (e.g. after a jump in the stream).
  void reset();

 private:
  const Relocalizer& relocalizer_;
  TrackingOptions options_;
  std::optional<Eigen::Vector3d> last_;  ///< the last accepted answer's estimated position in the map's world frame
  int since_last_ = 0;                   ///< query frames since it
};

}  // namespace sgtllc::map
