#include "sgtllc/footprint.h"

#include <algorithm>
#include <cmath>

#include "internal/footprint_cells.h"

namespace sgtllc {

size_t Footprint::words(int half) {
  const size_t side = 2 * static_cast<size_t>(std::max(half, 0));
  return (side * side + 63) / 64;
}

bool Footprint::occupied(int i, int j) const {
  const int side = 2 * half;
  if (i < 0 || j < 0 || i >= side || j >= side) return false;
  const size_t k = static_cast<size_t>(i) * static_cast<size_t>(side) + static_cast<size_t>(j);
  return (bits[k >> 6] >> (k & 63u)) & 1u;
}

FootprintMarker::FootprintMarker(const VerificationConfig& config) {
  if (config.min_footprint_overlap <= 0.0) return;
  enabled_ = true;
  cell_ = static_cast<float>(config.footprint_cell);
  half_ = static_cast<int>(std::ceil(config.footprint_radius / config.footprint_cell));
  r2_ = static_cast<float>(config.footprint_radius * config.footprint_radius);
}

Footprint FootprintMarker::grid() const {
  Footprint f;
  if (!enabled_) return f;
  f.cell = cell_;
  f.half = half_;
  f.bits.assign(Footprint::words(half_), 0);
  return f;
}

void finishFootprint(const std::vector<Eigen::Vector3f>& points, const VerificationConfig& config, Footprint* f) {
  // Off, the check costs nothing: a second pass over the points is about a tenth of a frame's time online.
  if (!f->empty() && config.max_seen_through < 1.0) f->sight = computeSight(points);
}

Footprint computeFootprint(const LabeledCloud& cloud, const LabelMap& labels, const VerificationConfig& config) {
  const FootprintMarker marker(config);
  Footprint f = marker.grid();
  if (f.empty()) return f;
  const size_t n = std::min(cloud.points.size(), cloud.labels.size());
  for (size_t p = 0; p < n; ++p) marker.mark(cloud.points[p], labels.classOf(cloud.labels[p]), f.bits);
  finishFootprint(cloud.points, config, &f);
  return f;
}

Footprint dilateFootprint(const Footprint& f) {
  if (f.empty() || f.dilated) return f;
  Footprint out = f;
  out.dilated = true;
  const int side = 2 * f.half;
  for (size_t w = 0; w < f.bits.size(); ++w) {
    for (uint64_t word = f.bits[w]; word != 0; word &= word - 1) {
      const size_t k = w * 64 + static_cast<size_t>(__builtin_ctzll(word));
      const int i = static_cast<int>(k / static_cast<size_t>(side)), j = static_cast<int>(k % static_cast<size_t>(side));
      for (int a = std::max(0, i - 1); a <= std::min(side - 1, i + 1); ++a) {
        for (int b = std::max(0, j - 1); b <= std::min(side - 1, j + 1); ++b) {
          const size_t n = static_cast<size_t>(a) * static_cast<size_t>(side) + static_cast<size_t>(b);
          out.bits[n >> 6] |= uint64_t{1} << (n & 63u);
        }
      }
    }
  }
  return out;
}

FootprintOverlap footprintOverlap(const Footprint& query, const Footprint& match, const Eigen::Matrix4d& T_match_query) {
  FootprintOverlap o;
  if (query.empty() || match.empty() || query.dilated || query.half != match.half || query.cell != match.cell) return o;
  int hits = 0;
  internal::forEachLandingCell(query, T_match_query, [&](int mi, int mj) {
    ++o.compared;
    bool hit = match.dilated && match.occupied(mi, mj);
    for (int di = -1; di <= 1 && !hit && !match.dilated; ++di) {
      for (int dj = -1; dj <= 1 && !hit; ++dj) hit = match.occupied(mi + di, mj + dj);
    }
    hits += hit ? 1 : 0;
  });
  o.share = o.compared > 0 ? static_cast<double>(hits) / o.compared : 0.0;
  o.seen = seenThrough(query.sight, match.sight, T_match_query);
  return o;
}

}  // namespace sgtllc
