/// @file scalar_codes.h
/// @brief Retrieval keys as one byte per dimension (internal): the inverted file scans these short codes, stored
///        list by list, and re-ranks the nearest by the exact key (docs/algorithm.md §5, "Retrieval at scale").
#pragma once

#include <cstdint>
#include <vector>

namespace sgtllc::internal {

/// One uniform step for every dimension over the range of the training rows' values, 0 included (the default keys
/// are non-negative histograms of unit length, so the range is 0 to their largest value): code = round((x − low) /
/// step), clamped to 0..255. One step for all makes the distance of two codes a sum of integer squares, which the
/// compiler vectorises. A pure function of the training rows, so a map restored from its keys gets the same codes.
class ScalarCodes {
 public:
  ScalarCodes() = default;
  /// The step for rows 0..@p count−1 of the row-major @p rows of @p dim dimensions.
  ScalarCodes(const float* rows, int count, int dim);

  /// Appends the codes of the @p dim values of @p row to @p out.
  void encode(const float* row, std::vector<uint8_t>* out) const;

  /// Squared L2 distance between two codes of @p dim bytes, in steps²: the exact distance / step², within the
  /// rounding of both.
  static uint32_t distance(const uint8_t* a, const uint8_t* b, int dim);

 private:
  float low_ = 0.0f;
  float inverse_step_ = 0.0f;
  int dim_ = 0;
};

}  // namespace sgtllc::internal
