// Selecting a level without clouds: by what every correspondence says of each candidate.

#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <random>

#include "pagor/verify/level_selection.hpp"

using namespace pagor;

namespace {

constexpr double kBound = 1.0;  // [m]

// 30 correspondences moved by T (within 0.1 m), 10 matched to themselves near the sensor (the
// spurious agreement a near-identity pose explains), 60 unrelated.
struct Scene {
  std::vector<Correspondence> items;
  Transform T = Transform::Identity();
};

Scene scene() {
  Scene s;
  s.T.block<3, 3>(0, 0) = Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  s.T.block<3, 1>(0, 3) = Eigen::Vector3d(20, -3, 0.5);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> far(-40, 40), near(-4, 4), noise(-0.05, 0.05);
  for (int i = 0; i < 100; ++i) {
    Correspondence c;
    if (i < 30) {
      c.p = Eigen::Vector3d(far(rng), far(rng), noise(rng));
      c.q = s.T.block<3, 3>(0, 0) * c.p + s.T.block<3, 1>(0, 3) +
            Eigen::Vector3d::Constant(noise(rng));
    } else if (i < 40) {
      c.p = Eigen::Vector3d(near(rng), near(rng), noise(rng));
      c.q = c.p + Eigen::Vector3d::Constant(noise(rng));
    } else {
      c.p = Eigen::Vector3d(far(rng), far(rng), noise(rng));
      c.q = Eigen::Vector3d(far(rng), far(rng), noise(rng));
    }
    s.items.push_back(c);
  }
  return s;
}

PoseEstimate candidate(const Transform& T, int inliers) {
  PoseEstimate e;
  e.valid = true;
  e.T_target_source = T;
  for (int i = 0; i < inliers; ++i) e.inliers.push_back(i);
  return e;
}

}  // namespace

TEST_CASE("a spurious clique with more GNC inliers loses to the pose every correspondence backs") {
  const Scene s = scene();
  // Level 0: the true pose from a small clique (6 inliers); level 1: identity, 10 inliers.
  const std::vector<PoseEstimate> c = {candidate(s.T, 6), candidate(Transform::Identity(), 10)};
  const VerificationResult r = select_without_clouds(c, s.items, kBound);
  CHECK(r.selected == 0);
  REQUIRE(r.support.size() == 2);
  CHECK(r.support[0] >= 30);
  CHECK(r.support[1] >= 10);
  CHECK(r.support[1] < 20);
  CHECK(r.support_scores[0] < r.support_scores[1]);
  for (double d : r.scores) CHECK(std::isinf(d));  // no D without clouds
}

TEST_CASE("ties go to more GNC inliers, then the lower level; invalid candidates never win") {
  const Scene s = scene();
  PoseEstimate invalid;
  std::vector<PoseEstimate> c = {invalid, candidate(s.T, 5), candidate(s.T, 8), candidate(s.T, 8)};
  VerificationResult r = select_without_clouds(c, s.items, kBound);
  CHECK(r.selected == 2);
  CHECK(std::isinf(r.support_scores[0]));
  CHECK(r.support[0] == 0);
  c = {invalid, invalid};
  r = select_without_clouds(c, s.items, kBound);
  CHECK(r.selected == -1);
  CHECK(select_without_clouds({}, s.items, kBound).selected == -1);
}

TEST_CASE("an SE(2) candidate is judged in the plane") {
  Scene s = scene();
  for (auto& c : s.items) c.q.z() += 5.0;  // a height offset SE(2) does not model
  PoseEstimate planar = candidate(s.T, 6);
  planar.model = PoseModel::se2;
  PoseEstimate spatial = candidate(s.T, 6);
  const VerificationResult r = select_without_clouds({spatial, planar}, s.items, kBound);
  CHECK(r.support[0] == 0);
  CHECK(r.support[1] >= 30);
  CHECK(r.selected == 1);
}

// same_answer_as: the first other eligible, valid candidate within the distinct translation and
// rotation; never the candidate itself, an ineligible or invalid one, or any for an invalid one.
TEST_CASE("the same answer is another eligible candidate's pose within the distinct tolerance") {
  const Scene s = scene();
  Transform near = s.T, moved = s.T, turned = s.T;
  near(0, 3) += 1.0;   // 1 m: the same answer at 2 m
  moved(0, 3) += 3.0;  // 3 m: distinct
  turned.block<3, 3>(0, 0) =
      Eigen::AngleAxisd(0.4 + 0.2, Eigen::Vector3d::UnitZ()).toRotationMatrix();  // 11.5 deg
  const EvaluationParams distinct{2.0, 5.0};
  PoseEstimate invalid;
  invalid.T_target_source = s.T;  // the same pose, but no valid candidate
  const std::vector<PoseEstimate> c = {candidate(moved, 4), candidate(turned, 4), invalid,
                                       candidate(near, 4), candidate(s.T, 9)};
  const std::vector<char> all(c.size(), 1);
  CHECK(same_answer_as(c, 4, all, distinct) == 3);  // not itself, not the invalid one
  CHECK(same_answer_as(c, 3, all, distinct) == 4);
  CHECK(same_answer_as(c, 0, all, distinct) == -1);  // 3 m from every other
  CHECK(same_answer_as(c, 1, all, distinct) == -1);  // turned away from every other
  CHECK(same_answer_as(c, 2, all, distinct) == -1);  // an invalid candidate has no answer
  std::vector<char> some = all;
  some[3] = 0;  // not eligible (e.g. not settled)
  CHECK(same_answer_as(c, 4, some, distinct) == -1);
  CHECK(same_answer_as(c, 4, all, EvaluationParams{0.5, 5.0}) == -1);  // tighter: distinct
}
