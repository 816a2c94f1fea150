// Work and memory budgets: parameters that would make a stage unbounded on the given input end in
// a ConfigError naming the key; ordinary parameters pass.

#include <catch2/catch.hpp>
#include <random>

#include "pagor/config.hpp"
#include "pagor/front/correspondences.hpp"
#include "pagor/errors.hpp"
#include "pagor/front/landmarks.hpp"
#include "pagor/util/work_budget.hpp"
#include "util/random_draw.hpp"

using namespace pagor;

namespace {

// `n` cluster landmarks of class 0, on a line 1 m apart.
LandmarkSet line_of_landmarks(std::size_t n) {
  LandmarkSet set;
  set.classes.push_back(ClassSummary{});
  set.classes.back().name = "car";
  for (std::size_t i = 0; i < n; ++i) {
    Landmark lm;
    lm.class_index = 0;
    lm.kind = LandmarkKind::cluster;
    lm.centroid = Eigen::Vector3d(static_cast<double>(i), 0, 0);
    lm.covariance = Eigen::Matrix3d::Identity() * 0.01;
    set.landmarks.push_back(lm);
    set.descriptors.emplace_back();
  }
  return set;
}

}  // namespace

TEST_CASE("a radius search over the whole class is refused before it runs") {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0.0f, 10.0f);
  std::vector<Eigen::Vector3f> pts(20000);
  for (auto& p : pts) p = draw3(u, rng).cast<float>();
  // Every point within 1e6 m of every other: 4e8 visits, over the 1e8 budget.
  CHECK_THROWS_WITH(
      check_radius_work(pts, 1e6, "landmarks.classes[1].cluster_tolerance", "class 'x'"),
      Catch::StartsWith("landmarks.classes[1].cluster_tolerance: 1e+06 m") &&
          Catch::Contains("budget"));
  // 0.3 m: a few neighbours per point at this density, far below the budget.
  CHECK_NOTHROW(check_radius_work(pts, 0.3, "k", "class 'x'"));
  // Small classes are never refused.
  pts.resize(5000);
  CHECK_NOTHROW(check_radius_work(pts, 1e6, "k", "class 'x'"));
}

TEST_CASE("correspondence budgets: all-to-all candidates and the graph's size") {
  CorrespondenceParams p;
  p.max_correspondences = 0;  // no cap
  const LandmarkSet small = line_of_landmarks(100);
  CHECK(match_landmarks(small, small, p).items.size() == 10000);
  const LandmarkSet mid = line_of_landmarks(200);  // 40000 > 20000 for the graph
  CHECK_THROWS_WITH(match_landmarks(mid, mid, p),
                    Catch::StartsWith("correspondences.max_correspondences: 40000"));
  p.max_correspondences = 1500;
  CHECK(match_landmarks(mid, mid, p).items.size() == 1500);
  const LandmarkSet big = line_of_landmarks(2100);  // 4.41e6 candidates > 4e6
  CHECK_THROWS_WITH(
      match_landmarks(big, big, p),
      Catch::StartsWith("landmarks.classes: all-to-all matching") && Catch::Contains("4410000"));
}
