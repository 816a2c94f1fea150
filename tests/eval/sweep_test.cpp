#include "pagor/eval/sweep.hpp"

#include <catch2/catch.hpp>

#include "pagor/errors.hpp"
#include "support/outcome_checks.hpp"

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

void check_sweep_matches_bench(const PairSet& set, const std::vector<SweepSetting>& settings) {
  const SweepResult swept = run_sweep(set, settings);
  REQUIRE(swept.settings.size() == settings.size());
  for (std::size_t k = 0; k < settings.size(); ++k) {
    INFO("setting " << settings[k].label);
    const std::vector<PairOutcome> fresh = fresh_bench(set, settings[k].config);
    REQUIRE(swept.settings[k].outcomes.size() == fresh.size());
    for (std::size_t p = 0; p < fresh.size(); ++p)
      test::check_same_outcome(swept.settings[k].outcomes[p], fresh[p]);
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
  grid.add("verification.mu", {0.5, 1.0});
  grid.add_json("graph.thresholds", {"[0.02,0.04]", "[0.03,0.06,0.12]"});
  grid.add_json("gnc.model", {"\"se3\""});
  const auto settings = sweep_settings(default_config(), grid);
  REQUIRE(settings.size() == 4);
  CHECK(settings[0].label == "eps=0.02/0.04 mu=0.5 m");
  CHECK(settings[1].label == "eps=0.02/0.04 mu=1 m");
  CHECK(settings[2].label == "eps=0.03/0.06/0.12 mu=0.5 m");
  CHECK(settings[3].config.graph.thresholds == std::vector<double>{0.03, 0.06, 0.12});
  CHECK(settings[3].config.gnc.model == PoseModel::se3);  // a one-value dimension applies
  // Each setting names every dimension's value, in document order.
  using Values = std::vector<std::pair<std::string, std::string>>;
  CHECK(settings[3].values == Values{{"graph.thresholds", "[0.03,0.06,0.12]"},
                                     {"gnc.model", "\"se3\""},
                                     {"verification.mu", "1.0"}});
  CHECK(sweep_settings(default_config(), {}).front().label == "base");
  SweepGrid indoor;  // difference TRIM: thresholds in metres
  indoor.add_json("graph.trim", {"\"difference\""});
  indoor.add_json("graph.thresholds", {"[0.05,0.1]", "[0.2]"});
  CHECK(sweep_settings(default_config(), indoor).back().label == "eps=0.2 m");

  grid.dimensions[0].values = {"0.5", "-1.0"};
  CHECK_THROWS_WITH(sweep_settings(default_config(), grid),
                    Catch::Contains("sweep setting 2") && Catch::Contains("verification.mu"));
  SweepGrid wrong;
  wrong.add("verification.nu", {1.0});
  CHECK_THROWS_WITH(sweep_settings(default_config(), wrong),
                    Catch::Contains("verification.nu: no such parameter"));
}

TEST_CASE("any numeric parameter sweeps by key path, in 1-D and 2-D") {
  const Config base = default_config();
  SweepGrid grid;
  grid.dimensions.push_back(parse_sweep_spec(base, "gnc.noise_bound=0.5,2", "--param"));
  grid.dimensions.push_back(
      parse_sweep_spec(base, "landmarks.classes[0].cluster_tolerance=0.3,0.6,0.9", "--param"));
  const auto settings = sweep_settings(base, grid);
  REQUIRE(settings.size() == 6);
  // The landmark parameter comes first in the document, so it varies slowest.
  CHECK(settings[0].label == "landmarks.classes[0].cluster_tolerance=0.3 m gnc.noise_bound=0.5 m");
  CHECK(settings[1].config.gnc.noise_bound == 2.0);
  CHECK(settings[1].config.landmarks.classes[0].cluster_tolerance == 0.3);
  CHECK(settings[5].config.landmarks.classes[0].cluster_tolerance == 0.9);
  // Everything else is the base's.
  Config back = settings[5].config;
  back.gnc.noise_bound = base.gnc.noise_bound;
  back.landmarks.classes[0].cluster_tolerance = base.landmarks.classes[0].cluster_tolerance;
  CHECK(config_to_json(back) == config_to_json(base));

  // Values that are only valid together are set together.
  SweepGrid sizes;
  sizes.add("landmarks.classes[0].min_points", {6000});
  sizes.add("landmarks.classes[0].max_points", {7000});
  CHECK(sweep_settings(base, sizes).front().config.landmarks.classes[0].min_points == 6000);

  // Choices by name, lists of numbers as sets, integers and flags as numbers.
  CHECK(parse_sweep_dimension(base, "clique.solver", "exact,cascaded", "--solver").values ==
        std::vector<std::string>{"\"exact\"", "\"cascaded\""});
  CHECK(parse_sweep_dimension(base, "graph.thresholds", "0.1;0.2,0.4", "--thresholds").values ==
        std::vector<std::string>{"[0.1]", "[0.2,0.4]"});
  CHECK(parse_sweep_dimension(base, "refinement.enabled", "0,1", "x").values.size() == 2);
  CHECK_THROWS_WITH(parse_sweep_dimension(base, "clique.solver", "exact,fast", "--solver"),
                    Catch::Contains("--solver: element 2 'fast' is not one of"));
  CHECK_THROWS_WITH(parse_sweep_spec(base, "landmarks.classes[0].name=a", "--param"),
                    Catch::Contains("cannot be swept"));
  CHECK_THROWS_WITH(parse_sweep_spec(base, "gnc.noise_bound", "--param"),
                    Catch::Contains("expected PATH=v1,v2"));
  CHECK_THROWS_WITH(parse_sweep_spec(base, "gnc.nothing=1", "--param"),
                    Catch::Contains("no such parameter"));
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
  grid.add("verification.mu", {1.0, 0.3});
  grid.dimensions.push_back(
      parse_sweep_dimension(base, "graph.thresholds", "0.02,0.04,0.08,0.16;0.01,0.02", "eps"));
  check_sweep_matches_bench(set, sweep_settings(base, grid));
}

TEST_CASE("a sweep's numbers on a KITTI pair equal separate bench runs per setting") {
  PairSet set = kitti_pair_set(PAGOR_KITTI_DIR, "00", PAGOR_KITTI_DIR "/pairs_00_dev.txt");
  set.pairs.resize(1);
  SweepGrid grid;
  grid.add_json("clique.solver", {"\"cascaded\"", "\"exact\""});
  grid.add("verification.mu", {1.0, 2.0});
  check_sweep_matches_bench(set, sweep_settings(default_config(), grid));
}
