#include "sgtllc/global_descriptor.h"

#include <algorithm>
#include <cmath>

namespace sgtllc {
namespace {

int fuzzyGroup(int m) { return m <= kVegetation ? 0 : 1; }  // spec §5 [CHOICE]: background first

/// 1 − cos θ_k from the vertex-rooted products, or a negative value for a degenerate triangle.
double oneMinusCosAtK(const Eigen::Vector3d& t) {
  const double ki2 = t[0] + t[2];  // |ik|² = a_i + a_k
  const double kj2 = t[1] + t[2];  // |jk|² = a_j + a_k
  const double denom = std::sqrt(ki2 * kj2);
  if (!(denom > 1e-12)) return -1.0;
  return 1.0 - std::clamp(t[2] / denom, -1.0, 1.0);
}

}  // namespace

int globalDescriptorSize(GlobalMode mode) {
  return mode == GlobalMode::kG2 ? kNumClasses * kNumSlots : kNumClasses * 2 * kNumClasses;
}

std::vector<float> computeGlobalDescriptor(const SemanticGraph& graph, const std::vector<LocalDescriptor>& local,
                                           const DescriptorConfig& config) {
  std::vector<float> des(globalDescriptorSize(config.global_mode), 0.0f);
  for (int i = 0; i < graph.size(); ++i) {
    const int o = graph.nodes[i].label;
    for (int a = 0; a < kNumSlots; ++a) {
      if (!local[i].isValid(a)) continue;
      const int m = a / kNumClasses;
      const int n = a % kNumClasses;
      double value = 0.0;
      int cell = 0;
      switch (config.global_mode) {
        case GlobalMode::kG1:
          value = slotTerms(local[i].slots[a], config.order)[2];  // a_k, the paper's Des[α][2]
          cell = 2 * kNumClasses * o + kNumClasses * fuzzyGroup(m) + n;
          break;
        case GlobalMode::kG2:
          value = oneMinusCosAtK(slotTerms(local[i].slots[a], config.order));
          cell = kNumSlots * o + a;
          break;
        case GlobalMode::kG3:
          value = oneMinusCosAtK(slotTerms(local[i].slots[a], config.order));
          cell = 2 * kNumClasses * o + kNumClasses * fuzzyGroup(m) + n;
          break;
      }
      des[cell] = std::max(des[cell], static_cast<float>(value));
    }
  }
  return des;
}

}  // namespace sgtllc
