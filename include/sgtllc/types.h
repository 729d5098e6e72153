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

/// Number of the paper's stable semantic classes (algorithm §1): the default class set. A configuration may declare
/// more (LabelConfig::extra_classes), numbered from 7 on; LabelConfig::numClasses() is the class count C.
inline constexpr int kNumPaperClasses = 7;

/// Upper bound of the class count C: the paper's seven plus at most nine extra classes. The G2 global descriptor
/// has C³ entries (16 classes: 4,096 floats, 16 KB per frame; GlobalMode) and a local descriptor C² slots.
inline constexpr int kMaxClasses = 16;

/// The paper's stable class indices in the order every C×C hash uses (algorithm §1 table): c = train id − 13.
enum SemanticClass : int {
  kBuilding = 0,
  kFence = 1,
  kVegetation = 2,
  kTrunk = 3,
  kTerrain = 4,
  kPole = 5,
  kTrafficSign = 6,
};

/// Lower-case names of the paper's classes in class-index order ("building", …, "traffic-sign"); extra classes are
/// named by the configuration (LabelConfig::className).
inline constexpr std::array<const char*, kNumPaperClasses> kClassNames = {
    "building", "fence", "vegetation", "trunk", "terrain", "pole", "traffic-sign"};

/// A LiDAR scan with one raw semantic id per point, in the sensor frame.
struct LabeledCloud {
  std::vector<Eigen::Vector3f> points;  ///< x, y, z in metres (sensor frame)
  std::vector<uint32_t> labels;         ///< raw per-point id, interpreted by LabelConfig (same length as points)
};

/// One semantic-graph node: an object instance reduced to its centre and class (algorithm §2).
struct Node {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  ///< p_i, metres, sensor frame
  int label = 0;                                      ///< l_i, stable class index 0..C−1 (0..6 by default)
};

/// Error for bad input data or configuration. The message names the offending item.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace sgtllc
