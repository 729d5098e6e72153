#include "report_plots.h"

#include <array>
#include <cstdio>
#include <map>

#include "figure.h"

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

/// The PR axes: full range, or zoomed on precision 0.9–1 where the curves of a good detector differ.
plot::Figure prFigure(const std::vector<CurveMetrics>& pairwise, const CurveMetrics* top1, const std::string& title,
                      bool zoom) {
  plot::Figure fig(zoom ? 620 : 900, 700);
  fig.title(zoom ? "Zoom: precision 0.9-1" : title);
  fig.xlabel("recall");
  fig.ylabel("precision");
  fig.xlim(0.0, 1.02);  // a curve at recall 1 stays off the frame
  if (zoom) fig.ylim(0.9, 1.005);
  else fig.ylim(0.0, 1.02);
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

void plotPrCurves(const std::string& path, const std::vector<CurveMetrics>& pairwise, const CurveMetrics* top1,
                  const std::string& title) {
  const plot::Figure full = prFigure(pairwise, top1, title, false), zoom = prFigure(pairwise, top1, title, true);
  plot::savePngRow(path, {&full, &zoom});
}

void plotTiming(const std::string& path, const SequenceRun& run) {
  std::vector<double> x, extraction, description, retrieval, verification, total;
  for (size_t i = 0; i < run.frames.size(); ++i) {
    const StageTimes& t = run.frames[i].timing;
    x.push_back(static_cast<double>(i));
    extraction.push_back(t.extraction_ms);
    description.push_back(t.description_ms);
    retrieval.push_back(t.retrieval_ms);
    verification.push_back(t.verification_ms);
    total.push_back(t.total_ms());
  }
  plot::Figure fig(1200, 600);
  fig.title("Time per frame and stage (reading files excluded)");
  fig.xlabel("frame");
  fig.ylabel("milliseconds");
  fig.legendAt("outside right");
  if (run.frames.empty()) fig.note("no frames");
  fig.line(x, total, "total", plot::Color{0.1, 0.1, 0.1}, 1.2);
  fig.line(x, extraction, "node extraction", plot::seriesColor(0), 1.0);
  fig.line(x, verification, "verification (15 candidates)", plot::seriesColor(1), 1.0);
  fig.line(x, retrieval, "retrieval", plot::seriesColor(2), 1.0);
  fig.line(x, description, "graph + descriptors", plot::seriesColor(3), 1.0);
  fig.savePng(path);
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
  // Drawn in this order, so the loops lie above the path and the missed revisits.
  fig.line(x, y, "trajectory", plot::Color{0.7, 0.7, 0.7}, 1.5);
  fig.points(miss_x, miss_y, counted("revisit missed", miss_x.size()), plot::Color{0.95, 0.6, 0.0}, 2.5);
  fig.segments(between, counted("loop " + pos + "-" + neg + " m apart (not scored)", between.size()),
               plot::Color{0.3, 0.4, 0.9}, 2.0);
  fig.segments(bad, counted("false loop (> " + neg + " m)", bad.size()), plot::Color{0.9, 0.0, 0.0}, 2.0);
  fig.segments(good, "", plot::Color{0.0, 0.55, 0.15}, 2.0);
  fig.points(true_x, true_y, counted("true loop (< " + pos + " m)", true_x.size()), plot::Color{0.0, 0.55, 0.15},
             3.5);
  if (!x.empty()) fig.points({x.front()}, {y.front()}, "start", plot::Color{0.0, 0.0, 0.0}, 6.0);
  if (x.empty()) fig.note("no frames");
  fig.savePng(path);
}

}  // namespace sgtllc::eval
