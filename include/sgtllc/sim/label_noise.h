/// @file label_noise.h
/// @brief Segmentation errors like a range-image network's (RangeNet++): labels go wrong per object or object part
///        and along object boundaries, never as independent per-point flips.
///
/// Three effects, all scaled by the rate R (0 = ground truth):
/// 1. Part confusions: all points of one object's class part (a trunk, a pole, a fence, a 5 m ground patch) take a
///    confusable class — trunk→vegetation, pole↔traffic-sign, fence→building, terrain↔vegetation, parking→road, … —
///    or only the part above or below a random height does (the top of a trunk becomes crown, the base of a wall
///    fence). Small and far parts go wrong more often; a whole part lost to its background is a per-class miss.
///    The decision depends on the part and its distance (10 m steps), not on the frame: no flicker from frame to
///    frame, and a revisit from a similar distance sees the same errors, as with a real network.
/// 2. Boundary bleeding: a point next to a differently labelled point in the range image takes that label with a
///    probability, as a network's coarse output blurs across depth edges.
/// 3. The network's label space: moving classes (252–259) become their static class, as in SemanticKITTI's
///    single-scan benchmark.
/// Instance ids stay the true ones where the predicted class is a thing class, else 0.
#pragma once

#include <cstdint>
#include <vector>

#include "sgtllc/sim/raycast.h"

namespace sgtllc::sim {

/// Default --label-noise: close to RangeNet++ on SemanticKITTI (stable-class IoUs roughly 50–90 %).
inline constexpr double kDefaultLabelNoise = 0.1;

/// SemanticKITTI .label words (semantic | instance << 16) with the true labels.
std::vector<uint32_t> trueLabels(const RawScan& scan);

/// .label words as a network would predict them at error rate @p rate (≥ 0; 0 returns trueLabels()). Pure in
/// (scan, rate, seed, scan_index).
std::vector<uint32_t> predictLabels(const RawScan& scan, double rate, uint64_t seed, int64_t scan_index);

}  // namespace sgtllc::sim
