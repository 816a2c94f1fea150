#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <random>

#include "pagor/pose/gnc.hpp"
#include "pagor/verify/evaluation.hpp"
#include "util/random_draw.hpp"

using namespace pagor;

namespace {

constexpr double kTranslationTol = 0.05;  // [m] with 0.01 m noise on 30 inliers
constexpr double kRotationTolDeg = 0.3;

struct Problem {
  std::vector<Eigen::Vector3d> p, q;
  Transform T = Transform::Identity();
  int inliers = 0;
};

Problem make_problem(int n, double outlier_ratio, PoseModel model, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> coord(-20.0, 20.0);
  std::normal_distribution<double> noise(0.0, 0.01);
  Problem pr;
  if (model == PoseModel::se3)
    pr.T.block<3, 3>(0, 0) =
        Eigen::AngleAxisd(0.9, Eigen::Vector3d(0.3, -0.2, 1).normalized()).toRotationMatrix();
  else
    pr.T.block<3, 3>(0, 0) = Eigen::AngleAxisd(-1.2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  pr.T.block<3, 1>(0, 3) =
      model == PoseModel::se2 ? Eigen::Vector3d(4, -7, 0) : Eigen::Vector3d(4, -7, 1.5);
  pr.inliers = static_cast<int>(n * (1 - outlier_ratio));
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d p = draw3(coord, rng).cwiseQuotient(Eigen::Vector3d(1, 1, 4));
    pr.p.push_back(p);
    if (i < pr.inliers)
      pr.q.push_back(pr.T.block<3, 3>(0, 0) * p + pr.T.block<3, 1>(0, 3) + draw3(noise, rng));
    else
      pr.q.push_back(draw3(coord, rng).cwiseQuotient(Eigen::Vector3d(1, 1, 4)));
  }
  return pr;
}

// GNC-TLS under `model` with a 0.1 m noise bound: a valid estimate within the tolerances of `pr`'s
// planted pose.
PoseEstimate solve_within_tolerance(const Problem& pr, PoseModel model) {
  GncParams params;
  params.model = model;
  params.noise_bound = 0.1;
  const PoseEstimate e = estimate_pose_gnc(pr.p, pr.q, params);
  REQUIRE(e.valid);
  const PoseError err = pose_error(e.T_target_source, pr.T);
  CHECK(err.translation < kTranslationTol);
  CHECK(err.rotation_deg < kRotationTolDeg);
  return e;
}

}  // namespace

TEST_CASE("GNC-TLS recovers a known pose with 70 % outliers, in SE(3) and SE(2)") {
  for (PoseModel model : {PoseModel::se3, PoseModel::se2}) {
    for (std::uint64_t seed : {1u, 2u, 3u, 4u, 5u}) {
      INFO((model == PoseModel::se3 ? "SE(3)" : "SE(2)") << ", seed " << seed);
      const Problem pr = make_problem(100, 0.7, model, seed);
      const PoseEstimate e = solve_within_tolerance(pr, model);
      // The inliers found are the planted ones.
      int planted_found = 0;
      for (int i : e.inliers) planted_found += i < pr.inliers;
      CHECK(planted_found == pr.inliers);
      CHECK(e.inliers.size() <= static_cast<std::size_t>(pr.inliers) + 1);
      if (model == PoseModel::se2) {
        CHECK(e.T_target_source(2, 3) == 0.0);
        CHECK(e.T_target_source(2, 2) == Approx(1.0));
      }
    }
  }
}

TEST_CASE("4-DoF GNC recovers yaw and a 3-D translation, level, from 2 correspondences up") {
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    INFO("seed " << seed);
    const Problem pr = make_problem(100, 0.7, PoseModel::four_dof, seed);
    const PoseEstimate e = solve_within_tolerance(pr, PoseModel::four_dof);
    CHECK(e.T_target_source(2, 3) == Approx(1.5).margin(kTranslationTol));  // height kept
    CHECK(e.T_target_source(2, 2) == Approx(1.0));                          // roll, pitch 0
  }
  // Two correspondences fix a yaw and a translation; one does not.
  const Problem two = make_problem(2, 0.0, PoseModel::four_dof, 9);
  GncParams params;
  params.model = PoseModel::four_dof;
  const PoseEstimate e = estimate_pose_gnc(two.p, two.q, params);
  REQUIRE(e.valid);
  CHECK(pose_error(e.T_target_source, two.T).translation < kTranslationTol);
  const std::vector<Eigen::Vector3d> one_p{two.p[0]}, one_q{two.q[0]};
  CHECK_FALSE(estimate_pose_gnc(one_p, one_q, params).valid);
}

TEST_CASE("without outliers the least-squares pose is exact") {
  const Problem pr = make_problem(10, 0.0, PoseModel::se3, 7);
  const PoseEstimate e = estimate_pose_gnc(pr.p, pr.q, GncParams{});
  REQUIRE(e.valid);
  CHECK(e.inliers.size() == 10);
  CHECK(e.iterations == 0);  // all residuals within the bound: no continuation needed
  CHECK(pose_error(e.T_target_source, pr.T).translation < 0.02);
}

TEST_CASE("too few or degenerate correspondences give an invalid candidate") {
  GncParams se3, se2;
  se2.model = PoseModel::se2;
  const std::vector<Eigen::Vector3d> none;
  CHECK_FALSE(estimate_pose_gnc(none, none, se3).valid);
  const std::vector<Eigen::Vector3d> two{{0, 0, 0}, {1, 0, 0}};
  const PoseEstimate e = estimate_pose_gnc(two, two, se3);
  CHECK_FALSE(e.valid);
  CHECK_THAT(e.failure, Catch::Contains("at least 3"));
  CHECK(estimate_pose_gnc(two, two, se2).valid);  // two distinct points fix a planar pose
  const std::vector<Eigen::Vector3d> line{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}};
  const PoseEstimate c = estimate_pose_gnc(line, line, se3);
  CHECK_FALSE(c.valid);
  CHECK_THAT(c.failure, Catch::Contains("degenerate"));
  const std::vector<Eigen::Vector3d> same{{1, 1, 0}, {1, 1, 0}, {1, 1, 0}};
  CHECK_FALSE(estimate_pose_gnc(same, same, se2).valid);
  const std::vector<Eigen::Vector3d> one{{1, 1, 0}};
  CHECK_FALSE(estimate_pose_gnc(one, one, se2).valid);
  CHECK_FALSE(estimate_pose_gnc(two, one, se2).valid);  // length mismatch
}

TEST_CASE("pose errors against ground truth") {
  Transform truth = Transform::Identity();
  truth.block<3, 1>(0, 3) = Eigen::Vector3d(10, 0, 0);
  Transform est = truth;
  est.block<3, 3>(0, 0) =
      Eigen::AngleAxisd(3.0 * 3.14159265358979 / 180, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  est.block<3, 1>(0, 3) = Eigen::Vector3d(11.5, 0, 0);
  const PoseError e = pose_error(est, truth);
  CHECK(e.translation == Approx(1.5));
  CHECK(e.rotation_deg == Approx(3.0).epsilon(1e-6));
  CHECK(e.success);
  // Euler angles of a known rotation, and the small-pitch branch.
  const Eigen::Matrix3d R = (Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ()) *
                             Eigen::AngleAxisd(-0.1, Eigen::Vector3d::UnitY()) *
                             Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitX()))
                                .toRotationMatrix();
  const Eigen::Vector3d ypr = yaw_pitch_roll_deg(R);
  CHECK(ypr.x() == Approx(0.5 * 180 / 3.14159265358979));
  CHECK(ypr.y() == Approx(-0.1 * 180 / 3.14159265358979));
  CHECK(ypr.z() == Approx(0.2 * 180 / 3.14159265358979));
  CHECK(yaw_pitch_roll_deg(Eigen::Matrix3d::Identity()).norm() == 0.0);
  EvaluationParams strict;
  strict.max_translation_error = 1.0;
  CHECK_FALSE(pose_error(est, truth, strict).success);
}

TEST_CASE("the automatic model: SE(3) for any rotation, 4-DoF where it explains as much") {
  GncParams params;
  params.model = PoseModel::automatic;
  params.noise_bound = 0.1;
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    INFO("seed " << seed);
    // A rotation about a tilted axis: 4-DoF cannot explain it.
    const Problem tilted = make_problem(100, 0.7, PoseModel::se3, seed);
    const PoseEstimate e = estimate_pose_gnc(tilted.p, tilted.q, params);
    REQUIRE(e.valid);
    CHECK(e.model == PoseModel::se3);
    CHECK(pose_error(e.T_target_source, tilted.T).rotation_deg < kRotationTolDeg);
    // A yaw: both explain every inlier; the simpler model is kept.
    const Problem level = make_problem(100, 0.7, PoseModel::four_dof, seed);
    const PoseEstimate f = estimate_pose_gnc(level.p, level.q, params);
    REQUIRE(f.valid);
    CHECK(f.model == PoseModel::four_dof);
    CHECK(pose_error(f.T_target_source, level.T).rotation_deg < kRotationTolDeg);
  }
  // Two correspondences: only 4-DoF can be fitted.
  const Problem two = make_problem(2, 0.0, PoseModel::four_dof, 9);
  const PoseEstimate e = estimate_pose_gnc(two.p, two.q, params);
  REQUIRE(e.valid);
  CHECK(e.model == PoseModel::four_dof);
  CHECK(minimal_sample_size(PoseModel::automatic) == 2);
}
