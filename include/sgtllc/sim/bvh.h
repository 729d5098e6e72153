/// @file bvh.h
/// @brief Bounding-volume hierarchy over scene primitives: exact closest-hit ray queries.
#pragma once

#include <cstdint>
#include <vector>

#include "sgtllc/sim/geometry.h"
#include "sgtllc/sim/rng.h"

namespace sgtllc::sim {

/// Per-ray facts the hit test needs besides the geometry.
struct RayContext {
  float time = 0.0f;  ///< primitives not alive at this time (s) are invisible
  uint64_t key = 0;   ///< identifies the ray; seeds the return depth inside porous primitives
};

/// The closest hit of a ray: parameter t and the primitive's index in the list that was searched (−1: none).
struct Hit {
  float t = kInf;
  int32_t prim = -1;
  bool valid() const { return prim >= 0; }
};

/// The uniform number that sets a ray's return depth inside porous primitive @p prim (see intersect()).
inline double porousDraw(uint64_t ray_key, uint32_t prim) { return hashUniform(hashWords(ray_key, prim, 0x5EED)); }

/// Closest hit by testing every primitive: the reference the BVH must equal.
Hit closestHitBruteForce(const std::vector<Primitive>& prims, const Ray& ray, float t_max, const RayContext& ctx);

/// Binned-SAH BVH. It owns its primitives, reordered for locality; hits index primitives().
class Bvh {
 public:
  Bvh() = default;
  explicit Bvh(std::vector<Primitive> prims, int max_leaf_size = 4);

  const std::vector<Primitive>& primitives() const { return prims_; }
  size_t size() const { return prims_.size(); }
  /// Bounds of everything (empty box if there are no primitives).
  Aabb bounds() const { return nodes_.empty() ? Aabb{} : nodes_[0].box; }
  /// Closest hit with t in (0, t_max]; identical to closestHitBruteForce over primitives().
  Hit closestHit(const Ray& ray, float t_max, const RayContext& ctx) const;

 private:
  struct Node {
    Aabb box;
    uint32_t first = 0;  ///< leaf: first primitive; inner: index of the right child (left child is next)
    uint32_t count = 0;  ///< primitives in a leaf; 0 for an inner node
    int axis = 0;        ///< split axis of an inner node
  };
  uint32_t build(std::vector<uint32_t>& order, const std::vector<Aabb>& boxes, const std::vector<Eigen::Vector3f>& mid,
                 uint32_t first, uint32_t count, int max_leaf_size, int depth);

  std::vector<Node> nodes_;
  std::vector<Primitive> prims_;
};

}  // namespace sgtllc::sim
