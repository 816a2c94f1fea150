#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include "pagor/eval/synthetic.hpp"
#include "pagor/pipeline.hpp"
#include "pagor/verify/evaluation.hpp"
#include "pagor/verify/refinement.hpp"

using namespace pagor;

namespace {

constexpr double kPi = 3.14159265358979323846;

// A pose off the truth by a translation [m] and a rotation about `axis` [deg], applied on the left.
Transform perturbed(const Transform& T, const Eigen::Vector3d& dt, const Eigen::Vector3d& axis,
                    double angle_deg) {
  Transform D = Transform::Identity();
  D.block<3, 3>(0, 0) = Eigen::AngleAxisd(angle_deg * kPi / 180.0, axis.normalized()).matrix();
  D.block<3, 1>(0, 3) = dt;
  return D * T;
}

struct Fixture {
  SyntheticScene scene = make_synthetic_scene();
  Verifier verifier{scene.source, scene.target, 0.3};
  Refiner refiner{verifier, 1.0};
  VerificationParams scoring;

  RefinementResult refine(const Transform& start, PoseModel model, const RefinementParams& p) {
    const double D = verifier.score(start, scoring.mu, scoring.score);
    return refiner.refine(start, D, model, p, scoring);
  }
};

}  // namespace

TEST_CASE("refinement brings a nearby pose to the truth and lowers D") {
  Fixture f;
  const Transform start = perturbed(f.scene.T_target_source, {0.5, -0.4, 0.0}, {0, 0, 1}, 2.0);
  RefinementParams params;
  params.max_iterations = 40;
  const RefinementResult r = f.refine(start, PoseModel::se3, params);
  REQUIRE(r.ran);
  CHECK(r.applied);
  CHECK(r.reason.empty());
  CHECK(r.score_after < r.score_before);
  const PoseError before = pose_error(start, f.scene.T_target_source, EvaluationParams{});
  const PoseError after = pose_error(r.T_after, f.scene.T_target_source, EvaluationParams{});
  CHECK(before.translation > 0.5);
  CHECK(after.translation < 0.05);  // the scene's noise is 0.02 m
  CHECK(after.rotation_deg < 0.2);
  CHECK(r.correction_translation == Approx(before.translation).margin(0.1));
  CHECK(f.refiner.normals_estimated() > 0);
  CHECK(f.refiner.normals_estimated() < f.verifier.target_points().size());
}

TEST_CASE("refinement keeps to the pose model") {
  Fixture f;
  const Transform& gt = f.scene.T_target_source;
  // Off by a yaw, a planar shift and a height offset: SE(2) may only undo the first two.
  const Transform start = perturbed(gt, {0.4, 0.3, 0.25}, {0, 0, 1}, 1.5);
  RefinementParams params;
  params.max_iterations = 40;

  SECTION("SE(2) changes yaw and x, y only") {
    const RefinementResult r = f.refine(start, PoseModel::se2, params);
    REQUIRE(r.applied);
    CHECK(r.T_after(2, 3) == Approx(start(2, 3)).margin(1e-9));
    const Eigen::Matrix3d dR = r.T_after.block<3, 3>(0, 0) * start.block<3, 3>(0, 0).transpose();
    CHECK(dR(2, 2) == Approx(1.0).margin(1e-9));  // a rotation about z only
    const PoseError after = pose_error(r.T_after, gt, EvaluationParams{});
    CHECK(after.translation == Approx(0.25).margin(0.05));  // the height offset remains
    CHECK(after.rotation_deg < 0.2);
  }
  SECTION("4-DoF with level roll and pitch keeps them, and corrects the height") {
    params.free_roll_pitch = false;
    const Transform tilted = perturbed(start, Eigen::Vector3d::Zero(), {1, 0, 0}, 1.0);
    const RefinementResult r = f.refine(tilted, PoseModel::four_dof, params);
    REQUIRE(r.applied);
    const Eigen::Matrix3d dR = r.T_after.block<3, 3>(0, 0) * tilted.block<3, 3>(0, 0).transpose();
    CHECK(dR(2, 2) == Approx(1.0).margin(1e-9));
    CHECK(r.T_after(2, 3) == Approx(gt(2, 3)).margin(0.1));
  }
  SECTION("4-DoF with free roll and pitch undoes a tilt") {
    const Transform tilted = perturbed(start, Eigen::Vector3d::Zero(), {1, 0, 0}, 1.0);
    const RefinementResult r = f.refine(tilted, PoseModel::four_dof, params);
    REQUIRE(r.applied);
    CHECK(pose_error(r.T_after, gt, EvaluationParams{}).rotation_deg < 0.2);
  }
}

TEST_CASE("refinement is bounded and keeps the selection when it cannot help") {
  Fixture f;
  const Transform start = perturbed(f.scene.T_target_source, {0.5, 0.0, 0.0}, {0, 0, 1}, 0.0);
  RefinementParams params;

  SECTION("a correction beyond the bound is rejected") {
    params.max_translation = 0.1;
    const RefinementResult r = f.refine(start, PoseModel::se3, params);
    CHECK_FALSE(r.applied);
    CHECK_THAT(r.reason, Catch::Contains("moved the pose"));
    CHECK(r.T_after.isApprox(start));
  }
  SECTION("a pose far from anything finds no pairs") {
    const Transform far = perturbed(start, {500.0, 0.0, 0.0}, {0, 0, 1}, 0.0);
    const RefinementResult r = f.refine(far, PoseModel::se3, params);
    CHECK_FALSE(r.applied);
    CHECK_THAT(r.reason, Catch::Contains("too few point pairs"));
    CHECK(r.iterations == 1);
  }
  SECTION("the truth itself is not made worse") {
    const RefinementResult r = f.refine(f.scene.T_target_source, PoseModel::se3, params);
    const Transform& kept = r.applied ? r.T_after : r.T_before;
    CHECK(pose_error(kept, f.scene.T_target_source, EvaluationParams{}).translation < 0.05);
    if (r.applied) CHECK(r.score_after < r.score_before);
  }
}

TEST_CASE("the pipeline reports refinement and uses the refined pose") {
  SyntheticScene scene = make_synthetic_scene();
  Config config = default_config();
  Pipeline p(config);
  p.set_input(scene.source, scene.target);
  p.set_ground_truth(scene.T_target_source);
  p.run();
  REQUIRE(p.selected_level() >= 0);
  const RefinementResult& r = p.refinement();
  REQUIRE(r.ran);
  const auto sel = static_cast<std::size_t>(p.selected_level());
  CHECK(r.T_before.isApprox(p.poses()[sel].T_target_source));
  CHECK(r.score_before == p.verification().scores[sel]);
  CHECK(p.selected_transform()->isApprox(r.applied ? r.T_after : r.T_before));
  REQUIRE(p.unrefined_error());
  CHECK(p.selected_error()->translation <= p.unrefined_error()->translation + 0.02);

  config.refinement.enabled = false;
  p.set_config(config);
  p.run();
  CHECK_FALSE(p.refinement().ran);
  CHECK(p.selected_transform()->isApprox(p.poses()[sel].T_target_source));

  CHECK_FALSE(preset_config("paper").refinement.enabled);
}
