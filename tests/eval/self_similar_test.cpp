#include <catch2/catch.hpp>

#include <cstdio>
#include <cstdlib>
#include <map>
#include <optional>

#include "pagor/pipeline.hpp"

#include "pagor/eval/self_similar.hpp"
#include "pagor/verify/evaluation.hpp"
#include "pagor/verify/verification.hpp"

using namespace pagor;

namespace {

// A source point moved onto the target sample it was drawn from (noise 0.02 m on each side).
constexpr float kSameSample = 0.15f;
// A source point moved onto the repeated structure, between its samples: floors are sampled every
// 0.6 m, so a shift by a period that is no multiple of it leaves up to 0.42 m to the nearest.
constexpr float kOnStructure = 0.5f;
// Points nearer the target sensor than this are seen by the target in every kind (ranges 30-40 m).
constexpr double kSeen = 29.0;

// The share of source points with `label` (any when `label` < 0) that `T` puts within `close` of
// a target point, among those it puts where the target sees.
double aligned(const SelfSimilarScene& s, const Transform& T, int label, float close) {
  const Verifier verifier(s.source, s.target, 0.0);  // no downsampling: the points as given
  REQUIRE(verifier.source_points().size() == s.source.size());
  const std::vector<float> d = verifier.distances(T, close);
  std::size_t near = 0, counted = 0;
  for (std::size_t i = 0; i < d.size(); ++i) {
    if (label >= 0 &&
        (s.source.labels.empty() || s.source.labels[i] != static_cast<std::uint32_t>(label)))
      continue;
    const Eigen::Vector3d q =
        T.block<3, 3>(0, 0) * s.source.points[i].cast<double>() + T.block<3, 1>(0, 3);
    if (q.head<2>().norm() > kSeen) continue;
    ++counted;
    near += d[i] <= close;
  }
  return counted ? static_cast<double>(near) / static_cast<double>(counted) : 0.0;
}

bool has_label(const PointCloud& c, std::uint32_t label) {
  for (std::uint32_t l : c.labels)
    if (l == label) return true;
  return false;
}

SelfSimilarParams params(SelfSimilarKind kind, std::uint64_t seed, bool objects, bool labelled) {
  SelfSimilarParams p;
  p.kind = kind;
  p.seed = seed;
  p.distinct_objects = objects;
  p.labelled = labelled;
  return p;
}

const SelfSimilarKind kKinds[] = {SelfSimilarKind::corridor, SelfSimilarKind::facades,
                                  SelfSimilarKind::sliding_street, SelfSimilarKind::symmetric_hall};

}  // namespace

TEST_CASE("the truth maps the source onto the target in every kind of self-similar scene") {
  for (SelfSimilarKind kind : kKinds)
    for (std::uint64_t seed : {1u, 2u}) {
      const SelfSimilarScene s = make_self_similar_scene(params(kind, seed, true, true));
      INFO(s.name);
      CHECK(aligned(s, s.T_target_source, -1, kSameSample) > 0.97);
      // The truth is not the identity: the sensors are 6 m or more apart.
      CHECK(s.T_target_source.block<3, 1>(0, 3).norm() >= 6.0);
    }
}

TEST_CASE("the look-alikes align the repeated scene, not its distinct objects") {
  for (SelfSimilarKind kind : kKinds) {
    const SelfSimilarScene plain = make_self_similar_scene(params(kind, 3, false, true));
    const SelfSimilarScene marked = make_self_similar_scene(params(kind, 3, true, true));
    INFO(plain.name);
    REQUIRE(plain.look_alikes.size() == (kind == SelfSimilarKind::symmetric_hall ? 1u : 5u));
    REQUIRE(plain.look_alikes.size() == marked.look_alikes.size());
    const EvaluationParams criterion;
    for (std::size_t k = 0; k < plain.look_alikes.size(); ++k) {
      INFO("look-alike " << k);
      // A look-alike is wrong by the success criterion ...
      CHECK_FALSE(pose_error(plain.look_alikes[k], plain.T_target_source, criterion).success);
      // ... yet puts the repeated structure onto itself wherever the target sees ...
      CHECK(aligned(plain, plain.look_alikes[k], -1, kOnStructure) > 0.97);
      // ... but not the car, which the truth aligns.
      CHECK(aligned(marked, marked.T_target_source, 0, kSameSample) > 0.97);
      // (On its own samples: its lowest rows lie within kOnStructure of the floor anywhere.)
      CHECK(aligned(marked, marked.look_alikes[k], 0, kSameSample) < 0.1);
    }
  }
}

TEST_CASE("self-similar scenes are reproducible from their seed") {
  for (SelfSimilarKind kind : kKinds) {
    const SelfSimilarScene a = make_self_similar_scene(params(kind, 5, true, true));
    const SelfSimilarScene b = make_self_similar_scene(params(kind, 5, true, true));
    const SelfSimilarScene c = make_self_similar_scene(params(kind, 6, true, true));
    INFO(a.name);
    REQUIRE(a.source.size() == b.source.size());
    REQUIRE(a.target.size() == b.target.size());
    CHECK(a.source.points == b.source.points);
    CHECK(a.target.labels == b.target.labels);
    CHECK(a.T_target_source == b.T_target_source);
    CHECK(a.period == b.period);
    CHECK_FALSE(a.T_target_source.isApprox(c.T_target_source, 1e-6));
  }
}

TEST_CASE("distinct objects and labels are there only when asked for") {
  for (SelfSimilarKind kind : kKinds)
    for (bool objects : {false, true}) {
      const SelfSimilarScene s = make_self_similar_scene(params(kind, 4, objects, true));
      const SelfSimilarScene xyz = make_self_similar_scene(params(kind, 4, objects, false));
      INFO(s.name);
      CHECK(xyz.source.labels.empty());
      CHECK(xyz.target.labels.empty());
      CHECK(xyz.source.size() == s.source.size());  // the same points, without labels
      CHECK(xyz.T_target_source == s.T_target_source);
      CHECK(s.source.labels.size() == s.source.size());
      CHECK(has_label(s.target, 12));  // walls or facades: building
      CHECK(has_label(s.target, 8));   // the floor: road
      CHECK(s.objects.size() == (objects ? 3u : 0u));
      for (std::uint32_t label : {0u, 18u, 13u}) {  // car, traffic-sign, bench (fence)
        CHECK(has_label(s.source, label) == objects);
        CHECK(has_label(s.target, label) == objects);
      }
      for (const SyntheticObject& o : s.objects) CHECK((o.in_source && o.in_target));
    }
  // The periods: pillars every 3-8 m, buildings 10-18 m; the sliding street and the hall none.
  const auto period = [](SelfSimilarKind kind, std::uint64_t seed) {
    return make_self_similar_scene(params(kind, seed, false, true)).period;
  };
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    CHECK(period(SelfSimilarKind::corridor, seed) >= 3.0);
    CHECK(period(SelfSimilarKind::corridor, seed) <= 8.0);
    CHECK(period(SelfSimilarKind::facades, seed) >= 10.0);
    CHECK(period(SelfSimilarKind::facades, seed) <= 18.0);
    CHECK(period(SelfSimilarKind::sliding_street, seed) == 0.0);
    CHECK(period(SelfSimilarKind::symmetric_hall, seed) == 0.0);
  }
  CHECK(self_similar_set(2).size() == 32u);
}

TEST_CASE("a labelled corridor names its numbering, and a run left to detect it warns") {
  // Pillars labelled trunk are half a corridor's points: detection takes the training numbering
  // for the learning map (trunk read as vegetation) by a fraction of a nat, so the generator's
  // manifest says kSelfSimilarLabelScheme, and a run left to detect it warns.
  const SelfSimilarScene s =
      make_self_similar_scene(params(SelfSimilarKind::corridor, 1, true, true));
  const auto doubts = [](const Pipeline& p) {
    int n = 0;
    for (const std::string& w : p.warnings()) n += w.find("fits them almost as well") != w.npos;
    return n;
  };
  const auto landmarks_of = [](const Pipeline& p, const std::string& name) {
    for (const ClassSummary& c : p.source_landmarks().classes)
      if (c.name == name) return c.landmarks;
    return std::size_t{0};
  };
  Pipeline guessed;
  guessed.set_input(s.source, s.target);
  guessed.run();
  CHECK(guessed.source_landmarks().labels.scheme.name == "semantickitti-learning");
  CHECK(doubts(guessed) == 2);  // both clouds
  CHECK(landmarks_of(guessed, "trunk") == 0);
  Pipeline told;
  told.set_input(s.source, s.target, builtin_label_scheme(kSelfSimilarLabelScheme));
  told.run();
  CHECK(doubts(told) == 0);
  // Read in their own numbering, the pillars are trunk landmarks and the car is a car.
  CHECK(landmarks_of(told, "trunk") >= 10);
  CHECK(landmarks_of(told, "car") == 1);
}

// The verdict on the set, scored against the truth (pose error and verdict): one row per scene
// and a summary per kind and variant. Hidden (a minute of registrations): run it with
//   self_similar_test "[self-similar-report]"   (PAGOR_SELF_SIMILAR_SEEDS: seeds, 5 unless set;
//   PAGOR_MAX_AMBIGUITY: acceptance.max_ambiguity, the default unless set; 10 turns the test off)
TEST_CASE("self-similar set: no wrong pose accepted", "[.][self-similar-report]") {
  const char* env = std::getenv("PAGOR_SELF_SIMILAR_SEEDS");
  const int seeds = env ? std::atoi(env) : 5;
  struct Tally {
    int pairs = 0, right = 0, accepted = 0, right_accepted = 0;
  };
  std::map<std::string, Tally> tallies;
  std::printf("%-28s %8s %8s %5s %-8s %s\n", "scene", "err m", "err deg", "right", "verdict",
              "reason / ambiguity");
  for (const SelfSimilarParams& p : self_similar_set(seeds)) {
    const SelfSimilarScene s = make_self_similar_scene(p);
    Pipeline pipeline;
    if (const char* max = std::getenv("PAGOR_MAX_AMBIGUITY")) {
      Config c = default_config();
      c.acceptance.max_ambiguity = std::atof(max);
      pipeline.set_config(c);
    }
    pipeline.set_input(s.source, s.target, builtin_label_scheme(kSelfSimilarLabelScheme));
    pipeline.set_ground_truth(s.T_target_source);
    pipeline.run();
    const std::optional<PoseError> e = pipeline.selected_error();
    const bool right = e && e->success;
    const Acceptance& a = pipeline.acceptance();
    const bool rival_right = !a.alternative.description.empty() &&
                             pose_error(a.alternative.T_target_source, s.T_target_source).success;
    std::printf("%-28s %8.2f %8.1f %5s %-8s ambiguity %.3f%s %s%s%s\n", s.name.c_str(),
                e ? e->translation : -1.0, e ? e->rotation_deg : -1.0, right ? "yes" : "no",
                a.accepted ? "ACCEPT" : "reject", a.ambiguity, rival_right ? " (rival right)" : "",
                a.alternative.description.c_str(), a.reason.empty() ? "" : " | ", a.reason.c_str());
    const std::string variant = std::string(self_similar_kind_name(p.kind)) +
                                (p.distinct_objects ? " +objects" : "") +
                                (p.labelled ? " labelled" : " xyz");
    for (const std::string& key : {variant, std::string("all")}) {
      Tally& t = tallies[key];
      ++t.pairs;
      t.right += right;
      t.accepted += a.accepted;
      t.right_accepted += right && a.accepted;
    }
  }
  std::printf("\n%-34s %8s %15s %15s %10s %7s\n", "kind and variant", "success", "accepted-wrong",
              "right-rejected", "precision", "recall");
  for (const auto& [key, t] : tallies) {
    const auto pct = [](int a, int b) {
      return b ? std::to_string(100 * a / b) + " %" : std::string("n/a");
    };
    std::printf("%-34s %8s %15d %15d %10s %7s\n", key.c_str(),
                (std::to_string(t.right) + "/" + std::to_string(t.pairs)).c_str(),
                t.accepted - t.right_accepted, t.right - t.right_accepted,
                pct(t.right_accepted, t.accepted).c_str(), pct(t.right_accepted, t.right).c_str());
  }
  const Tally& all = tallies["all"];
  CHECK(all.accepted == all.right_accepted);  // no wrong pose accepted
}
