#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <random>
#include <thread>

#include "pagor/errors.hpp"
#include "pagor/eval/synthetic.hpp"
#include "pagor/verify/verification.hpp"
#include "util/random_draw.hpp"

using namespace pagor;

namespace {

Transform perturbed(const Transform& T, double dx, double yaw_deg) {
  Transform P = Transform::Identity();
  P.block<3, 3>(0, 0) =
      Eigen::AngleAxisd(yaw_deg * 3.14159265358979 / 180, Eigen::Vector3d::UnitZ())
          .toRotationMatrix();
  P(0, 3) = dx;
  return P * T;
}

PoseEstimate candidate(const Transform& T, int inliers) {
  PoseEstimate e;
  e.valid = true;
  e.T_target_source = T;
  e.inliers.assign(static_cast<std::size_t>(inliers), 0);
  return e;
}

}  // namespace

TEST_CASE("the truncated score picks the true pose among perturbed candidates at low overlap") {
  const SyntheticScene scene = make_synthetic_scene();
  const Verifier verifier(scene.source, scene.target, 0.5);
  CHECK(verifier.source_points().size() < scene.source.size());
  const Transform& T = scene.T_target_source;
  const std::vector<PoseEstimate> c = {candidate(perturbed(T, 0.6, 0.0), 10),
                                       candidate(perturbed(T, 0.0, 2.0), 10), candidate(T, 10),
                                       candidate(perturbed(T, 3.0, 10.0), 10)};
  const VerificationResult r = verify_candidates(verifier, c, VerificationParams{});
  CHECK(r.selected == 2);
  CHECK_FALSE(r.tie);
}

TEST_CASE("with full overlap every score kind picks the true pose") {
  const SyntheticScene scene = make_synthetic_scene();
  PointCloud moved = scene.source;
  const Transform T = perturbed(Transform::Identity(), 4.0, 30.0);
  for (auto& p : moved.points)
    p = (T.block<3, 3>(0, 0) * p.cast<double>() + T.block<3, 1>(0, 3)).cast<float>();
  const Verifier verifier(scene.source, moved, 0.5);
  const std::vector<PoseEstimate> c = {candidate(perturbed(T, 0.6, 0.0), 10), candidate(T, 10),
                                       candidate(perturbed(T, 0.0, 3.0), 10)};
  for (ScoreKind kind : {ScoreKind::truncated, ScoreKind::trimmed, ScoreKind::nearest}) {
    VerificationParams vp;
    vp.score = kind;
    vp.mu = 2.0;
    INFO("score kind " << to_string(kind));
    CHECK(verify_candidates(verifier, c, vp).selected == 1);
  }
}

TEST_CASE("scores match a brute-force reference") {
  PointCloud source, target;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<float> u(-5.f, 5.f);
  for (int i = 0; i < 200; ++i) source.points.push_back(draw3(u, rng).cast<float>());
  for (int i = 0; i < 300; ++i) target.points.push_back(draw3(u, rng).cast<float>());
  const Verifier verifier(source, target, 0.0);  // no downsampling
  Transform T = Transform::Identity();
  T(0, 3) = 0.3;
  const double mu = 1.0;
  double truncated = 0, trimmed = 0, nearest = 0;
  for (const auto& p : source.points) {
    const Eigen::Vector3f tp = p + Eigen::Vector3f(0.3f, 0, 0);
    float best = HUGE_VALF;
    for (const auto& q : target.points) best = std::min(best, (tp - q).norm());
    truncated += std::min<double>(best, mu);
    trimmed += best < mu ? best : 0.0;
    nearest += best;
  }
  CHECK(verifier.score(T, mu, ScoreKind::truncated) == Approx(truncated).epsilon(1e-5));
  CHECK(verifier.score(T, mu, ScoreKind::trimmed) == Approx(trimmed).epsilon(1e-5));
  CHECK(verifier.score(T, mu, ScoreKind::nearest) == Approx(nearest).epsilon(1e-5));
  CHECK(verifier.score(T, mu, ScoreKind::truncated, 3) == Approx(truncated).epsilon(1e-5));
  double sum = 0;
  for (float d : verifier.distances(T)) sum += d;
  CHECK(sum == Approx(nearest).epsilon(1e-5));
}

TEST_CASE(
    "invalid candidates are never selected; all invalid selects none; ties go to more inliers") {
  const SyntheticScene scene = make_synthetic_scene();
  const Verifier verifier(scene.source, scene.target, 1.0);
  PoseEstimate invalid;
  std::vector<PoseEstimate> c = {invalid, candidate(perturbed(scene.T_target_source, 2.0, 5.0), 5)};
  VerificationResult r = verify_candidates(verifier, c, VerificationParams{});
  CHECK(r.selected == 1);
  CHECK(std::isinf(r.scores[0]));

  r = verify_candidates(verifier, {invalid, invalid}, VerificationParams{});
  CHECK(r.selected == -1);
  CHECK(verify_candidates(verifier, {}, VerificationParams{}).selected == -1);

  c = {candidate(scene.T_target_source, 5), candidate(scene.T_target_source, 9)};
  r = verify_candidates(verifier, c, VerificationParams{});
  CHECK(r.tie);
  CHECK(r.selected == 1);
}

TEST_CASE("an empty target scores every point at mu") {
  PointCloud source, target;
  source.points.assign(10, Eigen::Vector3f::Zero());
  source.points[1].x() = 5;
  const Verifier verifier(source, target, 0.0);
  CHECK(verifier.score(Transform::Identity(), 0.5, ScoreKind::truncated) == Approx(5.0));
}

TEST_CASE("the selection keeps the distances its D summed; a repeated pose is scored once, alike") {
  const SyntheticScene scene = make_synthetic_scene();
  const Verifier verifier(scene.source, scene.target, 0.5);
  const Transform& T = scene.T_target_source;
  const Transform off = perturbed(T, 0.6, 0.0);
  // The true pose twice, the second with more inliers: a tie the inliers break towards index 3.
  const std::vector<PoseEstimate> c = {candidate(off, 10), candidate(T, 10), candidate(off, 10),
                                       candidate(T, 12)};
  VerificationParams vp;
  const VerificationResult r = verify_candidates(verifier, c, vp);
  CHECK(r.selected == 3);
  CHECK(r.tie);
  CHECK(r.scores[0] == r.scores[2]);
  CHECK(r.scores[1] == r.scores[3]);
  CHECK(r.scores[1] == verifier.score(T, vp.mu, vp.score));
  CHECK(r.distance_bound == static_cast<float>(vp.mu));
  CHECK(r.selected_distances == verifier.distances(T, static_cast<float>(vp.mu)));
  double D = 0.0;
  for (float d : r.selected_distances) D += std::min<double>(d, vp.mu);
  CHECK(D == Approx(r.scores[3]).epsilon(1e-12));

  // Selected first by a lower score, then a duplicate of a pose scored earlier wins a tie:
  // its distances are those of that earlier pose.
  const std::vector<PoseEstimate> d = {candidate(T, 10), candidate(off, 10), candidate(T, 11)};
  const VerificationResult s = verify_candidates(verifier, d, vp);
  CHECK(s.selected == 2);
  CHECK(s.selected_distances == verifier.distances(T, static_cast<float>(vp.mu)));
}

TEST_CASE("bounded distances (on the grid) and unbounded ones (kd-tree) equal a linear scan") {
  const SyntheticScene scene = make_synthetic_scene();
  const Verifier verifier(scene.source, scene.target, 0.5);
  const Transform T = perturbed(scene.T_target_source, 0.4, 3.0);
  const auto& src = verifier.source_points();
  const auto& tgt = verifier.target_points();
  const Eigen::Matrix3f R = T.block<3, 3>(0, 0).cast<float>();
  const Eigen::Vector3f t = T.block<3, 1>(0, 3).cast<float>();
  // Larger bounds after smaller ones: the verifier replaces its grid by a coarser one. Bounds of
  // tens of metres or more would put hundreds of points in a cell: those go to the tree, bounded.
  for (float bound :
       {0.3f, 1.0f, 2.5f, 40.0f, 1000.0f, std::numeric_limits<float>::infinity(), 0.5f, 3.0f}) {
    const std::vector<float> d = verifier.distances(T, bound);
    REQUIRE(d.size() == src.size());
    for (std::size_t i = 0; i < src.size(); i += 7) {
      const Eigen::Vector3f q = R * src[i] + t;
      float best = bound * bound;
      for (const auto& p : tgt) best = std::min(best, (p - q).squaredNorm());
      INFO("bound " << bound << " point " << i);
      if (best < bound * bound)
        REQUIRE(d[i] == std::sqrt(best));
      else
        REQUIRE(std::isinf(d[i]));
    }
  }
}

TEST_CASE("distances of flagged points only: theirs as for all points, the others unsearched") {
  const SyntheticScene scene = make_synthetic_scene();
  const Verifier verifier(scene.source, scene.target, 0.5);
  const Transform T = perturbed(scene.T_target_source, 0.4, 3.0);
  const std::size_t n = verifier.source_points().size();
  std::vector<char> only(n, 0);
  for (std::size_t i = 0; i < n; i += 3) only[i] = 1;
  for (float bound : {0.5f, 2.0f, std::numeric_limits<float>::infinity()}) {
    const std::vector<float> all = verifier.distances(T, bound);
    const std::vector<float> some = verifier.distances(T, bound, only);
    REQUIRE(some.size() == n);
    std::size_t found = 0;
    for (std::size_t i = 0; i < n; ++i) {
      INFO("bound " << bound << " point " << i);
      if (only[i]) {
        REQUIRE(some[i] == all[i]);
        found += std::isfinite(some[i]);
      } else {
        REQUIRE(std::isinf(some[i]));
      }
    }
    CHECK(found > 0);
  }
  CHECK_THROWS_AS(verifier.distances(T, 1.0f, std::vector<char>(n + 1, 1)), InputError);
}

TEST_CASE("points counted within a radius are those whose nearest target point is closer") {
  // count_within stops at the first target point it finds; it must count exactly the flagged
  // points whose nearest distance is below the radius, on one thread or several, on the grid and
  // on the kd-tree (a radius too large for a grid).
  const SyntheticScene scene = make_synthetic_scene();
  const Verifier verifier(scene.source, scene.target, 0.5);
  const std::size_t n = verifier.source_points().size();
  std::vector<char> only(n, 0);
  for (std::size_t i = 0; i < n; i += 2) only[i] = 1;
  for (const Transform& T : {scene.T_target_source, perturbed(scene.T_target_source, 0.4, 3.0),
                             Transform(Transform::Identity())})
    for (float radius : {0.25f, 0.5f, 1.0f, 3.0f, 1000.0f}) {
      const Eigen::Matrix3f R = T.block<3, 3>(0, 0).cast<float>();
      const Eigen::Vector3f t = T.block<3, 1>(0, 3).cast<float>();
      std::size_t expected = 0;
      for (std::size_t i = 0; i < n; ++i) {
        if (!only[i]) continue;
        const Eigen::Vector3f q = R * verifier.source_points()[i] + t;
        bool near = false;
        for (const Eigen::Vector3f& p : verifier.target_points())
          near = near || (p - q).squaredNorm() < radius * radius;
        expected += near;
      }
      INFO("radius " << radius);
      CHECK(verifier.count_within(T, radius, only) == expected);
      CHECK(verifier.count_within(T, radius, only, 3) == expected);
      if (radius == 1.0f) CHECK(expected > 0);
    }
  CHECK(verifier.count_within(scene.T_target_source, 1.0f, std::vector<char>(n, 0)) == 0);
  const Verifier two(scene.source, scene.target, 0.5, 2);  // the clouds downsampled at once
  CHECK(two.source_points() == verifier.source_points());
  CHECK(two.target_points() == verifier.target_points());
  CHECK_THROWS_AS(verifier.count_within(Transform::Identity(), 1.0f, std::vector<char>(n + 1, 1)),
                  InputError);
}

TEST_CASE("one verifier searched from several threads at once, with growing bounds, agrees") {
  // The grid is built lazily and replaced by a coarser one when a larger bound comes; threads
  // that still search an older grid must see it intact (run under ThreadSanitizer too).
  const SyntheticScene scene = make_synthetic_scene();
  const Transform T = perturbed(scene.T_target_source, 0.3, 1.0);
  const std::vector<float> bounds = {0.3f, 1.0f,  2.5f,    0.5f,
                                     4.0f, 40.0f, 1000.0f, std::numeric_limits<float>::infinity()};
  std::vector<std::vector<float>> expected;
  {
    const Verifier alone(scene.source, scene.target, 0.5);
    for (float b : bounds) expected.push_back(alone.distances(T, b));
  }
  const Verifier shared(scene.source, scene.target, 0.5);
  std::vector<std::vector<float>> got(bounds.size());
  std::vector<std::thread> pool;
  for (std::size_t k = 0; k < bounds.size(); ++k)
    pool.emplace_back([&, k] { got[k] = shared.distances(T, bounds[k]); });
  for (auto& t : pool) t.join();
  for (std::size_t k = 0; k < bounds.size(); ++k) CHECK(got[k] == expected[k]);
}
