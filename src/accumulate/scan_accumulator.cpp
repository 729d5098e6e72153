#include "sgtllc/accumulate/scan_accumulator.h"

#include <string>
#include <utility>

#include <Eigen/LU>

namespace sgtllc {
namespace {

void checkScan(const LabeledCloud& scan, size_t index) {
  if (scan.points.size() != scan.labels.size()) {
    throw Error("scan " + std::to_string(index) + " to accumulate has " + std::to_string(scan.points.size()) +
                " points but " + std::to_string(scan.labels.size()) + " labels");
  }
}

void checkPose(const Eigen::Isometry3d& T, size_t index) {
  if (!T.matrix().allFinite()) throw Error("pose of scan " + std::to_string(index) + " to accumulate is not finite");
}

}  // namespace

LabeledCloud mergeScans(const std::vector<const LabeledCloud*>& scans,
                        const std::vector<Eigen::Isometry3d>& T_world_scan) {
  if (scans.size() != T_world_scan.size()) {
    throw Error("accumulating " + std::to_string(scans.size()) + " scans with " +
                std::to_string(T_world_scan.size()) + " poses");
  }
  LabeledCloud out;
  if (scans.empty()) return out;
  size_t total = 0;
  for (size_t k = 0; k < scans.size(); ++k) {
    checkScan(*scans[k], k);
    checkPose(T_world_scan[k], k);
    total += scans[k]->points.size();
  }
  out.points.reserve(total);
  out.labels.reserve(total);
  const size_t newest = scans.size() - 1;
  // The general 4×4 inverse, as Simulator::merge uses, so a drive accumulated here from its poses matches the
  // simulator's own accumulation point for point (tests/test_accumulate.cpp compares the two).
  const Eigen::Matrix4d newest_world = T_world_scan[newest].matrix().inverse();
  for (size_t k = 0; k < scans.size(); ++k) {
    const LabeledCloud& s = *scans[k];
    if (k == newest) {
      out.points.insert(out.points.end(), s.points.begin(), s.points.end());
    } else {
      const Eigen::Matrix4d T = newest_world * T_world_scan[k].matrix();  // T_newest_k
      const Eigen::Matrix3f R = T.topLeftCorner<3, 3>().cast<float>();
      const Eigen::Vector3f t = T.topRightCorner<3, 1>().cast<float>();
      for (const Eigen::Vector3f& p : s.points) out.points.emplace_back(R * p + t);
    }
    out.labels.insert(out.labels.end(), s.labels.begin(), s.labels.end());
  }
  return out;
}

ScanAccumulator::ScanAccumulator(int scans) : capacity_(scans) {
  if (scans < 1 || scans > kMaxScans) {
    throw Error("scans to accumulate must be 1.." + std::to_string(kMaxScans) + ", not " + std::to_string(scans));
  }
}

LabeledCloud ScanAccumulator::add(LabeledCloud scan, const Eigen::Isometry3d& T_world_scan) {
  checkScan(scan, 0);
  checkPose(T_world_scan, 0);
  if (held_.size() == static_cast<size_t>(capacity_)) held_.pop_front();
  held_.push_back({std::move(scan), T_world_scan});
  std::vector<const LabeledCloud*> clouds;
  std::vector<Eigen::Isometry3d> poses;
  for (const Held& h : held_) {
    clouds.push_back(&h.cloud);
    poses.push_back(h.T_world_scan);
  }
  return mergeScans(clouds, poses);
}

size_t ScanAccumulator::points() const {
  size_t n = 0;
  for (const Held& h : held_) n += h.cloud.points.size();
  return n;
}

size_t ScanAccumulator::bytes() const {
  return points() * (sizeof(Eigen::Vector3f) + sizeof(uint32_t));
}

}  // namespace sgtllc
