#include <catch2/catch.hpp>
#include <random>

#include "pagor/util/kdtree.hpp"
#include "util/random_draw.hpp"

using namespace pagor;

namespace {

std::pair<int, float> brute_force(const std::vector<Eigen::Vector3f>& pts, const Eigen::Vector3f& q,
                                  float bound) {
  int best = -1;
  float d2 = bound;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const float d = (pts[i] - q).squaredNorm();
    if (d < d2) {
      d2 = d;
      best = static_cast<int>(i);
    }
  }
  return {best, d2};
}

}  // namespace

TEST_CASE("the kd-tree agrees with a linear scan, with and without a bound") {
  std::mt19937_64 rng(17);
  for (int n : {1, 7, 100, 5000}) {
    std::uniform_real_distribution<float> u(-20.f, 20.f);
    std::vector<Eigen::Vector3f> pts;
    for (int i = 0; i < n; ++i)
      pts.push_back(draw3(u, rng).cast<float>().cwiseProduct(Eigen::Vector3f(1, 1, 0.1f)));  // flat
    pts.push_back(pts.front());                         // a duplicate
    const KdTree3f tree(pts, 6);
    REQUIRE(tree.size() == pts.size());
    for (int k = 0; k < 500; ++k) {
      const Eigen::Vector3f q(u(rng) * 1.2f, u(rng) * 1.2f, u(rng) * 0.2f);
      for (float bound : {std::numeric_limits<float>::infinity(), 1.0f, 0.01f}) {
        const auto ref = brute_force(pts, q, bound);
        const auto got = tree.nearest(q, bound);
        REQUIRE(got.second == ref.second);
        if (ref.first >= 0) {
          REQUIRE(got.first >= 0);
          // Ties (the duplicate) may pick either copy; the distance must be the same.
          CHECK((pts[static_cast<std::size_t>(got.first)] - q).squaredNorm() == ref.second);
        } else {
          CHECK(got.first == -1);
        }
      }
    }
  }
}

TEST_CASE("an empty kd-tree finds nothing") {
  const KdTree3f tree(std::vector<Eigen::Vector3f>{});
  CHECK(tree.nearest(Eigen::Vector3f::Zero()).first == -1);
}
