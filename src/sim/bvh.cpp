#include "sgtllc/sim/bvh.h"

#include <algorithm>
#include <array>

namespace sgtllc::sim {
namespace {

constexpr int kBins = 16;
constexpr int kMaxSahDepth = 40;  // + log2(2^32) median levels < the 128-entry traversal stack

/// Test of one primitive, honouring time and porosity.
bool testPrimitive(const Primitive& p, uint32_t index, const Ray& ray, float t_max, const RayContext& ctx, float& t) {
  if (!p.aliveAt(ctx.time)) return false;
  return intersect(p, ray, 0.0f, t_max, p.porous() ? porousDraw(ctx.key, index) : 0.0, t);
}

}  // namespace

Hit closestHitBruteForce(const std::vector<Primitive>& prims, const Ray& ray, float t_max, const RayContext& ctx) {
  Hit best;
  best.t = t_max;
  for (size_t i = 0; i < prims.size(); ++i) {
    float t;
    // Ties keep the lower index, as the BVH does.
    if (testPrimitive(prims[i], static_cast<uint32_t>(i), ray, best.t, ctx, t) &&
        (t < best.t || (t == best.t && (best.prim < 0 || static_cast<int32_t>(i) < best.prim)))) {
      best.t = t;
      best.prim = static_cast<int32_t>(i);
    }
  }
  if (!best.valid()) best.t = kInf;
  return best;
}

Bvh::Bvh(std::vector<Primitive> prims, int max_leaf_size) {
  if (prims.empty()) return;
  const uint32_t n = static_cast<uint32_t>(prims.size());
  std::vector<Aabb> boxes(n);
  std::vector<Eigen::Vector3f> mid(n);
  std::vector<uint32_t> order(n);
  for (uint32_t i = 0; i < n; ++i) {
    boxes[i] = sim::bounds(prims[i]);
    mid[i] = boxes[i].centre();
    order[i] = i;
  }
  nodes_.reserve(2 * n / std::max(1, max_leaf_size) + 1);
  build(order, boxes, mid, 0, n, std::max(1, max_leaf_size), 0);
  prims_.reserve(n);
  for (uint32_t i : order) prims_.push_back(prims[i]);
}

uint32_t Bvh::build(std::vector<uint32_t>& order, const std::vector<Aabb>& boxes,
                    const std::vector<Eigen::Vector3f>& mid, uint32_t first, uint32_t count, int max_leaf_size,
                    int depth) {
  const uint32_t index = static_cast<uint32_t>(nodes_.size());
  nodes_.emplace_back();
  Aabb box, centres;
  for (uint32_t k = first; k < first + count; ++k) {
    box.grow(boxes[order[k]]);
    centres.grow(mid[order[k]]);
  }
  nodes_[index].box = box;
  const Eigen::Vector3f extent = centres.hi - centres.lo;
  int axis = 0;
  if (extent.y() > extent[axis]) axis = 1;
  if (extent.z() > extent[axis]) axis = 2;
  auto makeLeaf = [&] {
    nodes_[index].first = first;
    nodes_[index].count = count;
    return index;
  };
  if (count <= static_cast<uint32_t>(max_leaf_size) || extent[axis] <= 0.0f) return makeLeaf();

  // Binned surface-area heuristic along the widest centroid axis.
  std::array<Aabb, kBins> bin_box;
  std::array<uint32_t, kBins> bin_count{};
  const float scale = kBins / extent[axis];
  auto binOf = [&](uint32_t prim) {
    return std::min(kBins - 1, static_cast<int>((mid[prim][axis] - centres.lo[axis]) * scale));
  };
  for (uint32_t k = first; k < first + count; ++k) {
    const int b = binOf(order[k]);
    bin_box[b].grow(boxes[order[k]]);
    ++bin_count[b];
  }
  std::array<float, kBins> right_cost{};
  Aabb acc;
  uint32_t acc_count = 0;
  for (int b = kBins - 1; b > 0; --b) {
    acc.grow(bin_box[b]);
    acc_count += bin_count[b];
    right_cost[b] = acc.area() * acc_count;
  }
  float best_cost = kInf;
  int best_split = -1;
  acc = Aabb{};
  acc_count = 0;
  for (int b = 0; b < kBins - 1; ++b) {
    acc.grow(bin_box[b]);
    acc_count += bin_count[b];
    const float cost = acc.area() * acc_count + right_cost[b + 1];
    if (acc_count > 0 && acc_count < count && cost < best_cost) {
      best_cost = cost;
      best_split = b;
    }
  }
  uint32_t split;
  // Deep in the tree, median splits bound the depth (and the traversal stack) whatever the SAH prefers.
  if (best_split >= 0 && depth < kMaxSahDepth) {
    const auto it = std::partition(order.begin() + first, order.begin() + first + count,
                                   [&](uint32_t prim) { return binOf(prim) <= best_split; });
    split = static_cast<uint32_t>(it - order.begin()) - first;
  } else {
    split = count / 2;
    std::nth_element(order.begin() + first, order.begin() + first + split, order.begin() + first + count,
                     [&](uint32_t a, uint32_t b) { return mid[a][axis] < mid[b][axis]; });
  }
  nodes_[index].axis = axis;
  build(order, boxes, mid, first, split, max_leaf_size, depth + 1);
  const uint32_t right = build(order, boxes, mid, first + split, count - split, max_leaf_size, depth + 1);
  nodes_[index].first = right;
  nodes_[index].count = 0;
  return index;
}

Hit Bvh::closestHit(const Ray& ray, float t_max, const RayContext& ctx) const {
  Hit best;
  best.t = t_max;
  if (nodes_.empty()) return Hit{};
  std::array<uint32_t, 128> stack;
  int top = 0;
  stack[top++] = 0;
  float t_enter;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (!node.box.hit(ray, 0.0f, best.t, t_enter)) continue;
    if (node.count > 0) {
      for (uint32_t k = node.first; k < node.first + node.count; ++k) {
        float t;
        if (testPrimitive(prims_[k], k, ray, best.t, ctx, t) &&
            (t < best.t || (t == best.t && (best.prim < 0 || static_cast<int32_t>(k) < best.prim)))) {
          best.t = t;
          best.prim = static_cast<int32_t>(k);
        }
      }
      continue;
    }
    const uint32_t left = static_cast<uint32_t>(&node - nodes_.data()) + 1;
    // Visit the child on the ray's near side first so best.t shrinks early.
    if (ray.d[node.axis] > 0.0f) {
      stack[top++] = node.first;
      stack[top++] = left;
    } else {
      stack[top++] = left;
      stack[top++] = node.first;
    }
  }
  if (!best.valid()) best.t = kInf;
  return best;
}

}  // namespace sgtllc::sim
