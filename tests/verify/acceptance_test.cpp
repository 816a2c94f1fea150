#include <catch2/catch.hpp>

#include "pagor/verify/acceptance.hpp"
#include "pagor/front/landmarks.hpp"
#include "pagor/pipeline.hpp"
#include "pagor/sets/synthetic.hpp"

using namespace pagor;

namespace {

SyntheticScene scene_with_seed(std::uint64_t seed) {
  SyntheticParams p;
  p.seed = seed;
  return make_synthetic_scene(p);
}

}  // namespace

TEST_CASE("the ground layer is found under the structure") {
  std::vector<Eigen::Vector3f> points;
  for (int x = 0; x < 50; ++x)
    for (int y = 0; y < 50; ++y) points.emplace_back(0.2f * x, 0.2f * y, -1.73f);    // ground
  for (int z = 0; z < 100; ++z) points.emplace_back(3.0f, 3.0f, -1.5f + 0.05f * z);  // a pole
  const float top = ground_layer_top(points, 0.4f);
  CHECK(top > -1.73f);
  CHECK(top == Approx(-1.6f + 0.4f).margin(0.2f + 1e-4f));  // bin edge above -1.73, + thickness
  CHECK(ground_layer_top({}, 0.4f) < -1e30f);
}

TEST_CASE("a true pair is accepted, two scenes that share nothing are rejected") {
  const SyntheticScene a = scene_with_seed(7), b = scene_with_seed(8);

  Pipeline positive;
  positive.set_input(a.source, a.target);
  positive.set_ground_truth(a.T_target_source);
  positive.run();
  REQUIRE(positive.selected_error());
  CHECK(positive.selected_error()->success);
  const Acceptance& yes = positive.acceptance();
  INFO("positive: overlap " << yes.overlap << ", inliers " << yes.inliers << ", " << yes.reason);
  CHECK(yes.accepted);
  CHECK(yes.overlap >= positive.config().acceptance.min_overlap);
  CHECK(yes.reason.empty());

  Pipeline negative;
  negative.set_input(a.source, b.target);
  negative.run();
  const Acceptance& no = negative.acceptance();
  INFO("negative: overlap " << no.overlap << ", inliers " << no.inliers << ", " << no.reason);
  CHECK_FALSE(no.accepted);
  CHECK_FALSE(no.reason.empty());
  CHECK(no.overlap < yes.overlap);

  // Acceptance reuses the distances the verification kept; searching afresh judges alike.
  for (const Pipeline* p : {&positive, &negative}) {
    VerificationResult fresh = p->verification();
    fresh.selected_distances.clear();
    const Config& c = p->config();
    std::vector<PoseEstimate> candidates = p->poses();
    REQUIRE(fresh.selected >= 0);
    const auto sel = static_cast<std::size_t>(fresh.selected);
    if (p->refinement().applied) {
      candidates[sel].T_target_source = p->refinement().T_after;
      fresh.scores[sel] = p->refinement().score_after;
    }
    const Acceptance again = judge_selection(*p->verifier(), candidates, fresh, c.verification,
                                             c.evaluation, c.acceptance, c.gnc.model);
    CHECK(again.overlap == p->acceptance().overlap);
    CHECK(again.margin == p->acceptance().margin);
    CHECK(again.accepted == p->acceptance().accepted);
  }
}

TEST_CASE("thresholds decide the verdict, and a change re-judges without re-running the rest") {
  const SyntheticScene a = scene_with_seed(7);
  Pipeline p;
  p.set_input(a.source, a.target);
  p.run();
  REQUIRE(p.acceptance().accepted);
  const int verification_runs = p.runs(Stage::verification);
  Config c = p.config();
  c.acceptance.min_inliers = p.acceptance().inliers + 1;
  p.set_config(c);
  p.run();
  CHECK(p.runs(Stage::verification) == verification_runs);
  CHECK_FALSE(p.acceptance().accepted);
  CHECK_THAT(p.acceptance().reason, Catch::Contains("inliers"));
  c.acceptance.min_inliers = 0;
  c.acceptance.min_overlap = 0.99;
  p.set_config(c);
  p.run();
  CHECK_FALSE(p.acceptance().accepted);
  CHECK_THAT(p.acceptance().reason, Catch::Contains("overlap"));
}

TEST_CASE("no valid candidate is never accepted") {
  Verifier verifier(PointCloud{}, PointCloud{}, 0.5);
  std::vector<PoseEstimate> candidates(2);  // both invalid
  VerificationResult none;
  none.scores.assign(2, HUGE_VAL);
  const Acceptance a = judge_selection(verifier, candidates, none, {}, {}, {}, PoseModel::se3);
  CHECK_FALSE(a.accepted);
  CHECK(a.reason == "no valid candidate");
}
