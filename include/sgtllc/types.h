/// @file types.h
/// @brief Basic value types shared by every stage: the stable classes, labelled clouds and graph nodes.
#pragma once

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace sgtllc {

/// Number of stable semantic classes kept as graph nodes (spec §1).
inline constexpr int kNumClasses = 7;

/// Stable class indices in the order every 7×7 hash uses (spec §1 table): c = train id − 13.
enum SemanticClass : int {
  kBuilding = 0,
  kFence = 1,
  kVegetation = 2,
  kTrunk = 3,
  kTerrain = 4,
  kPole = 5,
  kTrafficSign = 6,
};

/// Lower-case class names in class-index order ("building", …, "traffic-sign").
inline constexpr std::array<const char*, kNumClasses> kClassNames = {
    "building", "fence", "vegetation", "trunk", "terrain", "pole", "traffic-sign"};

/// A LiDAR scan with one raw semantic id per point, in the sensor frame.
struct LabeledCloud {
  std::vector<Eigen::Vector3f> points;  ///< x, y, z in metres (sensor frame)
  std::vector<uint32_t> labels;         ///< raw per-point id, interpreted by LabelConfig (same length as points)
};

/// One semantic-graph node: an object instance reduced to its centre and class (spec §2).
struct Node {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  ///< p_i, metres, sensor frame
  int label = 0;                                      ///< l_i, stable class index 0..6
};

/// Error for bad input data or configuration. The message names the offending item.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace sgtllc
