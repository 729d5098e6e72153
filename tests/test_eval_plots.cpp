// The statistics the report plots are drawn from, on hand-computed cases: the PR zoom panel's range from the
// curves' knees, the running median and the histogram of the time-per-frame plot, and the plots' PNG sizes.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "eval/report_plots.h"
#include "eval/timing_plot.h"
#include "test_io_support.h"

namespace sgtllc::eval {
namespace {

using ::testing::DoubleNear;
using ::testing::ElementsAre;

/// A PR curve from its points in threshold order (highest first); the appended (recall 0, precision 1) point last.
PrCurve curve(std::vector<double> recall, std::vector<double> precision) {
  PrCurve c;
  for (size_t k = 0; k < recall.size(); ++k) c.thresholds.push_back(1.0 - 0.1 * static_cast<double>(k));
  c.recall = std::move(recall);
  c.precision = std::move(precision);
  c.recall.push_back(0.0);
  c.precision.push_back(1.0);
  c.positives = 100;
  return c;
}

TEST(PrZoom, FramesTheKneeOnBothAxes) {
  // F1max at (0.96, 0.995) (F1 0.977; (0.5, 1) and (1, 0.5) give 0.667): gaps 0.04 and 0.005, spans of twice
  // that rounded up to one digit: 0.08, and 0.01 → the minimal 0.02.
  const PrCurve good = curve({0.5, 0.96, 1.0}, {1.0, 0.995, 0.5});
  PrZoom z = prZoom({&good});
  EXPECT_NEAR(z.recall_lo, 0.92, 1e-12);
  EXPECT_NEAR(z.precision_lo, 0.98, 1e-12);
  // A second curve with its knee at (0.99, 0.9) widens only the precision axis: 2 × 0.1 → 0.2.
  const PrCurve second = curve({0.99, 1.0}, {0.9, 0.2});
  z = prZoom({&good, &second});
  EXPECT_NEAR(z.recall_lo, 0.92, 1e-12);
  EXPECT_NEAR(z.precision_lo, 0.8, 1e-12);
  // A knee at recall 0.92 (KITTI 00's 15 m curve): 0.16 → 0.2. At 0.985 and precision 0.9995: 0.03 and 0.02.
  const PrCurve kitti = curve({0.6, 0.92, 0.99}, {1.0, 1.0, 0.2});
  EXPECT_NEAR(prZoom({&kitti}).recall_lo, 0.8, 1e-12);
  const PrCurve urban = curve({0.6, 0.985, 0.999}, {1.0, 0.9995, 0.3});
  z = prZoom({&urban});
  EXPECT_NEAR(z.recall_lo, 0.97, 1e-12);
  EXPECT_NEAR(z.precision_lo, 0.98, 1e-12);
}

TEST(PrZoom, WeakOrMissingCurvesGiveTheWholeAxes) {
  const PrCurve weak = curve({0.3, 0.8}, {0.4, 0.1});  // knee (0.3, 0.4): 2 × 0.7 is more than the axis
  PrZoom z = prZoom({&weak});
  EXPECT_EQ(z.recall_lo, 0.0);
  EXPECT_EQ(z.precision_lo, 0.0);
  PrCurve none = curve({0.5}, {1.0});
  none.positives = 0;  // a curve without positives counts for nothing
  z = prZoom({&none, nullptr});
  EXPECT_EQ(z.recall_lo, 0.0);
  EXPECT_EQ(z.precision_lo, 0.0);
  const PrCurve perfect = curve({1.0}, {1.0});  // knee at (1, 1): the minimal span on both axes
  z = prZoom({&perfect, &none});
  EXPECT_NEAR(z.recall_lo, 0.98, 1e-12);
  EXPECT_NEAR(z.precision_lo, 0.98, 1e-12);
}

TEST(TimingStats, RunningMedianOfTruncatedWindows) {
  // Windows {1, 9}, {1, 9, 2}, {9, 2, 8}, {2, 8, 3}, {8, 3}: an even window takes the mean of its middle two.
  EXPECT_THAT(runningMedian({1, 9, 2, 8, 3}, 1), ElementsAre(5.0, 2.0, 8.0, 3.0, 5.5));
  EXPECT_THAT(runningMedian({1, 1, 100, 1, 1}, 1), ElementsAre(1.0, 1.0, 1.0, 1.0, 1.0));  // a spike goes
  EXPECT_THAT(runningMedian({4, 2, 7}, 0), ElementsAre(4.0, 2.0, 7.0));
  EXPECT_THAT(runningMedian({4, 2, 7}, 5), ElementsAre(4.0, 4.0, 4.0));
  EXPECT_TRUE(runningMedian({}, 3).empty());
}

TEST(TimingStats, HistogramCountsTheTailApart) {
  // Bins of 0.5 over [0, 2]: 2 itself is in the last bin, 5 is above.
  const Histogram h = histogram({0.0, 0.5, 1.0, 1.5, 2.0, 5.0, 0.49}, 2.0, 4);
  EXPECT_DOUBLE_EQ(h.width, 0.5);
  EXPECT_THAT(h.counts, ElementsAre(2, 1, 1, 2));
  EXPECT_EQ(h.above, 1);
}

class ReportPlots : public test::TempDirTest {};

TEST_F(ReportPlots, TimingHasTwoPanelsAndCopesWithNoFrames) {
  SequenceRun run;
  for (int i = 0; i < 300; ++i) {
    FrameRecord f;
    f.frame = i;
    f.timing.extraction_ms = 1.0 + 0.01 * (i % 7);
    f.timing.verification_ms = i == 150 ? 40.0 : 0.3;  // one slow frame: counted above the histogram's range
    run.frames.push_back(f);
    run.positions.emplace_back(i, 0, 0);
  }
  plotTiming(path("timing.png"), run);
  EXPECT_EQ(test::pngSize(path("timing.png")), std::make_pair(1050 + 620, 600));
  plotTiming(path("empty.png"), SequenceRun{});
  EXPECT_EQ(test::pngSize(path("empty.png")), std::make_pair(1050 + 620, 600));
}

}  // namespace
}  // namespace sgtllc::eval
