#include "pagor/util/kdtree.hpp"

#include <algorithm>

namespace pagor {

KdTree3f::KdTree3f(const std::vector<Eigen::Vector3f>& points, int leaf_size) {
  std::vector<Item> items(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) items[i] = Item{points[i], static_cast<int>(i)};
  if (!items.empty()) {
    nodes_.reserve(2 * items.size() / static_cast<std::size_t>(std::max(1, leaf_size)) + 1);
    build(items, 0, static_cast<int>(items.size()), std::max(1, leaf_size));
  }
  points_.resize(items.size());
  index_.resize(items.size());
  for (std::size_t i = 0; i < items.size(); ++i) {
    points_[i] = items[i].p;
    index_[i] = items[i].index;
  }
}

int KdTree3f::build(std::vector<Item>& items, int begin, int end, int leaf_size) {
  const int id = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  if (end - begin <= leaf_size) {
    nodes_[static_cast<std::size_t>(id)] = Node{0.0f, -1, begin, end};
    return id;
  }
  // Split the widest axis at the median (points and their indices move together, in place).
  Eigen::Vector3f lo = items[static_cast<std::size_t>(begin)].p, hi = lo;
  for (int i = begin + 1; i < end; ++i) {
    lo = lo.cwiseMin(items[static_cast<std::size_t>(i)].p);
    hi = hi.cwiseMax(items[static_cast<std::size_t>(i)].p);
  }
  int axis = 0;
  (hi - lo).maxCoeff(&axis);
  const int mid = begin + (end - begin) / 2;
  std::nth_element(items.begin() + begin, items.begin() + mid, items.begin() + end,
                   [axis](const Item& x, const Item& y) { return x.p[axis] < y.p[axis]; });
  const float split = items[static_cast<std::size_t>(mid)].p[axis];
  const int left = build(items, begin, mid, leaf_size);
  const int right = build(items, mid, end, leaf_size);
  nodes_[static_cast<std::size_t>(id)] = Node{split, axis, left, right};
  return id;
}

std::pair<int, float> KdTree3f::nearest(const Eigen::Vector3f& q, float max_distance_sq,
                                        int exclude) const {
  int best = -1;
  float best_d2 = max_distance_sq;
  if (nodes_.empty()) return {best, best_d2};
  // Stack of (node, squared distance from q to the node's side of its parent's plane).
  std::pair<int, float> stack[64];
  int top = 0;
  stack[top++] = {0, 0.0f};
  while (top > 0) {
    const auto [id, bound] = stack[--top];
    if (bound >= best_d2) continue;
    const Node& n = nodes_[static_cast<std::size_t>(id)];
    if (n.axis < 0) {
      for (int i = n.a; i < n.b; ++i) {
        const float d2 = (points_[static_cast<std::size_t>(i)] - q).squaredNorm();
        if (d2 < best_d2 && index_[static_cast<std::size_t>(i)] != exclude) {
          best_d2 = d2;
          best = index_[static_cast<std::size_t>(i)];
        }
      }
      continue;
    }
    const float diff = q[n.axis] - n.split;
    const int near = diff < 0 ? n.a : n.b, far = diff < 0 ? n.b : n.a;
    // Far side first on the stack, so the near side is searched first.
    stack[top++] = {far, diff * diff};
    stack[top++] = {near, 0.0f};
  }
  return {best, best_d2};
}

}  // namespace pagor
