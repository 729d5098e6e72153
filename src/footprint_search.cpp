#include "sgtllc/footprint_search.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "internal/footprint_cells.h"

namespace sgtllc {
namespace {

/// Cells of the query's footprint the coarse pass judges each shift on (bestFootprintShift).
constexpr size_t kCoarseCells = 256;

/// The match cells (column, row of the grid) that the query's occupied cells, their centres at the sensor's height,
/// land in under the pose: those that footprintOverlap compares under it (well inside the match grid). A shift by
/// whole cells moves them by whole cells, so each shift costs one look-up per cell. Every shift is judged on this one
/// set: were the cells that a shift pushes out of reach dropped instead, a shift ahead would gain by dropping the
/// far cells the match's sensor saw least of.
std::vector<Eigen::Vector2i> landingCells(const Footprint& query, const Eigen::Matrix4d& T_match_query) {
  std::vector<Eigen::Vector2i> out;
  internal::forEachLandingCell(query, T_match_query, [&](int i, int j) { out.emplace_back(i, j); });
  return out;
}

/// The share of @p cells, moved by (@p a, @p b) cells, that land on an occupied cell of the dilated match grid; −1
/// as soon as fewer than @p needed of them can (a shift that cannot beat the best so far).
FootprintShift shareAt(const std::vector<Eigen::Vector2i>& cells, const Footprint& dilated, int a, int b,
                       int needed = 0) {
  FootprintShift s;
  s.shift = Eigen::Vector2d(a * static_cast<double>(dilated.cell), b * static_cast<double>(dilated.cell));
  s.compared = static_cast<int>(cells.size());
  // Footprint::occupied, inlined: this loop is the search's whole cost.
  const unsigned side = 2u * static_cast<unsigned>(dilated.half);
  const uint64_t* bits = dilated.bits.data();
  int hits = 0, left = s.compared;
  for (const Eigen::Vector2i& c : cells) {
    const unsigned i = static_cast<unsigned>(c.x() + a), j = static_cast<unsigned>(c.y() + b);  // < 0 wraps high
    --left;
    if (i < side && j < side) {
      const size_t k = static_cast<size_t>(i) * side + j;
      hits += static_cast<int>((bits[k >> 6] >> (k & 63u)) & 1u);
    }
    // Most shifts of a search are far off: checked every 64 cells, the bound ends them early.
    if ((left & 63) == 0 && hits + left < needed) {
      s.share = -1.0;
      return s;
    }
  }
  s.share = s.compared > 0 ? static_cast<double>(hits) / s.compared : 0.0;
  return s;
}

/// Whether shift @p a (with @p around_a, the sum of its neighbours' shares; 0 in the coarse pass) beats @p b: a
/// higher share, then a higher sum around it, then the shorter shift, then the lower x, then the lower y.
bool better(const FootprintShift& a, double around_a, const FootprintShift& b, double around_b) {
  if (a.share != b.share) return a.share > b.share;
  if (around_a != around_b) return around_a > around_b;
  const double na = a.shift.squaredNorm(), nb = b.shift.squaredNorm();
  if (na != nb) return na < nb;
  if (a.shift.x() != b.shift.x()) return a.shift.x() < b.shift.x();
  return a.shift.y() < b.shift.y();
}

}  // namespace

FootprintShift bestFootprintShift(const Footprint& query, const Footprint& match, const Eigen::Matrix4d& T_match_query,
                                  double radius, int min_compared, double min_gain) {
  if (query.empty() || match.empty() || query.dilated || query.half != match.half || query.cell != match.cell ||
      !T_match_query.allFinite()) {
    return FootprintShift{};
  }
  const std::vector<Eigen::Vector2i> cells = landingCells(query, T_match_query);
  if (cells.empty() || static_cast<int>(cells.size()) < min_compared) return FootprintShift{};
  Footprint own;  // a stored frame's footprint is dilated already (footprint.h)
  const Footprint& dilated = match.dilated ? match : (own = dilateFootprint(match));
  const double unshifted = shareAt(cells, dilated, 0, 0).share;
  const double cell = query.cell;
  const int reach = static_cast<int>(std::floor(radius / cell));
  const auto at = [&](int a, int b) { return shareAt(cells, dilated, a, b); };
  // The coarse pass finds the peak on an even sample of at most kCoarseCells cells (a share to within about 0.02,
  // where a pose metres off gains 0.06 to 0.2); the fine pass judges its neighbourhood on every cell. A 64-beam
  // scan's footprint has thousands of cells, and the search runs on every loop an online run declares.
  std::vector<Eigen::Vector2i> sample;
  const size_t step = (cells.size() + kCoarseCells - 1) / kCoarseCells;
  for (size_t k = 0; k < cells.size(); k += step) sample.push_back(cells[k]);
  FootprintShift best = shareAt(sample, dilated, 0, 0);
  const double unshifted_sample = best.share;
  // The hits a coarse shift needs to tie the best so far: one that cannot is abandoned part way.
  const auto hitsOf = [&](const FootprintShift& s) { return static_cast<int>(std::lround(s.share * s.compared)); };
  // Every third shift from the pose outwards: with a cell of slack, a shift one cell off the right one agrees as well
  // as it does, so every shift is within one cell of a coarse one that sees its peak.
  const int coarse = reach / 3 * 3;
  for (int a = -coarse; a <= coarse; a += 3) {
    for (int b = -coarse; b <= coarse; b += 3) {
      const FootprintShift s = shareAt(sample, dilated, a, b, hitsOf(best));
      if (better(s, 0.0, best, 0.0)) best = s;
    }
  }
  // Where no shift gains half of min_gain on the sample, none is looked at further: most verified poses are right.
  if (!(best.share >= unshifted_sample + 0.5 * min_gain)) {
    FootprintShift none;
    none.compared = static_cast<int>(cells.size());
    none.share = none.unshifted_share = unshifted;
    return none;
  }
  // The fine pass: the shifts next to the coarse best, each judged with the sum of its own neighbours' shares.
  const int ca = static_cast<int>(std::lround(best.shift.x() / cell));
  const int cb = static_cast<int>(std::lround(best.shift.y() / cell));
  double shares[5][5];
  for (int a = 0; a < 5; ++a) {
    for (int b = 0; b < 5; ++b) {
      const int sa = ca + a - 2, sb = cb + b - 2;
      shares[a][b] = std::abs(sa) <= reach && std::abs(sb) <= reach ? at(sa, sb).share : 0.0;
    }
  }
  double best_around = -1.0;
  FootprintShift fine;
  for (int a = 1; a <= 3; ++a) {
    for (int b = 1; b <= 3; ++b) {
      const int sa = ca + a - 2, sb = cb + b - 2;
      if (std::abs(sa) > reach || std::abs(sb) > reach) continue;
      double around = 0.0;
      for (int da = -1; da <= 1; ++da) {
        for (int db = -1; db <= 1; ++db) around += (da || db) ? shares[a + da][b + db] : 0.0;
      }
      FootprintShift s;
      s.shift = Eigen::Vector2d(sa * cell, sb * cell);
      s.compared = static_cast<int>(cells.size());
      s.share = shares[a][b];
      if (best_around < 0.0 || better(s, around, fine, best_around)) {
        fine = s;
        best_around = around;
      }
    }
  }
  best = fine;
  best.unshifted_share = unshifted;
  return best;
}

}  // namespace sgtllc
