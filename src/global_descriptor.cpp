#include "sgtllc/global_descriptor.h"

#include <algorithm>
#include <cmath>

#include "sgtllc/descriptor.h"

namespace sgtllc {
namespace {

int fuzzyGroup(int m) { return m <= kVegetation ? 0 : 1; }  // algorithm §5 [CHOICE]: background first

/// 1 − cos θ_k from the vertex-rooted products, or a negative value for a degenerate triangle.
double oneMinusCosAtK(const Eigen::Vector3d& t) {
  const double ki2 = t[0] + t[2];  // |ik|² = a_i + a_k
  const double kj2 = t[1] + t[2];  // |jk|² = a_j + a_k
  const double denom = std::sqrt(ki2 * kj2);
  if (!(denom > 1e-12)) return -1.0;
  return 1.0 - std::clamp(t[2] / denom, -1.0, 1.0);
}

}  // namespace

int globalDescriptorSize(GlobalMode mode, int num_classes) {
  const int c = num_classes;
  return mode == GlobalMode::kG2 ? c * c * c : c * 2 * c;
}

std::vector<float> computeGlobalDescriptor(const SemanticGraph& graph, const DescriptorConfig& config) {
  const int num_classes = graph.num_classes;
  const int num_slots = graph.numSlots();
  std::vector<float> des(globalDescriptorSize(config.global_mode, num_classes), 0.0f);
  for (int i = 0; i < graph.size(); ++i) {
    const int o = graph.nodes[i].label;
    const SlotRow<const TwoStepPath> paths = graph.paths[i];
    for (int m = 0, a = 0; m < num_classes; ++m) {
      const int fuzzy_row = 2 * num_classes * o + num_classes * fuzzyGroup(m);
      for (int n = 0; n < num_classes; ++n, ++a) {  // a = C·m + n
        const TwoStepPath& path = paths[a];
        if (!path.exists() || path.k == i) continue;  // the slots a local descriptor holds (descriptor.cpp)
        const Eigen::Vector3d t =
            triangleTerms(graph.nodes[i].centre, graph.nodes[path.j].centre, graph.nodes[path.k].centre);
        double value = 0.0;
        int cell = 0;
        switch (config.global_mode) {
          case GlobalMode::kG1:
            value = t[2];  // a_k
            cell = fuzzy_row + n;
            break;
          case GlobalMode::kG2:
            value = oneMinusCosAtK(t);
            cell = num_slots * o + a;
            break;
          case GlobalMode::kG3:
            value = oneMinusCosAtK(t);
            cell = fuzzy_row + n;
            break;
        }
        des[cell] = std::max(des[cell], static_cast<float>(value));
      }
    }
  }
  return des;
}

}  // namespace sgtllc
