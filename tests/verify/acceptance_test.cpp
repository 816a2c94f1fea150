#include <catch2/catch.hpp>

#include "pagor/front/landmarks.hpp"
#include "pagor/pipeline.hpp"
#include "pagor/sets/synthetic.hpp"
#include "pagor/verify/acceptance.hpp"

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

TEST_CASE("a pose that aligns only the ground of a sloped street is not trusted") {
  // Two scans that share nothing but a street climbing at 8 % (boards on opposite sides of it):
  // the identity lays the road onto itself and aligns nothing else. With a single height layer
  // half of the climbing road counted as structure, and a scene of little structure was judged on
  // all its points: either made such a pose look aligned.
  PointCloud source, target;
  const auto road = [](double x) { return static_cast<float>(0.08 * x - 1.7); };
  for (double x = -40; x < 40; x += 0.3)
    for (double y = -8; y < 8; y += 0.3) {
      source.points.emplace_back(x, y, road(x));
      target.points.emplace_back(x, y, road(x));
    }
  for (int k = 0; k < 12; ++k)  // 2 m boards: the source's along one side, the target's the other
    for (double u = 0; u < 2.0; u += 0.1)
      for (double z = 0.5; z < 3.0; z += 0.1) {
        const double xs = -33.0 + 6.0 * k + u, xt = xs + 3.0;
        source.points.emplace_back(xs, 7.0, road(xs) + z);
        target.points.emplace_back(xt, -7.0, road(xt) + z);
      }
  const Verifier verifier(source, target, 0.3);
  std::vector<PoseEstimate> candidates(1);
  candidates[0].valid = true;
  candidates[0].T_target_source = Transform::Identity();  // the road aligned onto itself
  candidates[0].inliers = {0, 1, 2, 3, 4};
  VerificationResult v;
  v.selected = 0;
  v.scores = {verifier.score(Transform::Identity(), 1.0, ScoreKind::truncated)};
  const Config c = default_config();
  const Acceptance a = judge_selection(verifier, candidates, v, c.verification, c.evaluation,
                                       c.acceptance, c.gnc.model);
  INFO("overlap " << a.overlap << ": " << a.reason);
  CHECK(a.overlap < 0.05);  // of the boards, none aligned
  CHECK_FALSE(a.accepted);
  CHECK_THAT(a.reason, Catch::StartsWith("overlap"));
}
