// Indoor re-localization in the studio: the floor plan and the scan's columns reach the pair
// view's snapshot, the benchmark view's trajectory is the selected poses' translations over the
// plan, picking levels are labelled by their epsilon with its unit, and a driven walk over every
// widget with an indoor pair open.

#include <catch2/catch.hpp>
#include <fstream>

#include "pagor/eval/indoor_synthetic.hpp"
#include "pagor/indoor/floor_projection.hpp"
#include "pagor/io/clouds.hpp"
#include "runners/bench_worker.hpp"
#include "runners/worker.hpp"
#include "scene/plan_overlay.hpp"
#include "scene/scene_overlay.hpp"
#include "studio_test_util.hpp"
#include "ui_driver.hpp"
#include "widgets/bench_plots.hpp"
#include "widgets/plot_export.hpp"

using namespace pagor;
using namespace pagor::test;

namespace {

constexpr double kTimeout = 600.0;  // [s]: generous for sanitizer builds
constexpr int kScans = 6;           // a short generated sequence
constexpr double kExact = 1e-12;    // the same numbers, copied [m]

const std::string kIndoorData = PAGOR_SOURCE_DIR "/tests/data/indoor/";

PairSource indoor_pair() {
  PairSource d;
  d.kind = PairSource::Kind::files;
  d.source = kIndoorData + "scan_000010.bin";
  d.target = kIndoorData + "plan.json";
  d.ground_truth = kIndoorData + "gt_000010.txt";
  return d;
}

// A generated sequence of kScans scans (seed 1) and its manifest in `tmp`.
PairSet indoor_sequence(const TempDir& tmp) {
  IndoorSceneParams scene;
  scene.seed = 1;
  write_indoor_sequence(tmp.file("seq"), scene, kScans);
  return read_pair_manifest(tmp.file("seq/pairs.txt"));
}

Eigen::Vector2d translation(const Transform& T) {
  return T.topRightCorner<2, 1>();
}

}  // namespace

TEST_CASE("an indoor pair's plan and scan columns reach the snapshot, other pairs have none") {
  const Config config = preset_config("indoor");
  studio::Worker w;
  w.submit(indoor_pair(), config);
  REQUIRE(w.wait_idle(kTimeout));
  const auto s = w.snapshot();
  REQUIRE(s);
  REQUIRE(s->plan);
  const FloorPlan plan = read_floor_plan(kIndoorData + "plan.json");
  CHECK(s->plan->walls.size() == plan.walls.size());
  CHECK(s->plan->columns.size() == plan.columns.size());
  CHECK(studio::wall_segment_count(*s->plan) == studio::wall_segment_count(plan));
  // The columns are those the floor projection finds in the scan (scan frame).
  const FloorScan scan =
      prepare_floor_scan(load_cloud(kIndoorData + "scan_000010.bin").cloud, config.indoor);
  REQUIRE(s->scan_columns);
  REQUIRE(s->scan_columns->size() == scan.columns.size());
  CHECK(!scan.columns.empty());
  for (std::size_t i = 0; i < scan.columns.size(); ++i)
    CHECK(((*s->scan_columns)[i].center - scan.columns[i].center).norm() < kExact);

  PairSource synthetic;
  synthetic.kind = PairSource::Kind::synthetic;
  w.submit(synthetic, default_config());
  REQUIRE(w.wait_idle(kTimeout));
  CHECK_FALSE(w.snapshot()->plan);
  CHECK_FALSE(w.snapshot()->scan_columns);
}

TEST_CASE("wall segments of a plan: open polylines n-1, closed ones n") {
  FloorPlan p;
  p.walls.push_back({{{0, 0}, {1, 0}, {1, 1}}, false});
  p.walls.push_back({{{0, 0}, {2, 0}, {2, 2}, {0, 2}}, true});
  CHECK(studio::wall_segment_count(p) == 2 + 4);
}

TEST_CASE("trajectory: the selected poses' translations over the plan, coloured by scan index") {
  TempDir tmp;
  const PairSet set = indoor_sequence(tmp);
  REQUIRE(set.pairs.size() == kScans);
  const Config config = preset_config("indoor");
  studio::BenchWorker bench;
  bench.open(set, config);
  REQUIRE(bench.wait_idle(kTimeout));
  const auto plan = bench.plan();
  REQUIRE(plan);
  const FloorPlan expected_plan = read_floor_plan(tmp.file("seq/plan.json"));
  CHECK(plan->walls.size() == expected_plan.walls.size());
  CHECK(plan->columns.size() == expected_plan.columns.size());

  std::vector<PairOutcome> outcomes;
  for (const studio::BenchRow& r : bench.rows()) outcomes.push_back(r.outcome);
  REQUIRE(outcomes.size() == kScans);
  // Each outcome's pose is what a fresh run of its pair selects.
  Pipeline fresh(config);
  run_pair(fresh, set.pairs[2]);
  REQUIRE(outcomes[2].T_target_source);
  CHECK((*outcomes[2].T_target_source - *fresh.selected_transform()).norm() < 1e-9);
  CHECK(outcomes[2].level_epsilons == config.graph.thresholds);

  const studio::Plot p = studio::trajectory_plot(outcomes, plan.get());
  CHECK(p.kind == studio::PlotKind::map);
  CHECK(p.x_unit == "m");
  CHECK(p.value_unit == "m");
  REQUIRE(p.color_bar);
  CHECK(p.color_bar->unit == "scan index");
  CHECK(p.backdrop.lines.size() == expected_plan.walls.size());
  CHECK(p.backdrop.circles.size() == expected_plan.columns.size());
  REQUIRE(p.series.size() == 4);  // truth, re-localized, failure, rejected
  // The truth line passes through every scan's ground-truth position, in order.
  REQUIRE(p.series[0].x.size() == kScans);
  for (int i = 0; i < kScans; ++i) {
    const Eigen::Vector2d t = translation(*outcomes[i].T_target_source_gt);
    CHECK(p.series[0].x[i] == Approx(t.x()).margin(kExact));
    CHECK(p.series[0].y[i] == Approx(t.y()).margin(kExact));
  }
  // Every selected pose is one point, in the series its verdict and error put it in.
  std::size_t next[4] = {0, 0, 0, 0};
  for (int i = 0; i < kScans; ++i) {
    const PairOutcome& o = outcomes[i];
    if (!o.T_target_source) continue;
    const std::size_t k = o.error && !o.success ? 2 : !o.accepted ? 3 : 1;
    const studio::PlotSeries& s = p.series[k];
    const std::size_t j = next[k]++;
    REQUIRE(j < s.x.size());
    const Eigen::Vector2d t = translation(*o.T_target_source);
    CHECK(s.x[j] == Approx(t.x()).margin(kExact));
    CHECK(s.y[j] == Approx(t.y()).margin(kExact));
    CHECK(s.tips[j].find("pair " + o.name) != std::string::npos);
    if (o.error) CHECK(s.tips[j].find(" m, ") != std::string::npos);  // errors in m and deg
    CHECK(s.tips[j].find(o.accepted ? "accepted" : "rejected") != std::string::npos);
    if (k == 1) CHECK(s.color_values[j] == i);
  }
  for (std::size_t k = 1; k < 4; ++k) CHECK(p.series[k].x.size() == next[k]);
  CHECK(next[1] + next[2] + next[3] > 0);

  // Exports: CSV rows per point with units in the header, and a PNG.
  const std::string csv = studio::plot_csv(p);
  CHECK(csv.rfind("\"series\",\"x [m]\",\"y [m]\",\"time [scan index]\",\"tip\"\n", 0) == 0);
  CHECK(static_cast<std::size_t>(std::count(csv.begin(), csv.end(), '\n')) ==
        1 + kScans + next[1] + next[2] + next[3]);
  studio::export_plot_png(p, tmp.file("trajectory.png"), 640, 400);
  std::ifstream png(tmp.file("trajectory.png"), std::ios::binary);
  char magic[4] = {};
  png.read(magic, 4);
  CHECK(std::string(magic + 1, 3) == "PNG");
}

TEST_CASE("bench results read back keep the poses and thresholds the trajectory needs") {
  TempDir tmp;
  const PairSet set = indoor_sequence(tmp);
  Pipeline p(preset_config("indoor"));
  const PairOutcome o = run_pair(p, set.pairs[0]);
  // As `pagor bench --out` run beside the manifest writes it: the plan by its relative path.
  std::string line = o.report_json;
  const std::string plan_path = tmp.file("seq/plan.json");
  REQUIRE(line.find(plan_path) != std::string::npos);
  line.replace(line.find(plan_path), plan_path.size(), "plan.json");
  std::ofstream(tmp.file("seq/results.jsonl")) << line << "\n";
  const std::vector<PairOutcome> back = read_bench_results(tmp.file("seq/results.jsonl"));
  REQUIRE(back.size() == 1);
  REQUIRE(back[0].T_target_source);
  REQUIRE(back[0].T_target_source_gt);
  CHECK((*back[0].T_target_source - *o.T_target_source).norm() < 1e-9);
  CHECK((*back[0].T_target_source_gt - *o.T_target_source_gt).norm() < 1e-9);
  CHECK(back[0].level_epsilons == o.level_epsilons);
  CHECK(back[0].trim == TrimKind::difference);  // the indoor preset's; labels carry metres
  // The results view finds the plan beside the results file (the manifest's relative target).
  studio::BenchWorker bench;
  bench.show_results(back, tmp.file("seq/results.jsonl"));
  REQUIRE(bench.wait_idle(kTimeout));
  REQUIRE(bench.plan());
  CHECK(bench.plan()->columns.size() == read_floor_plan(tmp.file("seq/plan.json")).columns.size());
}

TEST_CASE("picking statistics label each level by its epsilon with the TRIM's unit") {
  CHECK(studio::level_label(0, 0.05, TrimKind::difference) == "level 0: \xCE\xB5 = 0.05 m");
  CHECK(studio::level_label(3, 0.1, TrimKind::ratio) == "level 3: \xCE\xB5 = 0.1");
  CHECK(studio::level_label(2, std::nullopt, std::nullopt) == "level 2");
  PairOutcome a;
  a.loaded = a.has_ground_truth = true;
  a.selected_level = 1;
  a.level_success = {false, true};
  a.level_epsilons = {0.05, 0.1};
  a.trim = TrimKind::difference;
  CHECK(studio::picking_plot(summarize({a})).categories ==
        std::vector<std::string>{"level 0: \xCE\xB5 = 0.05 m", "level 1: \xCE\xB5 = 0.1 m"});
  a.trim = TrimKind::ratio;
  CHECK(studio::picking_plot(summarize({a})).categories[1] == "level 1: \xCE\xB5 = 0.1");
}

TEST_CASE("every widget with an indoor pair open, the floor plan layer included") {
  TempDir tmp;
  studio::AppState s = base_state(tmp);
  s.data = indoor_pair();  // with the default (outdoor) parameters
  UiDriver d(s);
  d.settle();
  CHECK(d.state().camera.top_down);  // new indoor data is looked at from above
  // The data panel offers the indoor parameters, and they apply.
  REQUIRE(d.click_widget("use the indoor parameters##data", "Pagor Studio"));
  d.settle();
  CHECK(config_to_json(d.state().config, -1) == config_to_json(preset_config("indoor"), -1));
  CHECK_FALSE(d.find("use the indoor parameters##data", "Pagor Studio"));
  REQUIRE(d.find("floor plan", "Pagor Studio"));
  const bool before = d.state().view.layers.plan;
  REQUIRE(d.click_widget("floor plan", "Pagor Studio"));
  CHECK(d.state().view.layers.plan == !before);
  const int acted = exercise_every_widget(
      d,
      [&] {
        if (d.state().data.kind != PairSource::Kind::files) d.click_widget("files");
        hide_clouds(d.state());
        d.state().dialog.open = false;  // the file browser has a test of its own
        if (d.state().show_help) d.click_widget("close##help");
      },
      600, "", skip_parameter_sections);
  d.settle();
  CHECK(acted >= 60);
  WARN("widgets acted on: " << acted << ", distinct: " << d.touched().size());
}

TEST_CASE("after a failed open, an indoor pair opened is framed by the camera") {
  TempDir tmp;
  UiDriver d(synthetic_state(tmp), 1024, 768);
  d.settle();
  const Eigen::Vector3f synthetic_target = d.state().camera.target;
  // As the Data panel's "Open" does it: first a scan that is not there, then the right one.
  const auto open = [&](const PairSource& data) {
    d.state().config = preset_config("indoor");
    d.state().data = data;
    d.state().have_data = true;
    d.state().camera_fitted = false;
    d.state().view.level = -1;
    d.studio().submit_data();
    d.frame();
    d.settle();
  };
  PairSource bad = indoor_pair();
  bad.source = kIndoorData + "no_such_scan.bin";
  open(bad);
  CHECK_FALSE(d.studio().worker().status().error.empty());
  open(indoor_pair());
  INFO(d.studio().worker().status().error);
  REQUIRE(d.studio().worker().status().error.empty());
  const auto snap = d.studio().worker().snapshot();
  REQUIRE(snap->plan);
  d.frames(2);
  // Framed on what is shown now: the scan and its plan, not the synthetic scene before.
  const studio::ViewState& view = d.state().view;
  Eigen::Vector3f lo, hi;
  REQUIRE(studio::shown_bounds(*snap, view, studio::shown_source_pose(view, *snap), lo, hi));
  const Eigen::Vector3f centre = 0.5f * (lo + hi);
  REQUIRE((centre - synthetic_target).norm() > 1.0f);  // the two scenes are apart
  CHECK((d.state().camera.target - centre).norm() < 1e-3f);
  CHECK(d.state().camera.top_down);
}
