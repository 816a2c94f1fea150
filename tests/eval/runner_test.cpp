// The one runner over many pairs and the rates of a set: runs equal fresh ones, kept pipelines
// re-run only what a change invalidates, and a rate of nothing is undefined.

#include <algorithm>
#include <catch2/catch.hpp>
#include <chrono>
#include <fstream>
#include <mutex>
#include <nlohmann/json.hpp>
#include <numeric>
#include <sstream>
#include <thread>

#include "pagor/errors.hpp"
#include "pagor/eval/runner.hpp"
#include "pagor/eval/sweep.hpp"
#include "support/outcome_checks.hpp"
#include "support/test_util.hpp"

using namespace pagor;

namespace {

// Three generated pairs (synthetic scenes with a known pose) and one whose files do not exist.
PairSet synthetic_set() {
  PairSet set;
  set.origin = "generated";
  for (std::uint64_t seed : {3, 7, 11}) {
    PairEntry e;
    e.name = "seed " + std::to_string(seed);
    e.source.kind = PairSource::Kind::synthetic;
    e.source.synthetic_seed = seed;
    set.pairs.push_back(e);
  }
  PairEntry missing;
  missing.name = "missing";
  missing.source.kind = PairSource::Kind::files;
  missing.source.source = missing.source.target = "/nonexistent/cloud.pcd";
  set.pairs.push_back(missing);
  return set;
}

Config synthetic_config() {
  Config c = default_config();
  c.refinement.enabled = false;
  return c;
}

}  // namespace

TEST_CASE(
    "the runner gives what a fresh pipeline gives, and re-runs only what a change invalidates") {
  const PairSet set = synthetic_set();
  SetRunner runner(set);
  Config c = synthetic_config();
  const PairOutcome first = runner.run(0, c);
  REQUIRE(first.loaded);
  for (bool r : first.ran) CHECK(r);  // a pair loaded from its files runs every stage
  c.verification.mu = 0.5;
  const PairOutcome second = runner.run(0, c);
  CHECK_FALSE(second.ran[static_cast<std::size_t>(Stage::landmarks)]);
  CHECK_FALSE(second.ran[static_cast<std::size_t>(Stage::clique)]);
  CHECK(second.ran[static_cast<std::size_t>(Stage::verification)]);
  Pipeline fresh(c);
  const PairOutcome want = run_pair(fresh, set.pairs[0]);
  test::check_same_outcome(second, want);

  const PairOutcome missing = runner.run(3, c);
  CHECK_FALSE(missing.loaded);
  CHECK_THAT(missing.load_error, Catch::Contains("/nonexistent/cloud.pcd"));
}

TEST_CASE("the runner keeps pipelines within its budget, and always the last pair run") {
  SetRunner runner(synthetic_set());
  const Config c = synthetic_config();
  runner.run(0, c);
  runner.run(1, c);
  CHECK_FALSE(runner.cached(0));  // budget 0: only the last one is kept
  CHECK(runner.cached(1));
  runner.set_cache_budget(std::size_t(1) << 32);
  runner.run(0, c);
  runner.run(2, c);
  CHECK(runner.cached(0));
  CHECK(runner.cached(1));
  CHECK(runner.cached(2));
  CHECK(runner.cached_count() == 3);
  CHECK(runner.cache_bytes() > 0);
  runner.clear_cache();
  CHECK(runner.cached_count() == 0);
}

TEST_CASE("run_set: outcomes in set order, reused results, hooks in the order asked") {
  SetRunner runner(synthetic_set());
  RunSetHooks hooks;
  hooks.order = {2, 1, 0, 3};
  std::vector<std::size_t> seen;
  hooks.reuse = [](std::size_t i) -> std::optional<PairOutcome> {
    if (i != 1) return std::nullopt;
    PairOutcome o;
    o.name = "from an earlier run";
    o.loaded = true;
    o.timed = false;
    return o;
  };
  hooks.done = [&](std::size_t i, const PairOutcome&) { seen.push_back(i); };
  const std::vector<PairOutcome> out = run_set(runner, synthetic_config(), hooks);
  CHECK(seen == hooks.order);
  REQUIRE(out.size() == 4);
  CHECK(out[0].name == "seed 3");
  CHECK(out[1].name == "from an earlier run");
  CHECK_FALSE(out[3].loaded);
  std::atomic<bool> cancel{true};
  hooks.cancel = &cancel;
  CHECK_THROWS_AS(run_set(runner, synthetic_config(), hooks), Cancelled);
}

TEST_CASE("a sweep on the runner equals a benchmark run per setting") {
  const PairSet set = synthetic_set();
  SweepGrid grid;
  grid.add("verification.mu", {0.5, 1.0});
  const auto settings = sweep_settings(synthetic_config(), grid);
  SetRunner runner(set);
  const SweepResult swept = run_sweep(runner, settings);
  REQUIRE(swept.settings.size() == 2);
  for (std::size_t k = 0; k < settings.size(); ++k) {
    SetRunner fresh(set);
    const std::vector<PairOutcome> want = run_set(fresh, settings[k].config);
    for (std::size_t i = 0; i < want.size(); ++i) {
      INFO("setting " << k << ", pair " << i);
      test::check_same_outcome(swept.settings[k].outcomes[i], want[i]);
    }
  }
  // Each pair's landmarks ran once for both settings; the missing pair never loads.
  CHECK(swept.stage_runs[static_cast<std::size_t>(Stage::landmarks)] == 3);
}

TEST_CASE("rates of nothing are undefined, and shown as n/a") {
  const BenchmarkSummary none = summarize({});
  CHECK_FALSE(none.success_rate());
  CHECK_FALSE(none.upper_bound_rate());
  CHECK_FALSE(none.precision());
  CHECK_FALSE(none.recall());
  CHECK(rate_text(none.precision()) == "n/a");
  CHECK(rate_text(0.75) == "75.0 %");
  CHECK(ratio(0, 0) == std::nullopt);
  CHECK(ratio(3, 4) == 0.75);
}

TEST_CASE("the summary counts what the rows say: picks per level, unjudged accepts, verdicts") {
  PairOutcome a, b, neg, unknown;
  a.loaded = b.loaded = neg.loaded = unknown.loaded = true;
  a.has_ground_truth = b.has_ground_truth = true;
  a.selected_level = 1;
  a.success = a.accepted = true;
  a.level_success = {false, true, true};
  a.level_epsilons = {0.02, 0.04, 0.08};
  a.trim = TrimKind::ratio;
  a.diagnosis = "success";
  b.selected_level = 0;
  b.level_success = {false, false, true};
  b.diagnosis = "clique-missed";
  neg.negative = true;
  neg.accepted = true;
  neg.selected_level = 2;
  neg.level_success = {true, true, true};  // never counted: no ground truth for negatives
  unknown.accepted = true;                 // no ground truth and not a known negative
  const BenchmarkSummary s = summarize({a, b, neg, unknown});
  REQUIRE(s.levels.size() == 3);
  CHECK(s.levels[0].selected == 1);
  CHECK(s.levels[1].selected == 1);
  CHECK(s.levels[1].selected_and_succeeded == 1);
  CHECK(s.levels[2].alone_succeeds == 2);
  CHECK(s.levels[2].epsilon == 0.08);
  CHECK(s.trim == TrimKind::ratio);
  CHECK(s.accepted == 2);
  CHECK(s.true_accepts == 1);
  CHECK(s.false_accepts == 1);
  CHECK(s.accepted_unjudged == 1);
  CHECK(s.precision() == 0.5);
  CHECK(s.diagnoses ==
        std::vector<std::pair<std::string, int>>{{"success", 1}, {"clique-missed", 1}});
}

TEST_CASE("a pair's own failure fails that pair, named, and the set goes on") {
  test::TempDir dir;
  // A truncated PCD: its pair fails while the others run (a 1e30 point used to stop the run).
  std::ofstream(dir.file("cut.pcd")) << "VERSION .7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\n"
                                        "WIDTH 100\nHEIGHT 1\nPOINTS 100\nDATA binary\n0123";
  PairSet set = synthetic_set();
  set.pairs[1].source.kind = PairSource::Kind::files;
  set.pairs[1].source.source = dir.file("cut.pcd");
  set.pairs[1].source.target = dir.file("cut.pcd");
  SetRunner runner(set);
  const std::vector<PairOutcome> out = run_set(runner, synthetic_config());
  REQUIRE(out.size() == 4);
  CHECK(out[0].loaded);
  CHECK_FALSE(out[1].loaded);
  CHECK_THAT(out[1].load_error, Catch::Contains("cut.pcd: truncated PCD body"));
  CHECK(out[2].loaded);
  CHECK_FALSE(out[3].loaded);
  const BenchmarkSummary s = summarize(out);
  CHECK(s.pairs_run == 2);
  CHECK(s.skipped == 2);
}

TEST_CASE("a configuration error, the same for every pair, stops the set with its key") {
  Config c = synthetic_config();
  c.refinement.enabled = true;
  c.refinement.normal_radius = 100;  // every target point a neighbour of every other
  c.verification.voxel_size = 0.05;
  SetRunner runner(synthetic_set());
  CHECK_THROWS_WITH(run_set(runner, c), Catch::Contains("refinement.normal_radius"));
}

TEST_CASE("the rows and the summary agree: every accept is counted, failed pairs are not") {
  // Each kind of row: accepted with truth (right, wrong), without truth, a negative accepted and
  // one rejected, a failed pair.
  std::vector<PairOutcome> rows(6);
  for (auto& o : rows) o.loaded = true;
  rows[0].has_ground_truth = rows[0].success = rows[0].accepted = true;
  rows[1].has_ground_truth = rows[1].accepted = true;
  rows[2].accepted = true;  // no ground truth
  rows[3].negative = rows[3].accepted = true;
  rows[4].negative = true;
  rows[5].loaded = false;
  rows[5].load_error = "x.pcd: cannot read";
  const BenchmarkSummary s = summarize(rows);
  const auto accepts = std::count_if(rows.begin(), rows.end(),
                                     [](const PairOutcome& o) { return o.loaded && o.accepted; });
  CHECK(s.accepted_total() == accepts);
  CHECK(s.accepted_total() == 4);
  CHECK(s.accepted_unjudged == 1);
  CHECK(s.accepted == 3);  // the judged ones: the precision's denominator
  CHECK(s.precision() == Approx(1.0 / 3));
  CHECK(s.pairs_run == 5);
  CHECK(s.skipped == 1);
  CHECK(s.negatives == 2);
}

// A report without its times (every key ending in `_ms`: `timings_ms`, the diagnosis' `time_ms`,
// each level's `clique_time_ms`): what must not depend on how many jobs ran the set.
static void erase_times(nlohmann::json& j) {
  if (j.is_object())
    for (auto it = j.begin(); it != j.end();) {
      const std::string& key = it.key();
      if (key.size() > 3 && key.compare(key.size() - 3, 3, "_ms") == 0)
        it = j.erase(it);
      else
        erase_times(*it++);
    }
  else if (j.is_array())
    for (auto& child : j) erase_times(child);
}

static std::string without_timings(const std::string& report_json) {
  nlohmann::json j = nlohmann::json::parse(report_json);
  erase_times(j);
  return j.dump();
}

TEST_CASE("pairs on two worker threads give the outcomes of one, rows in set order") {
  const PairSet set = synthetic_set();
  SetRunner one(set);
  const std::vector<PairOutcome> want = run_set(one, synthetic_config());
  std::vector<std::unique_ptr<SetRunner>> runners = make_runners(set, 2);
  REQUIRE(runners.size() == 2);
  std::vector<std::size_t> done, finished;
  std::vector<SetProgress> progress;
  RunSetHooks hooks;
  hooks.finished = [&](std::size_t i, const PairOutcome&) { finished.push_back(i); };
  hooks.done = [&](std::size_t i, const PairOutcome&) { done.push_back(i); };
  hooks.progress = [&](const SetProgress& p) { progress.push_back(p); };
  const std::vector<PairOutcome> got = run_set(runners, synthetic_config(), hooks);
  CHECK(done == std::vector<std::size_t>{0, 1, 2, 3});  // set order, however they finished
  std::sort(finished.begin(), finished.end());
  CHECK(finished == std::vector<std::size_t>{0, 1, 2, 3});  // each once
  REQUIRE(progress.size() == 4);
  CHECK(progress.back().done == 4);
  CHECK(progress.back().ran == 4);
  CHECK(progress.back().seconds_left() == std::optional<double>(0.0));
  REQUIRE(got.size() == want.size());
  for (std::size_t i = 0; i < want.size(); ++i) {
    INFO("pair " << i);
    CHECK(got[i].name == want[i].name);
    CHECK(got[i].loaded == want[i].loaded);
    test::check_same_outcome(got[i], want[i]);
    if (want[i].loaded)
      CHECK(without_timings(got[i].report_json) == without_timings(want[i].report_json));
  }
  CHECK_FALSE(got[3].loaded);  // the missing pair fails its row only
  CHECK_THAT(got[3].load_error, Catch::Contains("/nonexistent/cloud.pcd"));
}

TEST_CASE("the workers with nothing left lend themselves to the calls still running") {
  // One long call and quick ones: once the quick ones are done, their workers find nothing left
  // and the long call sees them lent to it (the test waits for that, up to 20 s).
  for (int jobs : {2, 3}) {
    std::vector<std::size_t> order(static_cast<std::size_t>(jobs));
    std::iota(order.begin(), order.end(), 0);
    std::atomic<int> seen{-1};
    run_parallel(
        jobs, order,
        [&](int, std::size_t i, const std::atomic<int>* lent, const std::atomic<bool>*) {
          if (i != 0) return;
          const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(20);
          while (lent->load() < jobs - 1 && std::chrono::steady_clock::now() < until)
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
          seen = lent->load();
        },
        [](std::size_t) {});
    INFO("jobs " << jobs);
    CHECK(seen == jobs - 1);
  }
  // A pair run with workers lent (more threads than its runner's) gives the same outcome.
  const PairSet set = synthetic_set();
  SetRunner one(set), other(set);
  const PairOutcome a = one.run(0, synthetic_config());
  const std::atomic<int> two{2};
  const PairOutcome b = other.run(0, synthetic_config(), nullptr, &two);
  test::check_same_outcome(a, b);
  CHECK(without_timings(a.report_json) == without_timings(b.report_json));
  // A kept pipeline re-run with other threads too.
  Config changed = synthetic_config();
  changed.verification.mu = 0.5;
  CHECK(without_timings(one.run(0, changed).report_json) ==
        without_timings(other.run(0, changed, nullptr, &two).report_json));
}

TEST_CASE("parallel pairs: reused outcomes are not run, a cancel stops them, jobs parse") {
  const PairSet set = synthetic_set();
  std::vector<std::unique_ptr<SetRunner>> runners = make_runners(set, 2);
  RunSetHooks hooks;
  hooks.reuse = [](std::size_t i) -> std::optional<PairOutcome> {
    if (i == 3) return std::nullopt;  // only the missing pair runs
    PairOutcome o;
    o.name = "reused " + std::to_string(i);
    o.loaded = true;
    o.timed = false;
    return o;
  };
  std::vector<std::size_t> finished;
  hooks.finished = [&](std::size_t i, const PairOutcome&) { finished.push_back(i); };
  const std::vector<PairOutcome> out = run_set(runners, synthetic_config(), hooks);
  CHECK(finished == std::vector<std::size_t>{3});
  CHECK(out[0].name == "reused 0");
  CHECK(out[2].name == "reused 2");
  CHECK_FALSE(out[3].loaded);
  std::atomic<bool> cancel{true};
  RunSetHooks cancelled;
  cancelled.cancel = &cancel;
  CHECK_THROWS_AS(run_set(runners, synthetic_config(), cancelled), Cancelled);
  CHECK(parse_jobs("3", "--jobs") == 3);
  CHECK(parse_jobs("auto", "--jobs") >= 1);
  CHECK_THROWS_WITH(parse_jobs("0", "--jobs"), Catch::Contains("--jobs"));
  CHECK_THROWS_WITH(parse_jobs("2x", "--jobs"), Catch::Contains("'2x'"));
}

TEST_CASE("prepare runs once for each pair that runs, on the thread that runs it, before it ends") {
  const PairSet set = synthetic_set();
  for (int jobs : {1, 2}) {
    INFO("jobs " << jobs);
    std::vector<std::unique_ptr<SetRunner>> runners = make_runners(set, jobs);
    RunSetHooks hooks;
    hooks.reuse = [](std::size_t i) -> std::optional<PairOutcome> {
      if (i != 0) return std::nullopt;  // pair 0 is taken from an earlier run
      PairOutcome o;
      o.loaded = true;
      o.timed = false;
      return o;
    };
    std::vector<std::thread::id> prepared_on(set.pairs.size());  // each entry one pair's
    std::vector<int> prepared(set.pairs.size(), 0);
    const std::thread::id caller = std::this_thread::get_id();
    hooks.prepare = [&](std::size_t i) {
      ++prepared[i];
      prepared_on[i] = std::this_thread::get_id();
    };
    std::vector<std::size_t> seen_prepared;  // at `finished`, what prepare(i) wrote is there
    hooks.finished = [&](std::size_t i, const PairOutcome&) {
      if (prepared[i] == 1) seen_prepared.push_back(i);
    };
    run_set(runners, synthetic_config(), hooks);
    CHECK(prepared[0] == 0);  // reused: not prepared
    for (std::size_t i = 1; i < set.pairs.size(); ++i) {
      CHECK(prepared[i] == 1);
      CHECK((prepared_on[i] == caller) == (jobs == 1));  // the workers' with jobs > 1
    }
    CHECK(seen_prepared.size() == set.pairs.size() - 1);
  }
}

TEST_CASE("a sweep on two jobs equals the sweep on one") {
  const PairSet set = synthetic_set();
  SweepGrid grid;
  grid.add("verification.mu", {0.5, 1.0});
  const auto settings = sweep_settings(synthetic_config(), grid);
  const SweepResult one = run_sweep(set, settings, 1, {}, nullptr, 1);
  std::vector<int> seen(set.pairs.size() * settings.size(), 0);
  const SweepResult two = run_sweep(
      set, settings, 1, [&](int p, int k, const PairOutcome&) { ++seen[p * settings.size() + k]; },
      nullptr, 2);
  CHECK(std::all_of(seen.begin(), seen.end(), [](int n) { return n == 1; }));
  CHECK(two.stage_runs == one.stage_runs);
  REQUIRE(two.settings.size() == one.settings.size());
  for (std::size_t k = 0; k < settings.size(); ++k)
    for (std::size_t i = 0; i < set.pairs.size(); ++i) {
      INFO("setting " << k << ", pair " << i);
      CHECK(two.settings[k].outcomes[i].name == one.settings[k].outcomes[i].name);
      test::check_same_outcome(two.settings[k].outcomes[i], one.settings[k].outcomes[i]);
    }
  const auto strip = [](std::string lines) {  // the wall and mean times aside
    std::string out;
    std::istringstream in(lines);
    for (std::string line; std::getline(in, line);) {
      nlohmann::json j = nlohmann::json::parse(line);
      j.erase("wall_ms");
      j.erase("mean_time_ms");
      out += j.dump() + "\n";
    }
    return out;
  };
  CHECK(strip(sweep_json_lines(two)) == strip(sweep_json_lines(one)));
}
