#include "pagor/kdtree.hpp"

#include <algorithm>
#include <numeric>

namespace pagor {

KdTree3f::KdTree3f(const std::vector<Eigen::Vector3f>& points, int leaf_size)
    : points_(points), index_(points.size()) {
  std::iota(index_.begin(), index_.end(), 0);
  if (!points_.empty()) {
    nodes_.reserve(2 * points_.size() / static_cast<std::size_t>(std::max(1, leaf_size)) + 1);
    build(0, static_cast<int>(points_.size()), std::max(1, leaf_size));
  }
}

int KdTree3f::build(int begin, int end, int leaf_size) {
  const int id = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  if (end - begin <= leaf_size) {
    nodes_[static_cast<std::size_t>(id)] = Node{0.0f, -1, begin, end};
    return id;
  }
  // Split the widest axis at the median.
  Eigen::Vector3f lo = points_[static_cast<std::size_t>(begin)], hi = lo;
  for (int i = begin + 1; i < end; ++i) {
    lo = lo.cwiseMin(points_[static_cast<std::size_t>(i)]);
    hi = hi.cwiseMax(points_[static_cast<std::size_t>(i)]);
  }
  int axis = 0;
  (hi - lo).maxCoeff(&axis);
  const int mid = begin + (end - begin) / 2;
  // Sort a permutation, then apply it to points and indices together.
  std::vector<int> order(static_cast<std::size_t>(end - begin));
  std::iota(order.begin(), order.end(), begin);
  std::nth_element(order.begin(), order.begin() + (mid - begin), order.end(), [&](int x, int y) {
    return points_[static_cast<std::size_t>(x)][axis] < points_[static_cast<std::size_t>(y)][axis];
  });
  std::vector<Eigen::Vector3f> p(order.size());
  std::vector<int> idx(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    p[k] = points_[static_cast<std::size_t>(order[k])];
    idx[k] = index_[static_cast<std::size_t>(order[k])];
  }
  std::copy(p.begin(), p.end(), points_.begin() + begin);
  std::copy(idx.begin(), idx.end(), index_.begin() + begin);
  const float split = points_[static_cast<std::size_t>(mid)][axis];
  const int left = build(begin, mid, leaf_size);
  const int right = build(mid, end, leaf_size);
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
