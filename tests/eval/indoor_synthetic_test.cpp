// The generated car park: fixed seeds, a repetitive column grid, what the plan does not show, and
// re-localization on a short generated sequence against its plan (floors below measured rates).

#include <catch2/catch.hpp>
#include <fstream>

#include "pagor/eval/benchmark.hpp"
#include "pagor/eval/indoor_synthetic.hpp"
#include "pagor/eval/threshold_comparison.hpp"
#include "pagor/indoor/floor_plan.hpp"
#include "pagor/indoor/floor_projection.hpp"
#include "pagor/io/clouds.hpp"
#include "pagor/pipeline.hpp"
#include "pagor/verify/evaluation.hpp"
#include "support/test_util.hpp"

using namespace pagor;

namespace {

// The first `scans` scans of the car park of `seed`, written under `dir` and read back as
// `pagor bench` reads them.
PairSet car_park(const test::TempDir& dir, std::uint64_t seed, int scans) {
  IndoorSceneParams scene;
  scene.seed = seed;
  write_indoor_sequence(dir.file("seq"), scene, scans);
  PairSet set = read_pair_manifest(dir.file("seq/pairs.txt"));
  REQUIRE(set.pairs.size() == static_cast<std::size_t>(scans));
  return set;
}

// Scan `scan` of the car park of `seed` (of 120, as `pagor indoor` draws it) against its plan,
// written under `dir` and read back as `pagor bench` reads it.
PairEntry one_scan(const test::TempDir& dir, std::uint64_t seed, int scan) {
  IndoorSceneParams scene;
  scene.seed = seed;
  const IndoorWorld w = make_indoor_world(scene, 120);
  const Eigen::Vector3d& pose = w.trajectory[static_cast<std::size_t>(scan)];
  // The scan's random stream as write_indoor_sequence draws it.
  std::mt19937_64 rng(seed * 1000003u + static_cast<std::uint64_t>(scan));
  write_kitti_bin(ray_cast_indoor(w, pose, {}, rng), dir.file("scan.bin"));
  write_floor_plan(w.plan, dir.file("plan.json"));
  {
    std::ofstream(dir.file("gt.txt")) << transform_file_text(pose_transform(pose));
    std::ofstream(dir.file("pairs.txt")) << "scan.bin plan.json gt=gt.txt\n";
  }
  const PairSet set = read_pair_manifest(dir.file("pairs.txt"));
  REQUIRE(set.pairs.size() == 1u);
  return set.pairs[0];
}

}  // namespace

TEST_CASE("the same seed gives the same building and scans") {
  IndoorSceneParams p;
  p.seed = 4;
  const IndoorWorld a = make_indoor_world(p, 5), b = make_indoor_world(p, 5);
  REQUIRE(a.plan.columns.size() == b.plan.columns.size());
  CHECK(a.trajectory[3].isApprox(b.trajectory[3]));
  std::mt19937_64 ra(1), rb(1);
  const PointCloud sa = ray_cast_indoor(a, a.trajectory[2], {}, ra);
  const PointCloud sb = ray_cast_indoor(b, b.trajectory[2], {}, rb);
  REQUIRE(sa.size() == sb.size());
  CHECK(sa.points[sa.size() / 2].isApprox(sb.points[sb.size() / 2]));
  p.seed = 5;
  CHECK_FALSE(make_indoor_world(p, 5).trajectory[3].isApprox(a.trajectory[3]));
}

TEST_CASE("the column grid repeats: shifted by one pitch most columns land near another") {
  IndoorSceneParams p;
  const IndoorWorld w = make_indoor_world(p, 1);
  const int expected = p.grid_x * p.grid_y;
  CHECK(static_cast<int>(w.plan.columns.size()) < expected);  // some are missing
  CHECK(static_cast<int>(w.plan.columns.size()) > expected / 2);
  int near = 0, shifted = 0;
  for (const PlanColumn& c : w.plan.columns) {
    const Eigen::Vector2d moved = c.center + Eigen::Vector2d(p.pitch_x, 0);
    bool inside = false;
    for (const PlanColumn& o : w.plan.columns) {
      inside |= o.center.x() > moved.x() - 1.0;
      if ((o.center - moved).norm() < 2 * p.line_jitter + 0.1) {
        ++near;
        break;
      }
    }
    shifted += inside;
  }
  // Self-similar: at least 60 % of the columns that stay inside the grid find a partner.
  CHECK(near >= 0.6 * shifted);
}

TEST_CASE("scans see cars and people the plan lacks, and nothing through glass") {
  IndoorSceneParams p;
  p.glass_fraction = 0.5;
  const IndoorWorld w = make_indoor_world(p, 8);
  CHECK(w.obstacles.size() > 20);
  CHECK(w.plan.walls.size() == w.built.walls.size() + 1);  // the ramp edge is only drawn
  // Distance from g to the nearest segment of the built walls that are (not) glass.
  const auto nearest = [&](const Eigen::Vector2d& g, bool glass) {
    double best = 1e9;
    for (std::size_t k = 0; k < w.built.walls.size(); ++k) {
      if (static_cast<bool>(w.glass[k]) != glass) continue;
      const auto& pts = w.built.walls[k].points;
      for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
        const Eigen::Vector2d a = pts[i], b = pts[i + 1];
        const double t = std::clamp((g - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
        best = std::min(best, (a + t * (b - a) - g).norm());
      }
    }
    return best;
  };
  int glass_hits = 0, wall_hits = 0;
  std::mt19937_64 rng(2);
  for (const auto& pose : w.trajectory) {
    const PointCloud s = ray_cast_indoor(w, pose, {}, rng);
    const Transform T = pose_transform(pose);
    for (const auto& q : s.points) {
      if (q.z() < -0.3f || q.z() > 1.9f) continue;  // the height band: not floor or ceiling
      const Eigen::Vector2d g = (T * Eigen::Vector4d(q.x(), q.y(), q.z(), 1)).head<2>();
      const bool on_wall = nearest(g, false) < 0.05;
      wall_hits += on_wall;
      glass_hits += !on_wall && nearest(g, true) < 0.05;
    }
  }
  CHECK(wall_hits > 1000);
  CHECK(glass_hits == 0);
}

TEST_CASE("re-localization on a generated sequence: the pyramid and its baselines") {
  // 16 scans of seed 2 against the plan, written and run as `pagor bench` does. Measured:
  // pyramid 13/16, best single threshold 12/16 (bench/README.md: 100/120 on the 120-scan
  // sequence); the floor sits below.
  test::TempDir dir;
  const PairSet set = car_park(dir, 2, 16);

  const Config config = preset_config("indoor");
  std::vector<Variant> variants = threshold_variants(config);
  REQUIRE(variants.size() == 11);
  const auto results = compare_variants(set, variants);
  for (const auto& r : results) INFO(r.name << ": " << r.successes << "/" << r.with_truth);
  REQUIRE(results[0].with_truth == 16);
  CHECK(results[0].successes >= 10);

  // The pipeline through the benchmark runner agrees with the comparison's pyramid.
  Pipeline pipeline(config);
  int successes = 0;
  for (const PairEntry& e : set.pairs) successes += run_pair(pipeline, e).success;
  CHECK(successes == results[0].successes);
}

namespace {

// Distance from g to an obstacle's footprint (a turned box or a circle) [m]; 0 inside.
double to_obstacle(const IndoorObstacle& o, const Eigen::Vector2d& g) {
  const Eigen::Vector2d d = g - o.center;
  if (!o.box) return std::max(0.0, d.norm() - o.radius);
  const double c = std::cos(o.yaw), s = std::sin(o.yaw);
  const Eigen::Vector2d local(c * d.x() + s * d.y(), -s * d.x() + c * d.y());
  const Eigen::Vector2d out = (local.cwiseAbs() - o.half).cwiseMax(0.0);
  return out.norm();
}

}  // namespace

TEST_CASE("furniture: what a higher beam passes over is the cars and people, not the building") {
  // Measured on 8 scans of seed 2: see the INFO line; the floors sit below.
  IndoorSceneParams scene;
  scene.seed = 2;
  const IndoorWorld w = make_indoor_world(scene, 8);
  const IndoorParams params = preset_config("indoor").indoor;
  std::size_t furniture = 0, on_obstacle = 0, wall = 0, wall_on_obstacle = 0;
  std::mt19937_64 rng(3);
  for (const auto& pose : w.trajectory) {
    const FloorScan fs = prepare_floor_scan(ray_cast_indoor(w, pose, {}, rng), params);
    const Transform T = pose_transform(pose);
    for (std::size_t i = 0; i < fs.cloud.size(); ++i) {
      const Eigen::Vector3f& q = fs.cloud.points[i];
      const Eigen::Vector2d g = (T * Eigen::Vector4d(q.x(), q.y(), 0, 1)).head<2>();
      double nearest = 1e9;
      for (const auto& o : w.obstacles) nearest = std::min(nearest, to_obstacle(o, g));
      const bool near = nearest < 0.15;
      if (fs.cloud.labels[i] == kFurnitureLabel) furniture += 1, on_obstacle += near;
      if (fs.cloud.labels[i] == kWallLabel) wall += 1, wall_on_obstacle += near;
    }
  }
  INFO("furniture cells " << furniture << ", on a car or person " << on_obstacle << "; wall cells "
                          << wall << ", on a car or person " << wall_on_obstacle);
  REQUIRE(furniture > 500);
  CHECK(on_obstacle >= 0.95 * furniture);                        // precision
  CHECK(on_obstacle >= 0.5 * (on_obstacle + wall_on_obstacle));  // recall over obstacle cells

  // Off: every cell that is not a column is wall, as before.
  IndoorParams off = params;
  off.furniture_gap = 0;
  const FloorScan fs = prepare_floor_scan(ray_cast_indoor(w, w.trajectory[0], {}, rng), off);
  CHECK(fs.furniture == 0);
  for (std::uint32_t l : fs.cloud.labels) CHECK(l != kFurnitureLabel);
}

TEST_CASE("passed_over: a beam that clears an object returns from behind it") {
  // Azimuth 0: a low object at 5 m (beams at -4 to 0 degrees) and a wall at 10 m behind it (beams
  // at 2 to 8 degrees); azimuth 90 degrees: the wall alone, at 4 m.
  PointCloud scan;
  const auto at = [&](double az_deg, double el_deg, double range) {
    const double az = az_deg * M_PI / 180, el = el_deg * M_PI / 180;
    scan.points.emplace_back(static_cast<float>(range * std::cos(az)),
                             static_cast<float>(range * std::sin(az)),
                             static_cast<float>(range * std::tan(el)));
  };
  for (double el : {-4.0, -2.0, 0.0}) at(0, el, 5);
  for (double el : {2.0, 4.0, 6.0, 8.0}) at(0, el, 10);
  for (double el : {-4.0, 0.0, 4.0, 8.0}) at(90, el, 4);
  const std::vector<char> passed = passed_over(scan, 1.0);
  REQUIRE(passed.size() == scan.size());
  for (std::size_t i = 0; i < 3; ++i) CHECK(passed[i]);
  for (std::size_t i = 3; i < scan.size(); ++i) CHECK_FALSE(passed[i]);
  CHECK(passed_over(scan, 6.0) == std::vector<char>(scan.size(), 0));  // the wall is 5 m behind
  CHECK(passed_over(scan, 0.0) == std::vector<char>(scan.size(), 0));  // off
}

TEST_CASE("car park verdicts: furniture on a wall is no evidence for a shifted pose") {
  // 24 scans of seed 1 against the plan. Measured: with furniture 22 right poses accepted, without
  // it 17 (a car's side put on the outer wall by a shift of a column spacing made right poses
  // look rivalled); no wrong pose accepted either way. The floors sit below.
  test::TempDir dir;
  const PairSet set = car_park(dir, 1, 24);
  const auto verdicts = [&](double gap) {
    Config config = preset_config("indoor");
    config.indoor.furniture_gap = gap;
    Pipeline pipeline(config);
    int right = 0, wrong = 0;
    for (const PairEntry& e : set.pairs) {
      const PairOutcome o = run_pair(pipeline, e);
      right += o.accepted && o.success;
      wrong += o.accepted && !o.success;
    }
    return std::pair<int, int>(right, wrong);
  };
  const auto [right_with, wrong_with] = verdicts(preset_config("indoor").indoor.furniture_gap);
  const auto [right_without, wrong_without] = verdicts(0.0);
  INFO("right accepted: " << right_with << " with furniture, " << right_without << " without");
  CHECK(wrong_with == 0);
  CHECK(wrong_without == 0);
  CHECK(right_with > right_without);
}

TEST_CASE("car park verdicts: a pose two column spacings off is refuted by the truth it misses") {
  // Seed 7, scan 18 of 120: four columns and a little wall. The clique takes a pose 15.6 m off
  // along a row of columns; the plan's principal axis is turned ~4 degrees from the rows, so the
  // repetition found along it lay 1.1 m across the true pose, where nothing aligned, and the
  // wrong pose was accepted (ambiguity 0.5: 93 points against 196). Centred across the axis, the
  // alternative is the truth and aligns 101 points the selected pose does not, against none: the
  // selection is rejected, and the truth, refitted to the 4 correspondences it explains, adopted.
  test::TempDir dir;
  const PairEntry pair = one_scan(dir, 7, 18);
  Config config = preset_config("indoor");
  config.acceptance.adopt_alternative = false;
  Pipeline pipeline(config);
  const PairOutcome o = run_pair(pipeline, pair);
  const Acceptance& a = pipeline.acceptance();
  INFO(a.reason);
  REQUIRE_FALSE(o.success);  // as measured: the clique misses the true correspondences
  CHECK_FALSE(o.accepted);
  REQUIRE(pipeline.ground_truth());
  CHECK(pose_error(a.alternative.T_target_source, *pipeline.ground_truth(),
                   pipeline.config().evaluation)
            .success);
  CHECK(a.ambiguity > 2.0);
  CHECK(a.alternative.only_alternative > 10 * a.alternative.only_selected);
  CHECK_THAT(a.reason, Catch::Contains("fits better"));
  // The preset adopts the alternative: refitted, it is the truth, and trusted.
  Pipeline adopting(preset_config("indoor"));
  const PairOutcome b = run_pair(adopting, pair);
  INFO(adopting.acceptance().reason);
  CHECK(adopting.acceptance().adopted.applied);
  CHECK(b.success);
  CHECK(b.accepted);
}

TEST_CASE("car park verdicts: overturning the selection keeps the default's standard") {
  // Two right poses rivalled by their half turns, each wrong by ~23-27 m. The indoor preset's
  // looser ambiguity test (max_ambiguity 0.8) rejects them; the adoption keeps its own threshold,
  // adopt_max_ambiguity (0.55), for its bar (a ratio above 1 / 0.55^2 = 3.3) and for the refitted
  // pose's ambiguity test. Tied to max_ambiguity, as the adoption was, each half turn was adopted
  // and accepted: seed 11 scan 106 clears only the looser bar (19 points against 0, ratio 2.9);
  // seed 34 scan 109 clears both (ratio 3.47), and its refit is rivalled at 0.62, between the two
  // thresholds.
  const Config preset = preset_config("indoor");
  REQUIRE(preset.acceptance.max_ambiguity > preset.acceptance.adopt_max_ambiguity);
  Config tied = preset;  // the adoption at the ambiguity test's threshold, as before
  tied.acceptance.adopt_max_ambiguity = tied.acceptance.max_ambiguity;
  const double bar = preset.acceptance.adoption_bar();
  for (const auto& [seed, scan] : {std::pair<int, int>{11, 106}, {34, 109}}) {
    INFO("seed " << seed << ", scan " << scan);
    test::TempDir dir;
    const PairEntry pair = one_scan(dir, static_cast<std::uint64_t>(seed), scan);
    Pipeline pipeline(preset);
    const PairOutcome o = run_pair(pipeline, pair);
    const Acceptance& a = pipeline.acceptance();
    INFO(a.reason);
    CHECK(o.success);
    CHECK_FALSE(o.accepted);
    CHECK_FALSE(a.adopted.applied);
    if (a.ambiguity > bar) {  // the adoption was tried: its refit judged at the stricter threshold
      CHECK_THAT(a.reason, Catch::Contains("not trusted either") &&
                               Catch::Contains("judged at acceptance.adopt_max_ambiguity, 0.55"));
    } else {
      CHECK_THAT(a.reason, !Catch::Contains("refitted on"));
    }
    Pipeline loose(tied);
    const PairOutcome b = run_pair(loose, pair);
    INFO(loose.acceptance().reason);
    CHECK(loose.acceptance().adopted.applied);
    CHECK_FALSE(b.success);
    CHECK(b.accepted);
  }
}
