#include "pagor/sets/sweep.hpp"

#include <catch2/catch.hpp>

#include "pagor/errors.hpp"

using namespace pagor;

namespace {

// What a separate `pagor bench` run per setting gives: a fresh pipeline for every pair.
std::vector<PairOutcome> fresh_bench(const PairSet& set, const Config& config) {
  std::vector<PairOutcome> out;
  for (const PairEntry& e : set.pairs) {
    Pipeline pipeline(config);
    out.push_back(run_pair(pipeline, e));
  }
  return out;
}

void check_equal(const PairOutcome& swept, const PairOutcome& fresh) {
  INFO("pair " << fresh.name);
  REQUIRE(swept.loaded == fresh.loaded);
  CHECK(swept.selected_level == fresh.selected_level);
  CHECK(swept.success == fresh.success);
  CHECK(swept.upper_bound == fresh.upper_bound);
  CHECK(swept.accepted == fresh.accepted);
  CHECK(swept.level_success == fresh.level_success);
  CHECK(swept.margin == fresh.margin);
  REQUIRE(swept.error.has_value() == fresh.error.has_value());
  if (fresh.error) {
    CHECK(swept.error->translation == fresh.error->translation);
    CHECK(swept.error->rotation_deg == fresh.error->rotation_deg);
  }
}

void check_sweep_matches_bench(const PairSet& set, const std::vector<SweepSetting>& settings) {
  const SweepResult swept = run_sweep(set, settings);
  REQUIRE(swept.settings.size() == settings.size());
  for (std::size_t k = 0; k < settings.size(); ++k) {
    INFO("setting " << settings[k].label);
    const std::vector<PairOutcome> fresh = fresh_bench(set, settings[k].config);
    REQUIRE(swept.settings[k].outcomes.size() == fresh.size());
    for (std::size_t p = 0; p < fresh.size(); ++p)
      check_equal(swept.settings[k].outcomes[p], fresh[p]);
    const BenchmarkSummary s = summarize(fresh);
    CHECK(swept.settings[k].summary.successes == s.successes);
    CHECK(swept.settings[k].summary.upper_bound == s.upper_bound);
    CHECK(swept.settings[k].summary.accepted == s.accepted);
  }
  // Landmarks and correspondences ran once per pair: the settings reused them.
  CHECK(swept.stage_runs[static_cast<int>(Stage::landmarks)] == swept.pairs);
  CHECK(swept.stage_runs[static_cast<int>(Stage::correspondences)] == swept.pairs);
}

}  // namespace

TEST_CASE("the sweep grid varies mu fastest and labels the dimensions that vary") {
  SweepGrid grid;
  grid.mus = {0.5, 1.0};
  grid.threshold_sets = {{0.02, 0.04}, {0.03, 0.06, 0.12}};
  grid.models = {PoseModel::se3};
  const auto settings = sweep_settings(default_config(), grid);
  REQUIRE(settings.size() == 4);
  CHECK(settings[0].label == "eps=0.02/0.04 mu=0.5 m");
  CHECK(settings[1].label == "eps=0.02/0.04 mu=1 m");
  CHECK(settings[2].label == "eps=0.03/0.06/0.12 mu=0.5 m");
  CHECK(settings[3].config.graph.thresholds == std::vector<double>{0.03, 0.06, 0.12});
  CHECK(settings[3].config.gnc.model == PoseModel::se3);  // a one-value dimension applies
  CHECK(sweep_settings(default_config(), {}).front().label == "base");
  SweepGrid indoor;  // difference TRIM: thresholds in metres
  indoor.trims = {TrimKind::difference};
  indoor.threshold_sets = {{0.05, 0.1}, {0.2}};
  CHECK(sweep_settings(default_config(), indoor).back().label == "eps=0.2 m");

  grid.mus = {0.5, -1.0};
  CHECK_THROWS_WITH(
      sweep_settings(default_config(), grid),
      Catch::Contains("sweep setting 2 (eps=0.02/0.04 mu=-1 m)") && Catch::Contains("mu"));
}

TEST_CASE("number lists and threshold sets are parsed with the element named") {
  CHECK(parse_number_list("0.5, 1,2", "--mu") == std::vector<double>{0.5, 1.0, 2.0});
  CHECK(parse_threshold_sets("0.02,0.04;0.1", "--thresholds") ==
        std::vector<std::vector<double>>{{0.02, 0.04}, {0.1}});
  CHECK_THROWS_WITH(parse_number_list("0.5,x", "--mu"),
                    Catch::Contains("--mu: element 2 'x' is not a number"));
  CHECK_THROWS_AS(parse_number_list("", "--mu"), InputError);
}

TEST_CASE("a sweep's numbers on two semreg-dev pairs equal separate bench runs per setting") {
  PairSet set = read_pair_manifest(PAGOR_SOURCE_DIR "/bench/manifests/semreg-dev.txt");
  REQUIRE(set.pairs.size() >= 2);
  set.pairs.resize(2);
  const Config base = load_config(PAGOR_SOURCE_DIR "/bench/manifests/semreg-dev.json");
  SweepGrid grid;
  grid.mus = {1.0, 0.3};
  grid.threshold_sets = {base.graph.thresholds, {0.01, 0.02}};
  check_sweep_matches_bench(set, sweep_settings(base, grid));
}

TEST_CASE("a sweep's numbers on a KITTI pair equal separate bench runs per setting") {
  PairSet set = kitti_pair_set(PAGOR_KITTI_DIR, "00", PAGOR_KITTI_DIR "/pairs_00_dev.txt");
  set.pairs.resize(1);
  SweepGrid grid;
  grid.solvers = {CliqueSolver::cascaded, CliqueSolver::exact};
  grid.mus = {1.0, 2.0};
  check_sweep_matches_bench(set, sweep_settings(default_config(), grid));
}
