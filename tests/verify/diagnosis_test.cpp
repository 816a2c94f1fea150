// The diagnosis names the stage at fault: synthetic pairs built (fixed seeds, known ground truth)
// so that each verdict occurs, run through the real pipeline, plus the front end's counts on a
// hand-made correspondence set.

#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <random>

#include "pagor/eval/synthetic.hpp"
#include "pagor/pipeline.hpp"
#include "pagor/verify/diagnosis.hpp"
#include "util/random_draw.hpp"

using namespace pagor;

namespace {

// semantickitti-train ids
constexpr std::uint32_t kRoad = 8, kFence = 13, kTrunk = 15, kPole = 17;

// A vertical cylinder (trunk, pole) or a vertical wall from `a` to `b`, in the world (= source)
// frame, seen by the source and/or the target sensor.
struct Object {
  std::uint32_t label;
  Eigen::Vector2d a, b;  // cylinder: centre a; wall: ends a, b [m]
  double radius, height;
  bool wall, in_source, in_target;
};

Object trunk(double x, double y) {
  return {kTrunk, {x, y}, {x, y}, 0.2, 3.0, false, true, true};
}

// Surface samples every ~0.1 m with 1 cm noise; each sensor samples on its own.
void sample(const Object& o, std::mt19937& rng, const Transform& T, PointCloud& out) {
  std::normal_distribution<double> noise(0.0, 0.01);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double step = 0.1;
  const double along = o.wall ? (o.b - o.a).norm() : 2 * M_PI * o.radius;
  const int n = static_cast<int>(along / step * o.height / step);
  for (int k = 0; k < n; ++k) {
    const double s = u(rng), z = u(rng) * o.height;
    Eigen::Vector3d p;
    if (o.wall) {
      const Eigen::Vector2d xy = o.a + s * (o.b - o.a);
      p = {xy.x(), xy.y(), z};
    } else {
      const double phi = 2 * M_PI * s;
      p = {o.a.x() + o.radius * std::cos(phi), o.a.y() + o.radius * std::sin(phi), z};
    }
    p += draw3(noise, rng);
    out.points.push_back((T.block<3, 3>(0, 0) * p + T.block<3, 1>(0, 3)).cast<float>());
    out.labels.push_back(o.label);
  }
}

Transform pose(double yaw_deg, double roll_deg, Eigen::Vector3d t) {
  Transform T = Transform::Identity();
  T.block<3, 3>(0, 0) = (Eigen::AngleAxisd(yaw_deg * M_PI / 180, Eigen::Vector3d::UnitZ()) *
                         Eigen::AngleAxisd(roll_deg * M_PI / 180, Eigen::Vector3d::UnitX()))
                            .toRotationMatrix();
  T.block<3, 1>(0, 3) = t;
  return T;
}

// The scenes' configuration: their numbering named. A scene of trunks, poles and fences alone would
// read as the learning map's vegetation, terrain and buildings (the likelier scan), so each cloud
// also holds a patch of road, as a street scan does: 60 m x 60 m every 0.5 m, a kilometre away
// from everything (the source's at x = +1000 m, the target's at -1000 m in its own frame), where no
// candidate aligns it, so every candidate's D grows by the same amount.
Config scene_config() {
  Config c = default_config();
  c.label_scheme = builtin_label_scheme("semantickitti-train");
  return c;
}

// The patch lies on the world's ground, seen by the sensor whose frame `T` maps the world into
// (a rolled sensor sees it rolled, like everything else).
void add_road_patch(double x0, PointCloud& cloud, const Transform& T = Transform::Identity()) {
  for (int x = 0; x < 120; ++x)
    for (int y = 0; y < 120; ++y) {
      const Eigen::Vector3d world(x0 + 0.5 * x, -30.0 + 0.5 * y, 0.0);
      cloud.points.push_back((T.block<3, 3>(0, 0) * world + T.block<3, 1>(0, 3)).cast<float>());
      cloud.labels.push_back(kRoad);
    }
}

// Runs the pipeline (semantic landmarks only) on the objects seen by each sensor.
std::optional<Diagnosis> run(const std::vector<Object>& objects, const Transform& T_gt,
                             Config config = scene_config()) {
  config.landmarks.fallback.mode = FallbackMode::never;
  std::mt19937 rng_s(11), rng_t(23);
  PointCloud source, target;
  for (const Object& o : objects) {
    if (o.in_source) sample(o, rng_s, Transform::Identity(), source);
    if (o.in_target) sample(o, rng_t, T_gt, target);
  }
  add_road_patch(1000.0, source);
  add_road_patch(-1060.0, target, T_gt);
  Pipeline p(config);
  p.set_input(std::move(source), std::move(target));
  p.set_ground_truth(T_gt);
  p.run();
  return diagnose(p);
}

// Trunks and poles spread over 60 m x 60 m, seen by both sensors.
std::vector<Object> shared_scene(std::uint64_t seed) {
  std::mt19937 rng(static_cast<std::mt19937::result_type>(seed));
  std::uniform_real_distribution<double> xy(-30.0, 30.0);
  std::vector<Object> out;
  while (out.size() < 12) {
    const Eigen::Vector2d c = draw2(xy, rng);
    bool free = true;
    for (const Object& o : out) free = free && (o.a - c).norm() > 6.0;
    if (!free) continue;
    Object o = trunk(c.x(), c.y());
    if (out.size() % 2) o = {kPole, c, c, 0.1, 6.0, false, true, true};
    out.push_back(o);
  }
  return out;
}

// Four trunks both sensors see; a row of nine poles 5 m apart and a fence beside it that only
// the source sees; another row (spacing `spacing`) and fence only the target sees, 55 m away.
std::vector<Object> repetitive_scene(double spacing) {
  std::vector<Object> o = {trunk(-8, -6), trunk(7, -9), trunk(10, 8), trunk(-6, 11)};
  for (int k = 0; k < 9; ++k) {
    const Eigen::Vector2d a(-20.0 + 5.0 * k, 25.0), b(-4 * spacing + spacing * k, -30.0);
    o.push_back({kPole, a, a, 0.1, 6.0, false, true, false});
    o.push_back({kPole, b, b, 0.1, 6.0, false, false, true});
  }
  o.push_back({kFence, {-26, 27}, {26, 27}, 0, 3.0, true, true, false});
  o.push_back({kFence, {-26, -28}, {26, -28}, 0, 3.0, true, false, true});
  return o;
}

}  // namespace

TEST_CASE("diagnosis: a right pose is a success") {
  const auto d = run(shared_scene(3), pose(30, 0, {5, 2, 0}));
  REQUIRE(d);
  CHECK(d->verdict == DiagnosisVerdict::success);
  CHECK(d->true_correspondences == 12);
  CHECK(d->best_achievable == 12);
  REQUIRE_FALSE(d->levels.empty());
  for (const LevelDiagnosis& l : d->levels) {
    CHECK(l.consistent_true == 12);
    CHECK(l.precision == Approx(1.0));
    CHECK(l.recall == Approx(1.0));
  }
  CHECK(d->gt_score <= d->levels[static_cast<std::size_t>(d->selected)].score + 1.0);
  CHECK_FALSE(d->score_misled);
}

TEST_CASE("diagnosis: clouds that share no landmark have too few true correspondences") {
  std::vector<Object> objects = shared_scene(5);
  for (Object& o : shared_scene(6)) {  // the target sees another street, 200 m away
    o.a.x() += 200;
    o.b.x() += 200;
    o.in_source = false;
    objects.push_back(o);
  }
  for (std::size_t i = 0; i < 12; ++i) objects[i].in_target = false;
  const auto d = run(objects, pose(10, 0, {-200, 0, 0}));
  REQUIRE(d);
  CHECK(d->verdict == DiagnosisVerdict::too_few_true);
  CHECK(d->true_correspondences == 0);
  CHECK(d->classes.at(1).name == "trunk");
  CHECK(d->classes.at(1).source_landmarks == 6);
  CHECK(d->classes.at(1).target_landmarks == 6);
}

TEST_CASE("diagnosis: thresholds far below the landmark noise are not consistent at any level") {
  Config config = scene_config();
  config.graph.thresholds = {1e-7, 1e-6};
  config.gnc.model = PoseModel::se3;
  const auto d = run(shared_scene(3), pose(30, 0, {5, 2, 0}), config);
  REQUIRE(d);
  CHECK(d->verdict == DiagnosisVerdict::not_consistent);
  CHECK(d->best_achievable == 12);
  for (const LevelDiagnosis& l : d->levels) CHECK(l.consistent_true < 4);
}

TEST_CASE("diagnosis: a planted repetitive structure makes the clique miss the true set") {
  const auto d = run(repetitive_scene(5.0), pose(20, 0, {3, -2, 0}));
  REQUIRE(d);
  CHECK(d->verdict == DiagnosisVerdict::clique_missed);
  CHECK(d->best_achievable == 4);
  REQUIRE(d->at_fault_level >= 0);
  const LevelDiagnosis& l = d->levels[static_cast<std::size_t>(d->at_fault_level)];
  CHECK(l.consistent_true == 4);
  CHECK(l.clique_true == 0);
  CHECK(l.precision == 0.0);
  CHECK(l.clique_size >= 8);
}

TEST_CASE("diagnosis: a pose model that cannot hold the truth is wrong from a right clique") {
  // The target sensor is rolled by 12 deg; a 4-DoF pose keeps roll at 0. (The default model,
  // auto, sees the scene is not level and fits SE(3): there the pair succeeds.)
  Config four_dof = default_config();
  four_dof.gnc.model = PoseModel::four_dof;
  const auto d = run(shared_scene(3), pose(30, 12, {5, 2, 0}), four_dof);
  REQUIRE(d);
  CHECK(d->verdict == DiagnosisVerdict::pose_wrong);
  REQUIRE(d->at_fault_level >= 0);
  const LevelDiagnosis& l = d->levels[static_cast<std::size_t>(d->at_fault_level)];
  CHECK(l.precision >= 0.5);
  REQUIRE(l.error);
  CHECK(l.error->rotation_deg > 5.0);
  const auto automatic = run(shared_scene(3), pose(30, 12, {5, 2, 0}));
  REQUIRE(automatic);
  CHECK(automatic->verdict == DiagnosisVerdict::success);
}

TEST_CASE("diagnosis: a verification trap picks a wrong candidate although one was right") {
  // The rows differ by 5 % in spacing: consistent only at the looser levels, where nine poles
  // outvote four trunks; their fences then align far more points than the trunks do.
  const auto d = run(repetitive_scene(5.25), pose(20, 0, {3, -2, 0}));
  REQUIRE(d);
  CHECK(d->verdict == DiagnosisVerdict::verification_wrong);
  REQUIRE(d->at_fault_level >= 0);
  const LevelDiagnosis& right = d->levels[static_cast<std::size_t>(d->at_fault_level)];
  REQUIRE(right.error);
  CHECK(right.error->success);
  CHECK(right.precision == Approx(1.0));
  const LevelDiagnosis& chosen = d->levels[static_cast<std::size_t>(d->selected)];
  CHECK(chosen.score < right.score);
  CHECK(d->score_misled);
  CHECK(d->gt_score > chosen.score);
}

TEST_CASE("diagnosis: true correspondences sharing a landmark count once in the best set") {
  // Source landmarks 0, 1, 2 and target landmarks 0, 1, 2 of one class at the same places
  // (identity truth); extra correspondences reuse landmarks 0.
  LandmarkSet s, t;
  s.classes.push_back({});
  s.classes[0].name = "pole";
  s.classes[0].landmarks = 3;
  t.classes = s.classes;
  CorrespondenceSet corr;
  const auto add = [&](int i, int j, Eigen::Vector3d p, Eigen::Vector3d q) {
    corr.items.push_back({0, i, j, p, q, 1.0});
  };
  const Eigen::Vector3d a(0, 0, 0), b(10, 0, 0), c(0, 10, 0);
  add(0, 0, a, a);
  add(1, 1, b, b);
  add(2, 2, c, c);
  add(0, 1, a, a + Eigen::Vector3d(0.5, 0, 0));  // true within 1 m, but landmark 0 again
  add(1, 0, b, a);                               // false
  const PyramidGraph g = build_pyramid_graph(corr.items, default_config().graph);
  const Config config = default_config();
  std::vector<CliqueResult> cliques(1);
  cliques[0].vertices = {0, 1, 2};
  std::vector<PoseEstimate> poses(1);
  VerificationResult v;
  v.scores = {HUGE_VAL};
  DiagnosisInput in{&s, &t, &corr, &g, &cliques, &poses, &v, nullptr, &config, std::nullopt};
  const Diagnosis d = diagnose(in, Transform::Identity());
  CHECK(d.true_correspondences == 4);
  CHECK(d.best_achievable == 3);
  CHECK(d.residuals[3] == Approx(0.5));
  CHECK(d.levels.at(0).clique_true == 3);
  CHECK(d.levels.at(0).consistent_true == 3);
  CHECK(d.verdict == DiagnosisVerdict::pose_wrong);  // a right clique, but no pose
  const auto j = nlohmann::json::parse(diagnosis_json(d));
  CHECK(j["verdict"] == "pose-wrong");
  CHECK(j["classes"][0]["best_achievable"] == 3);
  CHECK(j["verification"]["gt_score_D"].is_null());
}

TEST_CASE("diagnosis: labels in another numbering than the scheme set are the cause, named") {
  Config raw = scene_config();
  raw.label_scheme = builtin_label_scheme("semantickitti");  // the scene is in the training ids
  const auto d = run(shared_scene(3), pose(30, 0, {5, 2, 0}), raw);
  REQUIRE(d);
  CHECK(d->verdict == DiagnosisVerdict::label_scheme);
  CHECK(d->labels_look_like == "semantickitti-train");
  CHECK_THAT(d->explanation, Catch::StartsWith("source labels do not fit scheme 'semantickitti'") &&
                                 Catch::Contains("look like 'semantickitti-train'"));
  const auto j = nlohmann::json::parse(diagnosis_json(*d));
  CHECK(j["verdict"] == "label-scheme");
  CHECK(j["labels_look_like"] == "semantickitti-train");
  // Read in their own numbering (set, or detected), the same scene succeeds.
  const auto right = run(shared_scene(3), pose(30, 0, {5, 2, 0}));
  REQUIRE(right);
  CHECK(right->verdict == DiagnosisVerdict::success);
  const auto automatic = run(shared_scene(3), pose(30, 0, {5, 2, 0}), default_config());
  CHECK(automatic->verdict == DiagnosisVerdict::success);
  CHECK(nlohmann::json::parse(diagnosis_json(*automatic))["labels_look_like"].is_null());
}

TEST_CASE("diagnosis: every verdict has a name and a sentence") {
  for (auto v :
       {DiagnosisVerdict::success, DiagnosisVerdict::label_scheme, DiagnosisVerdict::too_few_true,
        DiagnosisVerdict::not_consistent, DiagnosisVerdict::clique_missed,
        DiagnosisVerdict::pose_wrong, DiagnosisVerdict::verification_wrong}) {
    CHECK(std::string(verdict_name(v)).size() > 3);
    CHECK(std::string(verdict_sentence(v)).size() > 10);
  }
}
