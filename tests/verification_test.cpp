#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <random>

#include "pagor/synthetic.hpp"
#include "pagor/verification.hpp"

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
  for (int i = 0; i < 200; ++i) source.points.emplace_back(u(rng), u(rng), u(rng));
  for (int i = 0; i < 300; ++i) target.points.emplace_back(u(rng), u(rng), u(rng));
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
