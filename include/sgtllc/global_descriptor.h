/// @file global_descriptor.h
/// @brief Max-pooled global descriptor Des^G used for retrieval (algorithm §5).
#pragma once

#include <vector>

#include "sgtllc/config.h"
#include "sgtllc/graph.h"

namespace sgtllc {

/// Length of the global descriptor over C = @p num_classes classes: 2·C² for G1/G3, C³ for G2 (98 and 343 with
/// the paper's seven classes).
int globalDescriptorSize(GlobalMode mode, int num_classes = kNumPaperClasses);

/// Des^G of a frame over the graph's C classes (algorithm §5). Every cell starts at 0 and takes the max over nodes i
/// and their triangles (slots whose path exists with k ≠ i), computed from the triangle itself so that the local
/// descriptor's kind and order never change it:
/// - G1: cell 2C·l_i + C·fuzzy(m) + n, value = a_k (the paper's Des_i[α][2] in its own order);
/// - G2: cell C²·l_i + C·m + n, value = 1 − cos θ_k (θ_k the triangle's interior angle at v_k);
/// - G3: the G1 cells with the G2 value.
/// fuzzy(m) = 0 for building, fence, vegetation (background), 1 otherwise, extra classes included (objects).
/// Degenerate triangles never update.
std::vector<float> computeGlobalDescriptor(const SemanticGraph& graph, const DescriptorConfig& config);

}  // namespace sgtllc
