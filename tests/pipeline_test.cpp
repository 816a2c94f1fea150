#include <array>
#include <catch2/catch.hpp>

#include "pagor/errors.hpp"
#include "pagor/eval/synthetic.hpp"
#include "pagor/pipeline.hpp"
#include "pagor/registration.hpp"

using namespace pagor;

namespace {

std::array<int, kStageCount> runs(const Pipeline& p) {
  std::array<int, kStageCount> r{};
  for (int s = 0; s < kStageCount; ++s)
    r[static_cast<std::size_t>(s)] = p.runs(static_cast<Stage>(s));
  return r;
}

// Which stages ran between two snapshots.
std::vector<Stage> ran(const std::array<int, kStageCount>& before,
                       const std::array<int, kStageCount>& after) {
  std::vector<Stage> out;
  for (int s = 0; s < kStageCount; ++s)
    if (after[static_cast<std::size_t>(s)] != before[static_cast<std::size_t>(s)])
      out.push_back(static_cast<Stage>(s));
  return out;
}

// Edits a copy of p's configuration, sets it and runs: the stages that ran again.
template <class Edit>
std::vector<Stage> ran_after(Pipeline& p, const Edit& edit) {
  const auto before = runs(p);
  Config c = p.config();
  edit(c);
  p.set_config(c);
  p.run();
  return ran(before, runs(p));
}

Pipeline synthetic_pipeline() {
  SyntheticScene scene = make_synthetic_scene();
  Pipeline p;
  p.set_input(std::move(scene.source), std::move(scene.target));
  p.set_ground_truth(scene.T_target_source);
  return p;
}

}  // namespace

TEST_CASE("the pipeline registers the synthetic scene") {
  Pipeline p = synthetic_pipeline();
  p.run();
  CHECK(p.up_to_date());
  REQUIRE(p.selected_level() >= 0);
  const auto err = p.selected_error();
  REQUIRE(err);
  CHECK(err->success);
  CHECK(err->translation < 0.2);
  CHECK(p.upper_bound_success());
  CHECK(p.cliques().size() == p.config().graph.thresholds.size());
  CHECK(p.level_errors().size() == p.cliques().size());
}

TEST_CASE("a change re-runs only the stages it invalidates") {
  Pipeline p = synthetic_pipeline();
  p.run();
  auto before = runs(p);
  for (int s = 0; s < kStageCount; ++s) CHECK(before[static_cast<std::size_t>(s)] == 1);

  SECTION("mu: scoring and evaluation") {
    CHECK(ran_after(p, [](Config& c) { c.verification.mu = 0.5; }) ==
          std::vector<Stage>{Stage::verification, Stage::refinement, Stage::acceptance,
                             Stage::evaluation});
  }
  SECTION("a threshold: graph and everything after it but the metric clouds") {
    CHECK(ran_after(p, [](Config& c) { c.graph.thresholds[1] = 0.05; }) ==
          std::vector<Stage>{Stage::graph, Stage::clique, Stage::gnc, Stage::verification,
                             Stage::refinement, Stage::acceptance, Stage::evaluation});
  }
  SECTION("a clustering parameter: everything but the metric clouds") {
    CHECK(ran_after(p, [](Config& c) { c.landmarks.classes[0].cluster_tolerance = 0.6; }) ==
          std::vector<Stage>{Stage::landmarks, Stage::correspondences, Stage::graph, Stage::clique,
                             Stage::gnc, Stage::verification, Stage::refinement, Stage::acceptance,
                             Stage::evaluation});
  }
  SECTION("the verification voxel: metric clouds, scoring and evaluation") {
    CHECK(ran_after(p, [](Config& c) { c.verification.voxel_size = 0.7; }) ==
          std::vector<Stage>{Stage::verification_prep, Stage::verification, Stage::refinement,
                             Stage::acceptance, Stage::evaluation});
  }
  SECTION("GNC parameters: pose and after") {
    CHECK(ran_after(p, [](Config& c) { c.gnc.noise_bound = 0.8; }) ==
          std::vector<Stage>{Stage::gnc, Stage::verification, Stage::refinement, Stage::acceptance,
                             Stage::evaluation});
  }
  SECTION("refinement parameters: refinement and after") {
    CHECK(ran_after(p, [](Config& c) { c.refinement.max_iterations = 5; }) ==
          std::vector<Stage>{Stage::refinement, Stage::acceptance, Stage::evaluation});
  }
  SECTION("ground truth: evaluation only") {
    p.set_ground_truth(std::nullopt);
    p.run();
    CHECK(ran(before, runs(p)) == std::vector<Stage>{Stage::evaluation});
    CHECK(p.level_errors().empty());
    CHECK_FALSE(p.selected_error());
  }
  SECTION("an unchanged config runs nothing") {
    p.set_config(p.config());
    p.run();
    CHECK(ran(before, runs(p)).empty());
  }
  SECTION("an invalid config is rejected and the old one kept") {
    Config c = p.config();
    c.verification.mu = -1;
    CHECK_THROWS_AS(p.set_config(c), ConfigError);
    CHECK(p.config().verification.mu > 0);
    CHECK(p.up_to_date());
  }
}

TEST_CASE("a cancelled run throws, keeps finished stages, and resumes") {
  Pipeline p = synthetic_pipeline();
  std::atomic<bool> cancel{false};
  int calls = 0;
  CHECK_THROWS_AS(p.run(
                      [&](Stage s, double) {
                        ++calls;
                        if (s == Stage::graph) cancel = true;  // cancel while the graph is built
                      },
                      &cancel),
                  Cancelled);
  CHECK(p.runs(Stage::landmarks) == 1);
  CHECK(p.runs(Stage::graph) == 1);
  CHECK(p.runs(Stage::clique) == 0);
  CHECK(p.stale(Stage::clique));
  cancel = false;
  p.run();
  CHECK(p.up_to_date());
  CHECK(p.runs(Stage::landmarks) == 1);
  CHECK(p.runs(Stage::clique) == 1);
  CHECK(calls >= 3);
}

TEST_CASE("running without input is an error") {
  Pipeline p;
  CHECK_THROWS_AS(p.run(), InputError);
}

TEST_CASE("the JSON report carries the documented top-level keys") {
  Pipeline p = synthetic_pipeline();
  p.run();
  const std::string json = to_json(make_registration(p, {"s", "t"}));
  for (const char* key :
       {"\"T_target_source\"", "\"timings_ms\"", "\"levels\"", "\"selected_level\"",
        "\"ground_truth\"", "\"schema\": \"pagor.register/1\"", "\"clique\""})
    CHECK_THAT(json, Catch::Contains(key));
}

TEST_CASE("two threads give the same result as one") {
  // The parallel paths: both clouds' landmarks at once, graph rows and verification split over
  // threads. Also what the ThreadSanitizer run exercises (README, Development).
  SyntheticScene scene = make_synthetic_scene();
  Pipeline one(default_config(), 1), two(default_config(), 2);
  one.set_input(scene.source, scene.target);
  two.set_input(scene.source, scene.target);
  one.run();
  two.run();
  CHECK(two.source_landmarks().landmarks.size() == one.source_landmarks().landmarks.size());
  CHECK(two.target_landmarks().landmarks.size() == one.target_landmarks().landmarks.size());
  CHECK(two.correspondences().items.size() == one.correspondences().items.size());
  CHECK(two.graph().edges_at_level == one.graph().edges_at_level);
  CHECK(two.verification().scores == one.verification().scores);
  CHECK(two.selected_level() == one.selected_level());
  REQUIRE(one.selected_transform());
  CHECK(two.selected_transform()->isApprox(*one.selected_transform()));
}
