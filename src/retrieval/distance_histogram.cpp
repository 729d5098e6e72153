#include "sgtllc/retrieval/distance_histogram.h"

#include <cmath>
#include <utility>

namespace sgtllc::retrieval {

int numClassPairs(int num_classes) { return num_classes * (num_classes + 1) / 2; }

int classPairIndex(int a, int b, int num_classes) {
  if (a > b) std::swap(a, b);
  // Rows a = 0 … a − 1 hold C, C − 1, … pairs: a·C − a(a − 1)/2 of them before row a.
  return a * num_classes - a * (a - 1) / 2 + (b - a);
}

int distanceHistogramSize(int num_classes, int bins) { return numClassPairs(num_classes) * bins; }

std::vector<float> computeDistanceHistogram(const SemanticGraph& graph, const RetrievalConfig& config) {
  const int num_classes = graph.num_classes;
  const int bins = config.histogram_bins;
  const double range = config.histogram_range;
  std::vector<double> votes(static_cast<size_t>(distanceHistogramSize(num_classes, bins)), 0.0);
  const int n = graph.size();
  for (int p = 0; p < n; ++p) {
    for (int q = p + 1; q < n; ++q) {
      const double d = graph.distance(p, q);
      if (!(d < range)) continue;
      double* row = votes.data() + static_cast<size_t>(classPairIndex(graph.nodes[p].label, graph.nodes[q].label,
                                                                      num_classes)) * bins;
      const double x = d / range * bins - 0.5;  // position in units of bins, 0 at the first bin's centre
      if (x <= 0.0) {
        row[0] += 1.0;
      } else if (x >= bins - 1) {
        row[bins - 1] += 1.0;
      } else {
        const int b = static_cast<int>(x);
        const double w = x - b;
        row[b] += 1.0 - w;
        row[b + 1] += w;
      }
    }
  }
  double norm2 = 0.0;
  for (double v : votes) norm2 += v * v;
  const double scale = norm2 > 0.0 ? 1.0 / std::sqrt(norm2) : 0.0;
  std::vector<float> key(votes.size());
  for (size_t i = 0; i < votes.size(); ++i) key[i] = static_cast<float>(votes[i] * scale);
  return key;
}

}  // namespace sgtllc::retrieval
