#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <cmath>
#include <tuple>

#include "pagor/io/kitti.hpp"
#include "pagor/pipeline.hpp"
#include "pagor/verify/diagnosis.hpp"
#include "pagor/verify/evaluation.hpp"
#include "pagor/verify/refinement.hpp"
#include "support/test_util.hpp"

using namespace pagor;

namespace {

Pipeline run_pair(int source, int target) {
  const KittiSequence seq(test::kitti_root(), "00");
  Pipeline p;
  p.set_input(seq.load_frame(source).cloud, seq.load_frame(target).cloud);
  p.set_ground_truth(seq.ground_truth(source, target));
  p.run();
  return p;
}

}  // namespace

TEST_CASE("KITTI 0 -> 20 and 20 -> 30 succeed with the default config (2 m / 5 deg)") {
  for (const auto& [s, t] : {std::pair{0, 20}, std::pair{20, 30}}) {
    INFO("pair " << s << " -> " << t);
    const Pipeline p = run_pair(s, t);
    const auto err = p.selected_error();
    REQUIRE(err);
    INFO("errors " << err->translation << " m, " << err->rotation_deg << " deg");
    CHECK(err->success);
    CHECK(p.upper_bound_success());
    CHECK(p.acceptance().accepted);
  }
}

TEST_CASE("KITTI 0 -> 20: a pose that refinement rescues is a success, within the upper bound") {
  // With a 1.34 m criterion every candidate of 0 -> 20 misses (1.35 .. 1.40 m) and the refined
  // selection is right (1.32 m): the upper bound counts it, and the diagnosis says success.
  const KittiSequence seq(test::kitti_root(), "00");
  Config config = default_config();
  config.evaluation.max_translation_error = 1.34;
  Pipeline p(config);
  p.set_input(seq.load_frame(0).cloud, seq.load_frame(20).cloud);
  p.set_ground_truth(seq.ground_truth(0, 20));
  p.run();
  REQUIRE(p.refinement().applied);
  for (const auto& e : p.level_errors()) CHECK_FALSE((e && e->success));
  REQUIRE(p.selected_error());
  CHECK(p.selected_error()->success);
  CHECK(p.upper_bound_success());
  const auto d = diagnose(p);
  REQUIRE(d);
  CHECK(d->verdict == DiagnosisVerdict::success);
  CHECK(d->explanation.find("after refinement") != std::string::npos);
  REQUIRE(d->selected_error);
  CHECK(d->selected_error->translation == p.selected_error()->translation);
}

TEST_CASE("KITTI 20 -> 30 with the source turned about a tilted axis: SE(3), right, accepted") {
  // A handheld or aerial scan is not yaw-only: with the defaults (pose model auto) the tilted
  // ground makes the pair not gravity-aligned, and the poses are fitted in SE(3).
  const KittiSequence seq(test::kitti_root(), "00");
  for (double deg : {30.0, 120.0}) {
    INFO("turned " << deg << " deg");
    const Eigen::Matrix3d R =
        Eigen::AngleAxisd(deg * M_PI / 180, Eigen::Vector3d(0.3, -1, 0.6).normalized())
            .toRotationMatrix();
    PointCloud source = seq.load_frame(20).cloud;
    for (auto& x : source.points) x = (R * x.cast<double>()).cast<float>();
    Transform turn = Transform::Identity();
    turn.block<3, 3>(0, 0) = R;
    Pipeline p;
    p.set_input(std::move(source), seq.load_frame(30).cloud);
    p.set_ground_truth(seq.ground_truth(20, 30) * turn.inverse());
    p.run();
    REQUIRE(p.ground_planes());
    CHECK(p.gnc_params().model == PoseModel::automatic);  // not level: per level
    REQUIRE(p.selected_level() >= 0);
    CHECK(p.poses()[static_cast<std::size_t>(p.selected_level())].model == PoseModel::se3);
    const auto err = p.selected_error();
    REQUIRE(err);
    INFO("errors " << err->translation << " m, " << err->rotation_deg << " deg");
    CHECK(err->success);
    CHECK(p.acceptance().accepted);
  }
  // Level, the same pair keeps 4-DoF poses.
  const Pipeline level = run_pair(20, 30);
  CHECK(level.gnc_params().model == PoseModel::four_dof);
}

TEST_CASE("KITTI: refinement from the ground truth of frame 0 lands on a pose with lower D") {
  // The recorded pose of frame 0 is off: ICP started at the ground truth of 0 -> 20 converges
  // 1.3 m and 1.6 deg away, where D is lower by a fifth; 20 -> 30 stays within 0.1 m. This is
  // why the selected poses of the pairs with frame 0 show 1.3 m errors although they align.
  const KittiSequence seq(test::kitti_root(), "00");
  for (const auto& [s, t, expect_far] : {std::tuple{0, 20, true}, std::tuple{20, 30, false}}) {
    INFO("pair " << s << " -> " << t);
    const PointCloud source = seq.load_frame(s).cloud, target = seq.load_frame(t).cloud;
    const Transform gt = seq.ground_truth(s, t);
    const Verifier verifier(source, target, 0.5);
    Refiner refiner(verifier, 1.0);
    const VerificationParams scoring;
    const RefinementResult r = refiner.refine(gt, verifier.score(gt, scoring.mu, scoring.score),
                                              PoseModel::se3, {}, scoring);
    REQUIRE(r.applied);
    const PoseError moved = pose_error(r.T_after, gt, EvaluationParams{});
    if (expect_far) {
      CHECK(moved.translation > 1.0);
      CHECK(r.score_after < 0.9 * r.score_before);
    } else {
      CHECK(moved.translation < 0.2);
    }
  }
}

TEST_CASE("KITTI 0 -> 30 (26.6 m apart) runs and is reported") {
  const Pipeline p = run_pair(0, 30);
  REQUIRE(p.level_errors().size() == p.cliques().size());
  // Not required to succeed: the selection and its errors exist or the failure is explicit.
  if (p.selected_level() >= 0)
    CHECK(p.selected_error().has_value());
  else
    CHECK_FALSE(p.warnings().empty());
}

TEST_CASE("an unlabelled KITTI pair runs on class-agnostic keypoints and succeeds") {
  const KittiSequence seq(test::kitti_root(), "00");
  PointCloud source = seq.load_frame(20).cloud, target = seq.load_frame(30).cloud;
  source.labels.clear();
  target.labels.clear();
  Pipeline p;
  p.set_input(std::move(source), std::move(target));
  p.set_ground_truth(seq.ground_truth(20, 30));
  p.run();
  const auto& classes = p.source_landmarks().classes;
  REQUIRE(!classes.empty());
  CHECK(classes.back().name == "structure");
  CHECK(classes.back().landmarks > 100);
  const auto err = p.selected_error();
  REQUIRE(err);
  INFO("errors " << err->translation << " m, " << err->rotation_deg << " deg");
  CHECK(err->success);
}

TEST_CASE("KITTI 20 -> 30 georeferenced 300 km from the origin registers like near it") {
  const KittiSequence seq(test::kitti_root(), "00");
  // Both scans moved by the same offset S into a map frame: the pose becomes S T S^-1. Float32
  // holds the moved points to 1/32 m; the clouds near the origin are the moved ones moved back
  // (exactly), so both runs see the same points.
  const Eigen::Vector3f offset(300000.0f, -120000.0f, 40.0f);
  PointCloud source_far = seq.load_frame(20).cloud, target_far = seq.load_frame(30).cloud;
  for (auto& p : source_far.points) p += offset;
  for (auto& p : target_far.points) p += offset;
  PointCloud source = source_far, target = target_far;
  for (auto& p : source.points) p -= offset;
  for (auto& p : target.points) p -= offset;
  Transform S = Transform::Identity();
  S.block<3, 1>(0, 3) = offset.cast<double>();
  const Transform T_gt = seq.ground_truth(20, 30);

  Pipeline near_origin, far;
  near_origin.set_input(std::move(source), std::move(target));
  near_origin.set_ground_truth(T_gt);
  near_origin.run();
  far.set_input(std::move(source_far), std::move(target_far));
  far.set_ground_truth(S * T_gt * S.inverse());
  far.run();

  // Errors in the sensor frame (moved back): in the map frame a rotation error would be counted
  // again as a translation error of 300 km times its angle.
  REQUIRE(near_origin.selected_transform());
  REQUIRE(far.selected_transform());
  const Transform back = S.inverse() * *far.selected_transform() * S;
  const PoseError e_near = pose_error(*near_origin.selected_transform(), T_gt);
  const PoseError e_far = pose_error(back, T_gt);
  CHECK(e_near.success);
  CHECK(e_far.success);
  // Voxel means are stored as float32, which rounds them to 1/32 m out there, and float products
  // place a few points on the other side of a voxel boundary: the landmarks differ slightly
  // (7 of 647 correspondences here); both poses agree to well within the success criterion.
  const double corr_near = static_cast<double>(near_origin.correspondences().items.size());
  const double corr_far = static_cast<double>(far.correspondences().items.size());
  CHECK(std::abs(corr_far - corr_near) <= 0.05 * corr_near);
  const PoseError agreement = pose_error(back, *near_origin.selected_transform());
  CHECK(agreement.translation < 0.5);
  CHECK(agreement.rotation_deg < 1.0);
}
