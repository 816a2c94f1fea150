// The one-call entry and the one result type (registration.hpp): a pair registered in one call
// reads as a typed result, equal to the Pipeline's; poses in the frames of the points as given;
// the JSON report written from the result.

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "pagor/errors.hpp"
#include "pagor/eval/association_problem.hpp"
#include "pagor/eval/synthetic.hpp"
#include "pagor/io/clouds.hpp"
#include "pagor/pipeline.hpp"
#include "pagor/registration.hpp"
#include "pagor/report.hpp"

using namespace pagor;

namespace {

constexpr double kSameTransform = 1e-9;  // two runs of the same inputs: the same numbers

double max_difference(const Transform& a, const Transform& b) {
  return (a - b).cwiseAbs().maxCoeff();
}

}  // namespace

TEST_CASE("register_clouds registers the generated scene in one call") {
  SyntheticScene scene = make_synthetic_scene();
  RegisterOptions options;
  options.ground_truth = scene.T_target_source;
  const Registration r = register_clouds(scene.source, scene.target, default_config(), options);
  REQUIRE(r.T_target_source);
  CHECK(r.accepted());
  CHECK(r.succeeded());
  CHECK_FALSE(r.accepted_wrong());
  CHECK(r.selected_by == SelectedBy::score_D);
  REQUIRE(r.levels.size() == default_config().graph.thresholds.size());
  const LevelSummary& selected = r.levels[static_cast<std::size_t>(r.selected_level)];
  CHECK(selected.clique.size() >= 3);
  CHECK(selected.pose.valid);
  CHECK(std::isfinite(selected.score_D));
  REQUIRE(r.error);
  CHECK(r.error->translation < default_config().evaluation.max_translation_error);
  REQUIRE(r.diagnosis);
  CHECK(r.diagnosis->verdict == DiagnosisVerdict::success);
  CHECK(r.total_ms > 0);
  CHECK(r.verification_points > 0);
  std::size_t landmarks = 0;
  for (const ClassCount& c : r.classes) landmarks += c.source;
  CHECK(landmarks > 0);
}

TEST_CASE("the one call gives what the pipeline gives") {
  SyntheticScene scene = make_synthetic_scene();
  Pipeline p;
  p.set_input(scene.source, scene.target);
  p.set_ground_truth(scene.T_target_source);
  p.run();
  const Registration from_pipeline = make_registration(p);
  RegisterOptions options;
  options.ground_truth = scene.T_target_source;
  const Registration one_call =
      register_clouds(scene.source, scene.target, default_config(), options);
  REQUIRE(from_pipeline.T_target_source);
  REQUIRE(one_call.T_target_source);
  CHECK(max_difference(*from_pipeline.T_target_source, *one_call.T_target_source) < kSameTransform);
  CHECK(from_pipeline.selected_level == one_call.selected_level);
  REQUIRE(from_pipeline.levels.size() == one_call.levels.size());
  for (std::size_t l = 0; l < one_call.levels.size(); ++l)
    CHECK(from_pipeline.levels[l].clique == one_call.levels[l].clique);
  CHECK(from_pipeline.acceptance.accepted == one_call.acceptance.accepted);
  CHECK(from_pipeline.acceptance.reason == one_call.acceptance.reason);
}

TEST_CASE("poses are in the frames of the points as given, origins included") {
  // The same scene, each cloud kept relative to a georeferenced origin (as load_cloud keeps a
  // file whose points lie kilometres out): the transform between the files' frames is the scene's
  // moved by the origins.
  SyntheticScene scene = make_synthetic_scene();
  const Eigen::Vector3d source_origin(312000.0, 4215000.0, 20.0);
  const Eigen::Vector3d target_origin(312010.0, 4215003.0, 21.0);
  scene.source.origin = source_origin;
  scene.target.origin = target_origin;
  const Transform truth_files = to_file_frames(scene.T_target_source, source_origin, target_origin);
  RegisterOptions options;
  options.ground_truth = truth_files;
  const Registration r = register_clouds(scene.source, scene.target, default_config(), options);
  REQUIRE(r.T_target_source);
  CHECK(r.succeeded());
  REQUIRE(r.T_target_source_gt);
  CHECK(max_difference(*r.T_target_source_gt, truth_files) < 1e-6);
  // Judged between the clouds' frames (a file frame's lever arm of kilometres would turn a
  // hundredth of a degree into metres), the poses are the scene's.
  const auto in_clouds = [&](const Transform& T) {
    return to_cloud_frames(T, source_origin, target_origin);
  };
  CHECK(pose_error(in_clouds(*r.T_target_source), scene.T_target_source).success);
  const LevelSummary& selected = r.levels[static_cast<std::size_t>(r.selected_level)];
  CHECK(pose_error(in_clouds(selected.pose.T_target_source), scene.T_target_source).success);
}

TEST_CASE("register_correspondences without clouds selects without verifying") {
  AssociationParams a;
  a.m = 300;
  a.inlier_ratio = 0.2;
  a.seed = 3;
  const AssociationProblem problem = association_problem(a);
  Config config = default_config();
  config.graph = association_graph_params();
  RegisterOptions options;
  options.ground_truth = problem.T_target_source;
  const Registration r = register_correspondences(problem.correspondences, config, options);
  CHECK(r.selected_by == SelectedBy::without_clouds);
  CHECK_FALSE(r.acceptance.verified);
  CHECK_FALSE(r.accepted());  // nothing to verify on: neither accepted nor rejected on evidence
  REQUIRE(r.T_target_source);
  CHECK(r.succeeded());
  CHECK(r.origin_all.matcher == 300);
  CHECK(r.origin_all.landmark == 0);
  for (const LevelSummary& l : r.levels) CHECK(l.support.has_value());
}

TEST_CASE("the report is written from the result") {
  SyntheticScene scene = make_synthetic_scene();
  RegisterOptions options;
  options.ground_truth = scene.T_target_source;
  options.source_name = "scan A";
  const Registration r = register_clouds(scene.source, scene.target, default_config(), options);
  const nlohmann::json j = nlohmann::json::parse(to_json(r));
  CHECK(j["schema"] == "pagor.register/1");
  CHECK(j["source"] == "scan A");
  CHECK(j["selected_level"] == r.selected_level);
  CHECK(j["acceptance"]["accepted"] == r.acceptance.accepted);
  CHECK(j["ground_truth"]["success"] == r.succeeded());
  CHECK(j["diagnosis"]["verdict"] == verdict_name(r.diagnosis->verdict));
  CHECK(j["levels"].size() == r.levels.size());
  for (int row = 0; row < 4; ++row)
    for (int col = 0; col < 4; ++col)
      CHECK(j["T_target_source"][row][col].get<double>() == Approx((*r.T_target_source)(row, col)));
  CHECK(j.contains("config"));
  CHECK_FALSE(nlohmann::json::parse(to_json(r, -1, false)).contains("config"));
  // An indent is a number of spaces, clamped: no indent makes a line longer than the data.
  const std::string wide = to_json(r, 1 << 30);
  CHECK(wide.size() < 20 * to_json(r, 1).size());
}

TEST_CASE("the one call refuses bad inputs with the project's errors") {
  SyntheticScene empty = make_synthetic_scene();
  empty.target.points.clear();
  empty.target.labels.clear();
  CHECK_THROWS_WITH(register_clouds(empty.source, empty.target),
                    Catch::Contains("target: the cloud has no points"));
  Config config = default_config();
  config.verification.mu = -1.0;
  SyntheticScene scene = make_synthetic_scene();
  CHECK_THROWS_AS(register_clouds(scene.source, scene.target, config), ConfigError);
}
