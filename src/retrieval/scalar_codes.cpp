#include "retrieval/scalar_codes.h"

#include <algorithm>

namespace sgtllc::internal {

ScalarCodes::ScalarCodes(const float* rows, int count, int dim) : dim_(dim) {
  float low = 0.0f, high = 0.0f;  // the range always holds 0: a key of zeros (a frame without nodes) codes exactly
  const size_t values = static_cast<size_t>(count) * static_cast<size_t>(dim);
  for (size_t i = 0; i < values; ++i) {  // NaN is never smaller or larger: skipped
    low = std::min(low, rows[i]);
    high = std::max(high, rows[i]);
  }
  low_ = low;
  inverse_step_ = high > low ? 255.0f / (high - low) : 0.0f;
}

void ScalarCodes::encode(const float* row, std::vector<uint8_t>* out) const {
  for (int d = 0; d < dim_; ++d) {
    const float steps = (row[d] - low_) * inverse_step_;
    // Values below the training rows' range and NaN fail the test and become 0; values beyond it, 255.
    const float clamped = steps >= 0.0f ? std::min(steps, 255.0f) : 0.0f;
    out->push_back(static_cast<uint8_t>(clamped + 0.5f));  // round half up (non-negative: truncation)
  }
}

uint32_t ScalarCodes::distance(const uint8_t* a, const uint8_t* b, int dim) {
  // Integer sums are exact in any order, so the compiler may vectorise freely: 840 squares of at most 255² stay
  // far below 2³².
  uint32_t sum = 0;
  for (int d = 0; d < dim; ++d) {
    const int diff = static_cast<int>(a[d]) - static_cast<int>(b[d]);
    sum += static_cast<uint32_t>(diff * diff);
  }
  return sum;
}

}  // namespace sgtllc::internal
