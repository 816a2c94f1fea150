#pragma once
/// \file kdtree.hpp
/// A small static kd-tree over 3D float points for nearest-neighbour queries with an optional
/// distance bound: the verification only needs neighbours closer than mu, and the bound prunes
/// most of the search.

#include <Eigen/Core>
#include <limits>
#include <utility>
#include <vector>

namespace pagor {

class KdTree3f {
 public:
  /// Builds over a copy of `points`. `leaf_size` points at most per leaf.
  explicit KdTree3f(const std::vector<Eigen::Vector3f>& points, int leaf_size = 10);
  KdTree3f() = default;

  /// Nearest point to `q` strictly closer than sqrt(`max_distance_sq`): its index in the input and
  /// squared distance; index -1 (and `max_distance_sq`) when there is none. The input point with
  /// index `exclude` (if any) is skipped, so a point of the tree can ask for its neighbour.
  std::pair<int, float> nearest(const Eigen::Vector3f& q,
                                float max_distance_sq = std::numeric_limits<float>::infinity(),
                                int exclude = -1) const;

  std::size_t size() const { return points_.size(); }

 private:
  struct Node {
    float split = 0;   // coordinate of the splitting plane (inner nodes)
    int axis = -1;     // 0, 1, 2; -1 for a leaf
    int a = 0, b = 0;  // inner: children; leaf: [a, b) range of points_
  };
  struct Item {
    Eigen::Vector3f p;
    int index;
  };
  int build(std::vector<Item>& items, int begin, int end, int leaf_size);

  std::vector<Eigen::Vector3f> points_;  // reordered so that each leaf is contiguous
  std::vector<int> index_;               // original index of points_[i]
  std::vector<Node> nodes_;
};

}  // namespace pagor
