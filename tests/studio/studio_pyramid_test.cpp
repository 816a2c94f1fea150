// The pyramid panel's figures: the refined pose beside the candidate, labelled, where the eye
// looks; ΔD for a level whose ε was edited; the D gap to a level with another pose, naming the
// levels that found the selected pose again.

#include <algorithm>
#include <catch2/catch.hpp>

#include <Eigen/Geometry>
#include <string>

#include "panels/pyramid_chart.hpp"
#include "state/history.hpp"
#include "studio_test_util.hpp"
#include "ui_driver.hpp"

using namespace pagor;
using namespace pagor::test;

namespace {

Transform moved(double x, double yaw_rad = 0.0) {
  Transform T = Transform::Identity();
  T.block<3, 3>(0, 0) = Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  T(0, 3) = x;
  return T;
}

studio::LevelView level(double epsilon, double score, const Transform& T, bool valid = true) {
  studio::LevelView l;
  l.epsilon = epsilon;
  l.score_D = valid ? score : HUGE_VAL;
  l.pose.valid = valid;
  l.pose.T_target_source = T;
  return l;
}

studio::Snapshot levels_snapshot(const std::vector<studio::LevelView>& levels) {
  studio::Snapshot s;
  s.source = std::make_shared<const PointCloud>();
  s.levels = levels;
  return s;
}

}  // namespace

TEST_CASE("the D gap is to the best level with another pose; levels with the same pose are named") {
  const Transform A = moved(1.0, 0.1), B = moved(3.0, 0.4);
  SECTION("two levels found the selected pose, a third another") {
    const auto s = levels_snapshot(
        {level(0.1, 100, A), level(0.2, 100, A), level(0.3, 150, B), level(0.4, 0, A, false)});
    CHECK(studio::level_gap_text(s) ==
          "D gap to the runner-up pose: 50 m (L0 100.0 m, L2 150.0 m); L1 found the same pose as "
          "L0 (same D)");
  }
  SECTION("every valid level found the same pose") {
    const auto s = levels_snapshot({level(0.1, 80, A), level(0.2, 80, A), level(0.3, 80, A)});
    CHECK(studio::level_gap_text(s) ==
          "D gap to the runner-up pose: n/a (every valid level found the same pose); L1, L2 found "
          "the same pose as L0 (same D)");
  }
  SECTION("a gap under a metre is not rounded to 0 m") {
    const auto s = levels_snapshot({level(0.1, 199.3, A), level(0.2, 199.8, B)});
    CHECK(studio::level_gap_text(s) ==
          "D gap to the runner-up pose: 0.5 m (L0 199.3 m, L1 199.8 m)");
  }
  SECTION("all poses differ: the gap to the second-lowest D, as before") {
    const auto s = levels_snapshot({level(0.1, 120, A), level(0.2, 90, B)});
    CHECK(studio::level_gap_text(s) == "D gap to the runner-up pose: 30 m (L1 90.0 m, L0 120.0 m)");
  }
  CHECK(studio::same_pose(A, moved(1.0 + 0.5 * studio::kSamePoseTranslation, 0.1)));
  CHECK_FALSE(studio::same_pose(A, moved(1.0 + 2 * studio::kSamePoseTranslation, 0.1)));
}

TEST_CASE(
    "ΔD of a level whose ε was edited is against the level it replaced; an inserted one is new") {
  const Transform A = moved(1.0);
  auto before = levels_snapshot({level(0.1, 10, A), level(0.2, 20, A), level(0.3, 30, A)});
  SECTION("edited") {
    auto after = levels_snapshot({level(0.1, 10, A), level(0.25, 18, A), level(0.3, 30, A)});
    const studio::RunChanges c = studio::compare_runs(before, after);
    REQUIRE(c.levels.size() == 3);
    CHECK_FALSE(c.levels[1].added);
    REQUIRE(c.levels[1].d_delta);
    CHECK(*c.levels[1].d_delta == Approx(-2.0));
    REQUIRE(c.levels[1].epsilon_before);
    CHECK(*c.levels[1].epsilon_before == 0.2);
    CHECK_FALSE(c.levels[0].epsilon_before);
  }
  SECTION("inserted") {
    auto after = levels_snapshot(
        {level(0.1, 10, A), level(0.15, 15, A), level(0.2, 20, A), level(0.3, 30, A)});
    const studio::RunChanges c = studio::compare_runs(before, after);
    REQUIRE(c.levels.size() == 4);
    CHECK(c.levels[1].added);
    CHECK_FALSE(c.levels[1].d_delta);
    REQUIRE(c.levels[2].d_delta);
    CHECK(*c.levels[2].d_delta == 0.0);
  }
}

TEST_CASE("the verdict line gives the refined errors and the candidate's, each labelled") {
  auto s = levels_snapshot({level(0.1, 10, moved(1.0))});
  s.selected = 0;
  s.selected_error = PoseError{0.31, 0.8, true};
  s.unrefined_error = PoseError{0.52, 1.1, true};
  s.refinement.ran = s.refinement.applied = true;
  CHECK(studio::selected_text(s) ==
        "selected: SUCCESS (L0), refined 0.31 m / 0.80\xc2\xb0 (candidate before refinement "
        "0.52 m / 1.10\xc2\xb0)");
  s.refinement.applied = false;
  s.selected_error = s.unrefined_error;
  CHECK(studio::selected_text(s) == "selected: SUCCESS (L0), 0.52 m / 1.10\xc2\xb0 (not refined)");
}

#ifdef PAGOR_HAVE_KITTI
TEST_CASE("the selected level's refined pose is a labelled row under its candidate") {
  TempDir tmp;
  studio::AppState s = kitti_state(tmp, 0, 20);
  UiDriver d(s, 1400, 900);
  d.settle();
  const auto snap = d.studio().worker().snapshot();
  REQUIRE(snap);
  REQUIRE(snap->refinement.applied);  // KITTI 0 -> 20: refinement moves the selected pose
  REQUIRE(snap->selected_error);
  const auto rows = d.texts("  refined", "Pyramid");
  REQUIRE(rows.size() == 1);
  // The refined error in the row's cell (a figure of its own), not only in the verdict.
  const std::string refined_t = studio::ui::format("%.2f", snap->selected_error->translation);
  const auto errors = d.texts(refined_t, "Pyramid");
  CHECK(std::count(errors.begin(), errors.end(), refined_t) == 1);
  const auto verdict = d.texts("candidate before refinement", "Pyramid");
  REQUIRE(verdict.size() == 1);
  CHECK(verdict[0].find(studio::ui::format("refined %.2f m", snap->selected_error->translation)) !=
        std::string::npos);
}
#endif
