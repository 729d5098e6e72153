/// @file distance_histogram.h
/// @brief The class-pair distance histogram: a retrieval key that one node appearing or vanishing barely moves.
#pragma once

#include <vector>

#include "sgtllc/config.h"
#include "sgtllc/graph.h"

namespace sgtllc::retrieval {

/// Number of unordered class pairs {a, b}, a ≤ b, over @p num_classes classes: C(C + 1)/2 (28 for seven).
int numClassPairs(int num_classes);

/// Index of the unordered class pair {a, b} in 0..numClassPairs − 1: pairs (0,0), (0,1), …, (0,C−1), (1,1), …
int classPairIndex(int a, int b, int num_classes);

/// Length of the histogram key: numClassPairs(C) · @p bins (seven classes, 10 bins: 280 floats, 1,120 bytes).
int distanceHistogramSize(int num_classes, int bins);

/// The key of a frame (RetrievalKey::kDistanceHistogram): for every unordered pair of nodes p < q whose centres are
/// closer than config.histogram_range, the distance d_pq adds one vote to the histogram of the class pair
/// {l_p, l_q}, split linearly between the two bins whose centres enclose it (bins of width w = range / bins,
/// centred at (b + ½)·w; a distance below the first or above the last centre votes for that edge bin alone). The
/// whole vector is then scaled to unit L2 norm (all zero when no pair is in range), so that the squared L2
/// distance of two keys is 2 − 2·cos.
///
/// Why not max-pooling: a cell of Des^G (G2) is the maximum over nodes, so one node entering or leaving the scan
/// changes every cell it held by the full value; here it changes N − 1 of the N(N − 1)/2 votes, a share of 2/N,
/// spread over the bins (BENCHMARKS.md "Retrieval key": recall@15 0.888 → 0.985 on urban7, 0.980 → 0.987 on
/// sub5).
/// Rotation- and translation-invariant, like Des^G; deterministic (fixed summation order). O(N²) over the graph's
/// distance matrix.
std::vector<float> computeDistanceHistogram(const SemanticGraph& graph, const RetrievalConfig& config);

}  // namespace sgtllc::retrieval
