// One-byte codes of retrieval keys (algorithm §5 "Retrieval at scale"): the step from the training rows' range (0
// included), rounding and clamping by hand-computed codes, and the code distance against a brute-force sum and against
// the exact distance it estimates.
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "retrieval/scalar_codes.h"

namespace {

using sgtllc::internal::ScalarCodes;

TEST(ScalarCodes, StepComesFromTheLargestTrainingValueAndCodesRoundAndClamp) {
  // Largest value 0.5: one step is 0.5 / 255, so x codes as round(510 x).
  const std::vector<float> rows = {0.0f, 0.1f, 0.5f, 0.25f, 0.2f, 0.0f};
  const ScalarCodes codes(rows.data(), 2, 3);
  std::vector<uint8_t> out;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::vector<float> row = {0.25f, 0.5f, 0.7f, -0.3f, nan, 0.1f, 0.0009f, 0.001f};
  std::vector<float> wide(16, 0.125f);
  wide[9] = 0.5f;
  ScalarCodes(wide.data(), 2, 8).encode(row.data(), &out);  // the same largest value, rows of eight
  // 127.5 rounds up; 0.7 lies beyond the training rows (255); negative and NaN are 0; 51.0; 0.459 → 0; 0.51 → 1.
  EXPECT_EQ(out, (std::vector<uint8_t>{128, 255, 255, 0, 0, 51, 0, 1}));
  out.clear();
  codes.encode(rows.data() + 3, &out);  // appends
  codes.encode(rows.data(), &out);
  EXPECT_EQ(out, (std::vector<uint8_t>{128, 102, 0, 0, 51, 255}));
}

TEST(ScalarCodes, NegativeValuesWidenTheRangeBelowZero) {
  // Range −0.5 … 0.5: one step is 1 / 255, so x codes as round((x + 0.5) · 255).
  const std::vector<float> rows = {-0.5f, 0.0f, 0.5f, 0.25f, 0.1f};
  std::vector<uint8_t> out;
  const std::vector<float> row = {-0.5f, 0.0f, 0.5f, -1.0f, 0.25f};
  ScalarCodes(rows.data(), 1, 5).encode(row.data(), &out);
  EXPECT_EQ(out, (std::vector<uint8_t>{0, 128, 255, 0, 191}));  // 127.5 rounds up; 191.25 down
}

TEST(ScalarCodes, RowsOfZerosGiveZeroCodes) {
  const std::vector<float> rows(6, 0.0f);
  const ScalarCodes codes(rows.data(), 2, 3);
  std::vector<uint8_t> out;
  const std::vector<float> row = {0.0f, 1.0f, 5.0f};
  codes.encode(row.data(), &out);
  EXPECT_EQ(out, (std::vector<uint8_t>{0, 0, 0}));
}

TEST(ScalarCodes, DistanceIsTheSumOfSquaredDifferencesAndEstimatesTheExactOne) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> value(0.0f, 1.0f);
  constexpr int kDim = 840;  // the default key's length, with a tail past any multiple of a vector width
  std::vector<float> rows(3 * kDim);
  for (float& v : rows) v = value(rng);
  const ScalarCodes codes(rows.data(), 3, kDim);
  std::vector<uint8_t> a, b;
  codes.encode(rows.data(), &a);
  codes.encode(rows.data() + kDim, &b);
  uint64_t brute = 0;
  double exact = 0.0;
  float high = 0.0f;
  for (float v : rows) high = std::max(high, v);
  for (int d = 0; d < kDim; ++d) {
    brute += static_cast<uint64_t>((a[d] - b[d]) * (a[d] - b[d]));
    exact += std::pow(static_cast<double>(rows[d]) - rows[kDim + d], 2);
  }
  EXPECT_EQ(ScalarCodes::distance(a.data(), b.data(), kDim), brute);
  EXPECT_EQ(ScalarCodes::distance(a.data(), a.data(), kDim), 0u);
  // In steps² the estimate is the exact distance within rounding: each difference is off by at most one step.
  const double step = high / 255.0;
  EXPECT_NEAR(static_cast<double>(brute) * step * step, exact, 0.01 * exact);
  // The largest possible sum fits: 840 · 255².
  const std::vector<uint8_t> zeros(kDim, 0), full(kDim, 255);
  EXPECT_EQ(ScalarCodes::distance(zeros.data(), full.data(), kDim), 840u * 255u * 255u);
}

}  // namespace
