#include "report_plots.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>

#include "sgtllc/plot/figure.h"

namespace sgtllc::eval {
namespace {

std::string format(const char* fmt, double a, double b = 0.0) {
  char buf[128];
  std::snprintf(buf, sizeof(buf), fmt, a, b);
  return buf;
}

void addCurve(plot::Figure& fig, const PrCurve& c, const std::string& label, plot::Color color, double width,
              bool dashed) {
  const PrSteps steps = prSteps(c);
  fig.line(steps.recall, steps.precision, label, color, width, dashed);
}

/// The PR axes: full range, or zoomed on the knee of the curves (prZoom).
plot::Figure prFigure(const std::vector<CurveMetrics>& pairwise, const CurveMetrics* top1, const std::string& title,
                      bool zoom) {
  std::vector<const PrCurve*> curves;
  for (const CurveMetrics& c : pairwise) curves.push_back(&c.curve);
  if (top1) curves.push_back(&top1->curve);
  const PrZoom z = zoom ? prZoom(curves) : PrZoom{};
  plot::Figure fig(zoom ? 620 : 900, 700);
  fig.title(zoom ? format("Zoom: recall %g-1, precision %g-1", z.recall_lo, z.precision_lo) : title);
  fig.xlabel("recall");
  fig.ylabel("precision");
  // A curve at recall or precision 1 stays off the frame.
  fig.xlim(z.recall_lo, 1.0 + 0.02 * (1.0 - z.recall_lo));
  fig.ylim(z.precision_lo, 1.0 + 0.02 * (1.0 - z.precision_lo));
  fig.legendAt("lower left");
  bool any = false;
  for (size_t k = 0; k < pairwise.size(); ++k) {
    const CurveMetrics& c = pairwise[k];
    if (!c.defined()) continue;
    any = true;
    addCurve(fig, c.curve, zoom ? "" : format("pairs, positive < %.0f m (F1max %.3f)", c.positive_distance, c.f1_max),
             plot::seriesColor(static_cast<int>(k)), 2.5, false);
  }
  if (top1 && top1->defined()) {
    any = true;
    addCurve(fig, top1->curve,
             zoom ? "" : format("top-1 per query, < %.0f m (F1max %.3f)", top1->positive_distance, top1->f1_max),
             plot::Color{0.1, 0.1, 0.1}, 2.0, true);
  }
  if (!any) fig.note(zoom ? "no positives" : "no positives in this sequence: F1max, EP and recall are n/a");
  return fig;
}

/// @p x > 0 rounded up to one significant digit (0.16 → 0.2, 0.03 → 0.03), so the zoom's axis ends on a tick.
double ceilOneDigit(double x) {
  const double mag = std::pow(10.0, std::floor(std::log10(x)));
  return std::ceil(x / mag - 1e-9) * mag;
}

}  // namespace

PrSteps prSteps(const PrCurve& c) {
  PrSteps s;
  if (c.recall.empty()) return s;
  // Start at the appended (recall 0, precision 1) point, then the thresholds from the highest.
  s.recall.push_back(c.recall.back());
  s.precision.push_back(c.precision.back());
  for (size_t k = 0; k + 1 < c.recall.size(); ++k) {
    s.recall.push_back(s.recall.back());
    s.precision.push_back(c.precision[k]);
    s.recall.push_back(c.recall[k]);
    s.precision.push_back(c.precision[k]);
  }
  return s;
}

PrZoom prZoom(const std::vector<const PrCurve*>& curves) {
  double gap_recall = 0.0, gap_precision = 0.0;
  bool any = false;
  for (const PrCurve* c : curves) {
    if (!c || c->positives <= 0) continue;
    // The curve's F1max point (f1Max's value; of equal ones the first, at the highest threshold).
    double best = -1.0, r = 0.0, p = 0.0;
    for (size_t k = 0; k < c->recall.size(); ++k) {
      const double sum = c->precision[k] + c->recall[k];
      const double f1 = sum > 0.0 ? 2.0 * c->precision[k] * c->recall[k] / sum : 0.0;
      if (f1 > best) {
        best = f1;
        r = c->recall[k];
        p = c->precision[k];
      }
    }
    any = true;
    gap_recall = std::max(gap_recall, 1.0 - r);
    gap_precision = std::max(gap_precision, 1.0 - p);
  }
  if (!any) return {};
  const auto lower = [](double gap) { return std::max(0.0, 1.0 - std::min(1.0, ceilOneDigit(std::max(0.02, 2.0 * gap)))); };
  return {lower(gap_recall), lower(gap_precision)};
}

void plotPrCurves(const std::string& path, const std::vector<CurveMetrics>& pairwise, const CurveMetrics* top1,
                  const std::string& title) {
  const plot::Figure full = prFigure(pairwise, top1, title, false), zoom = prFigure(pairwise, top1, title, true);
  plot::savePngRow(path, {&full, &zoom});
}

void plotMemory(const std::string& path, const SequenceRun& run) {
  std::vector<double> x, kib;
  for (size_t i = 0; i < run.frames.size(); ++i) {
    x.push_back(static_cast<double>(i));
    kib.push_back(static_cast<double>(run.frames[i].db_bytes) / 1024.0);
  }
  plot::Figure fig(1000, 600);
  fig.title("Database size over the sequence");
  fig.xlabel("frame");
  fig.ylabel("KiB");
  fig.legendAt("upper left");
  fig.line(x, kib, "stored nodes + global descriptors", plot::seriesColor(0), 2.0);
  fig.savePng(path);
}

void plotTrajectory(const std::string& path, const SequenceRun& run, const EvalOptions& options) {
  std::vector<double> x, y, miss_x, miss_y, true_x, true_y;
  std::vector<std::array<double, 4>> good, bad, between;
  std::map<long, size_t> index_of;
  for (size_t i = 0; i < run.frames.size(); ++i) index_of[run.frames[i].frame] = i;
  for (size_t i = 0; i < run.frames.size(); ++i) {
    const FrameRecord& f = run.frames[i];
    const Eigen::Vector3d& p = run.positions[i];
    x.push_back(p.x());
    y.push_back(p.y());
    if (f.is_loop) {
      const CandidateRecord& c = f.candidates[static_cast<size_t>(f.best)];
      const Eigen::Vector3d& q = run.positions[index_of.at(c.frame)];
      const std::array<double, 4> seg = {p.x(), p.y(), q.x(), q.y()};
      if (c.distance < options.positive_distances.at(0)) {
        good.push_back(seg);
        true_x.push_back(p.x());
        true_y.push_back(p.y());
      } else if (c.distance > options.negative_distance) {
        bad.push_back(seg);
      } else {
        between.push_back(seg);
      }
    } else if (f.has_revisit) {
      miss_x.push_back(p.x());
      miss_y.push_back(p.y());
    }
  }
  const auto counted = [](const std::string& label, size_t n) { return label + ": " + std::to_string(n); };
  const std::string pos = format("%.0f", options.positive_distances.at(0)), neg = format("%.0f", options.negative_distance);
  plot::Figure fig(1250, 900);
  fig.title("Trajectory (ground truth) and detected loops");
  fig.xlabel("x (m)");
  fig.ylabel("y (m)");
  fig.equalAspect();
  fig.legendAt("outside right");
  // Drawn in this order: the loops above the path, and the missed revisits above the loops (a true loop's dot
  // covers a metre of path, so the few misses among them would vanish underneath), outlined to stand out.
  fig.line(x, y, "trajectory", plot::Color{0.7, 0.7, 0.7}, 1.5);
  fig.segments(good, "", plot::Color{0.0, 0.55, 0.15}, 2.0);
  fig.points(true_x, true_y, counted("true loop (< " + pos + " m)", true_x.size()), plot::Color{0.0, 0.55, 0.15},
             3.0);
  fig.segments(between, counted("loop " + pos + "-" + neg + " m apart (not scored)", between.size()),
               plot::Color{0.3, 0.4, 0.9}, 2.0);
  fig.segments(bad, counted("false loop (> " + neg + " m)", bad.size()), plot::Color{0.9, 0.0, 0.0}, 2.0);
  fig.points(miss_x, miss_y, "", plot::Color{0.0, 0.0, 0.0}, 6.5);
  fig.points(miss_x, miss_y, counted("revisit missed", miss_x.size()), plot::Color{1.0, 0.55, 0.0}, 4.5);
  if (!x.empty()) fig.points({x.front()}, {y.front()}, "start", plot::Color{0.0, 0.0, 0.0}, 6.0);
  if (x.empty()) fig.note("no frames");
  fig.savePng(path);
}

}  // namespace sgtllc::eval
