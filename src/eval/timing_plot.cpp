#include "timing_plot.h"

#include <algorithm>
#include <cstdio>

#include "sgtllc/plot/figure.h"

namespace sgtllc::eval {
namespace {

struct Stage {
  std::string name;
  std::vector<double> ms;
  plot::Color color;
  double width;
};

std::string milliseconds(double v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), v < 10.0 ? "%.2f" : "%.1f", v);
  return buf;
}

/// Each stage's running median over the frames; its legend entry gives the median and p99 of all its frames.
plot::Figure sequencePanel(const std::vector<Stage>& stages, size_t frames, int half) {
  std::vector<double> x(frames);
  for (size_t i = 0; i < frames; ++i) x[i] = static_cast<double>(i);
  plot::Figure fig(1050, 600);
  fig.title("Time per frame and stage, running median of " + std::to_string(2 * half + 1) + " frames");
  fig.xlabel("frame");
  fig.ylabel("milliseconds (reading files excluded)");
  fig.legendAt("outside right");
  double top = 0.0;
  for (const Stage& s : stages) {
    const std::vector<double> smooth = runningMedian(s.ms, half);
    for (double v : smooth) top = std::max(top, v);
    fig.line(x, smooth, s.name + ": median " + milliseconds(percentile(s.ms, 0.5)) + ", p99 " +
                            milliseconds(percentile(s.ms, 0.99)) + " ms",
             s.color, s.width);
  }
  fig.ylim(0.0, top > 0.0 ? 1.1 * top : 1.0);
  if (frames == 0) fig.note("no frames");
  return fig;
}

/// The histogram of the total time per frame as steps, with its median and p99 as vertical lines.
plot::Figure histogramPanel(const std::vector<double>& total) {
  plot::Figure fig(620, 600);
  fig.title("Total time per frame, " + std::to_string(total.size()) + " frames");
  fig.xlabel("milliseconds");
  fig.ylabel("frames");
  fig.legendAt("upper right");
  if (total.empty()) {
    fig.note("no frames");
    return fig;
  }
  const double median = percentile(total, 0.5), p99 = percentile(total, 0.99);
  const double max = *std::max_element(total.begin(), total.end());
  // The tail beyond 1.5 × p99 is counted, not drawn: it would squeeze the bins where the frames lie.
  const double hi = std::max(std::min(max, 1.5 * p99), 1e-3);
  const Histogram h = histogram(total, hi, 50);
  std::vector<double> x = {0.0}, y = {0.0};
  int peak = 0;
  for (size_t k = 0; k < h.counts.size(); ++k) {
    x.insert(x.end(), {h.width * static_cast<double>(k), h.width * static_cast<double>(k + 1)});
    y.insert(y.end(), {static_cast<double>(h.counts[k]), static_cast<double>(h.counts[k])});
    peak = std::max(peak, h.counts[k]);
  }
  x.push_back(hi);
  y.push_back(0.0);
  const double top = 1.25 * peak;
  fig.xlim(0.0, 1.02 * hi);
  fig.ylim(0.0, top);
  fig.line(x, y, "frames per bin of " + milliseconds(h.width) + " ms", plot::seriesColor(0), 2.0);
  fig.line({median, median}, {0.0, top}, "median " + milliseconds(median) + " ms", plot::Color{0.1, 0.1, 0.1}, 2.0,
           true);
  fig.line({p99, p99}, {0.0, top}, "p99 " + milliseconds(p99) + " ms", plot::Color{0.85, 0.1, 0.1}, 2.0, true);
  if (h.above > 0) {
    fig.legendEntry(std::to_string(h.above) + " above " + milliseconds(hi) + " ms (max " + milliseconds(max) + ")",
                    plot::Color{0.6, 0.6, 0.6});
  }
  return fig;
}

}  // namespace

std::vector<double> runningMedian(const std::vector<double>& values, int half) {
  const long n = static_cast<long>(values.size()), h = std::max(0, half);
  std::vector<double> out(values.size()), window;
  for (long i = 0; i < n; ++i) {
    window.assign(values.begin() + std::max(0L, i - h), values.begin() + std::min(n, i + h + 1));
    const size_t mid = window.size() / 2;
    std::nth_element(window.begin(), window.begin() + static_cast<long>(mid), window.end());
    double m = window[mid];
    if (window.size() % 2 == 0) m = 0.5 * (m + *std::max_element(window.begin(), window.begin() + static_cast<long>(mid)));
    out[static_cast<size_t>(i)] = m;
  }
  return out;
}

Histogram histogram(const std::vector<double>& values, double hi, int bins) {
  Histogram h;
  h.counts.assign(static_cast<size_t>(std::max(1, bins)), 0);
  h.width = hi / static_cast<double>(h.counts.size());
  for (double v : values) {
    if (v > hi) {
      ++h.above;
      continue;
    }
    const size_t k = std::min(h.counts.size() - 1, static_cast<size_t>(std::max(0.0, v) / h.width));
    ++h.counts[k];
  }
  return h;
}

void plotTiming(const std::string& path, const SequenceRun& run) {
  std::vector<Stage> stages = {{"total", {}, plot::Color{0.1, 0.1, 0.1}, 2.0},
                               {"node extraction", {}, plot::seriesColor(0), 1.5},
                               {"verification", {}, plot::seriesColor(1), 1.5},
                               {"retrieval", {}, plot::seriesColor(2), 1.5},
                               {"graph + descriptors", {}, plot::seriesColor(3), 1.5},
                               {"ICP refinement", {}, plot::seriesColor(4), 1.5}};
  for (const FrameRecord& f : run.frames) {
    const StageTimes& t = f.timing;
    const double ms[] = {t.total_ms(), t.extraction_ms, t.verification_ms, t.retrieval_ms, t.description_ms,
                         t.refinement_ms};
    for (size_t k = 0; k < stages.size(); ++k) stages[k].ms.push_back(ms[k]);
  }
  // Refinement runs only with registration.online: without it the line would only take a legend row.
  if (!run.refinement_online) stages.pop_back();
  // A window of about 1 % of the sequence: a trend over a few hundred frames survives, a one-frame spike does not.
  const int half = std::clamp(static_cast<int>(run.frames.size() / 200), 0, 50);
  const plot::Figure left = sequencePanel(stages, run.frames.size(), half), right = histogramPanel(stages[0].ms);
  plot::savePngRow(path, {&left, &right});
}

}  // namespace sgtllc::eval
