// The benchmark view: its runner's re-evaluation against fresh runs, the plots (ticks, CSV, PNG),
// session round trip, and a driven-UI walk over every widget of the view.

#include <algorithm>
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "pagor/errors.hpp"
#include "panels/benchmark_view.hpp"
#include "runners/bench_worker.hpp"
#include "runners/pair_queue.hpp"
#include "studio_test_util.hpp"
#include "support/outcome_checks.hpp"
#include "ui_driver.hpp"
#include "widgets/bench_plots.hpp"
#include "widgets/plot_export.hpp"

using namespace pagor;
using namespace pagor::test;

namespace {

void wait(studio::BenchWorker& w) {
  REQUIRE(w.wait_idle(600));
}

}  // namespace

TEST_CASE("benchmark view: a parameter change re-evaluates the set as a fresh run would") {
  TempDir tmp;
  const PairSet set = read_pair_manifest(semreg_manifest(tmp, {"03", "05"}));
  studio::BenchWorker worker;
  Config config = semreg_config();
  worker.open(set, config);
  wait(worker);
  CHECK(worker.status().cached == 2);
  for (const Config& next : {[&] {
                               Config c = config;
                               c.verification.mu = 0.4;
                               return c;
                             }(),
                             [&] {
                               Config c = config;
                               c.graph.thresholds = {0.01, 0.03};
                               return c;
                             }()}) {
    worker.set_config(next);
    wait(worker);
    const std::vector<studio::BenchRow> rows = worker.rows();
    REQUIRE(rows.size() == set.pairs.size());
    for (std::size_t i = 0; i < rows.size(); ++i) {
      Pipeline fresh(next);
      const PairOutcome f = run_pair(fresh, set.pairs[i]);
      const PairOutcome& o = rows[i].outcome;
      INFO("pair " << f.name);
      CHECK(rows[i].current);
      CHECK(rows[i].cached);
      CHECK(o.selected_level == f.selected_level);
      CHECK(o.success == f.success);
      CHECK(o.accepted == f.accepted);
      CHECK(o.level_success == f.level_success);
      CHECK(o.margin == f.margin);
      REQUIRE(o.error.has_value() == f.error.has_value());
      if (f.error) CHECK(o.error->translation == f.error->translation);
    }
  }
  // A budget too small for any pipeline: pairs run from their files and none is kept but the
  // last one run (the runner keeps the pipeline in use, SetRunner::run).
  worker.set_budget(1);
  worker.open(set, config);
  wait(worker);
  CHECK(worker.status().cached <= 1);
  CHECK(worker.status().done == 2);
}

// A sweep over mu in {0.5, 1} on the small set, in the view's worker with `jobs` jobs, gives what
// core run_sweep gives with one: per setting the successes and upper bound, per pair the name,
// verdict, selected level and score.
void check_sweep_equals_core(int jobs) {
  TempDir tmp;
  const PairSet set = read_pair_manifest(semreg_manifest(tmp, {"03", "05"}));
  studio::BenchWorker worker;
  worker.set_jobs(jobs);
  worker.open(set, semreg_config());
  SweepGrid grid;
  grid.add("verification.mu", {0.5, 1.0});
  const auto settings = sweep_settings(semreg_config(), grid);
  worker.sweep(settings, semreg_config());
  for (int i = 0; i < 6000 && (worker.status().sweeping || !worker.sweep_result()); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  const auto record = worker.sweep_result();
  REQUIRE(record);
  CHECK(worker.status().sweep_done == worker.status().sweep_total);
  CHECK(worker.status().sweep_total == 4);
  const SweepResult want = run_sweep(set, settings);
  const SweepResult& got = record->result;
  REQUIRE(got.settings.size() == want.settings.size());
  for (std::size_t k = 0; k < want.settings.size(); ++k) {
    CHECK(got.settings[k].summary.successes == want.settings[k].summary.successes);
    CHECK(got.settings[k].summary.upper_bound == want.settings[k].summary.upper_bound);
    for (std::size_t p = 0; p < set.pairs.size(); ++p) {
      const PairOutcome& g = got.settings[k].outcomes[p];
      const PairOutcome& w = want.settings[k].outcomes[p];
      CHECK(g.name == w.name);
      CHECK(g.accepted == w.accepted);
      CHECK(g.selected_level == w.selected_level);
      CHECK(g.score == w.score);
    }
  }
}

TEST_CASE("benchmark view: a sweep over the open set equals core run_sweep") {
  check_sweep_equals_core(1);
}

// The small manifest and a pair whose source file is empty (its row fails on its own account).
PairSet set_with_broken_pair(const TempDir& tmp) {
  PairSet set = read_pair_manifest(semreg_manifest(tmp, {"03", "05"}));
  PairEntry broken = set.pairs.front();
  broken.name = "broken";
  broken.source.source = tmp.file("empty.pcd");
  std::ofstream(broken.source.source).flush();
  set.pairs.insert(set.pairs.begin() + 1, broken);
  return set;
}

// Rows of two runs agree on what a pair's outcome is (not on its times).
void check_same_outcomes(const std::vector<studio::BenchRow>& got,
                         const std::vector<studio::BenchRow>& want) {
  REQUIRE(got.size() == want.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    INFO("row " << i);
    CHECK(got[i].done);
    CHECK(got[i].current);
    test::check_same_outcome(got[i].outcome, want[i].outcome);
  }
}

TEST_CASE("benchmark view: two jobs give the rows of one, also after a change mid-pass") {
  TempDir tmp;
  const PairSet set = set_with_broken_pair(tmp);
  const Config a = semreg_config();
  Config b = a;
  b.verification.mu = 0.4;
  studio::BenchWorker one;
  one.open(set, a);
  wait(one);
  const std::vector<studio::BenchRow> rows_a = one.rows();
  one.set_config(b);
  wait(one);
  const std::vector<studio::BenchRow> rows_b = one.rows();
  CHECK(one.status().jobs == 1);
  CHECK(rows_a[1].outcome.load_error.find("empty.pcd") != std::string::npos);
  CHECK(rows_a[0].outcome.loaded);  // the broken pair fails its row only
  CHECK(rows_a[2].outcome.loaded);

  studio::BenchWorker two;
  two.set_jobs(2);
  two.open(set, a);
  // The progress counts each pair once, in step with the rows that are done.
  for (std::size_t seen = 0; !two.wait_idle(0.02);) {
    const studio::BenchStatus st = two.status();
    CHECK(static_cast<std::size_t>(st.done) >= seen);
    CHECK(st.done <= st.total);
    seen = static_cast<std::size_t>(st.done);
  }
  studio::BenchStatus st = two.status();
  CHECK(st.jobs == 2);
  CHECK(st.done == 3);
  CHECK(st.pass_progress().done == 3);
  CHECK(st.pass_progress().total == 3);
  REQUIRE(st.pass_progress().seconds_left());
  CHECK(*st.pass_progress().seconds_left() == Approx(0.0));  // none left [s]
  CHECK(st.cached == 2);  // the broken pair has no pipeline to keep
  check_same_outcomes(two.rows(), rows_a);
  // A configuration change re-evaluates on both runners, each its kept pairs.
  two.set_config(b);
  wait(two);
  check_same_outcomes(two.rows(), rows_b);
  CHECK(two.status().cached == 2);
  // A change while the pass runs (once a pair is done, unless the pass was quicker) cancels it;
  // the rows are then those of the last configuration.
  two.set_config(a);
  while (two.status().done == 0 && !two.wait_idle(0.01)) {
  }
  two.set_config(b);
  wait(two);
  check_same_outcomes(two.rows(), rows_b);
  CHECK(two.status().done == 3);
}

TEST_CASE("the pair queue: a job's kept pairs first, then the unkept, then another's last") {
  // Pairs 0 and 3 kept by runner 0; 1, 2 and 5 by runner 1; 4 by none.
  studio::PairQueue q({0, 1, 1, 0, -1, 1}, 2);
  const auto next = [&](int job) { return q.next(job).value_or(99); };
  CHECK(next(0) == 0);
  CHECK(next(0) == 3);
  CHECK(next(0) == 4);  // its own are done: the pair no runner keeps
  CHECK(next(0) == 5);  // then the last of runner 1's
  CHECK(next(1) == 1);
  CHECK(next(1) == 2);
  CHECK_FALSE(q.next(1));
  CHECK_FALSE(q.next(0));
  // Jobs on threads of their own take every pair exactly once.
  std::vector<int> home(200);
  for (std::size_t i = 0; i < home.size(); ++i) home[i] = static_cast<int>(i * 7 % 5) - 1;
  studio::PairQueue shared(home, 4);
  std::vector<std::vector<std::size_t>> taken(4);
  std::vector<std::thread> jobs;
  for (int w = 0; w < 4; ++w)
    jobs.emplace_back([&, w] {
      while (const auto i = shared.next(w)) taken[static_cast<std::size_t>(w)].push_back(*i);
    });
  for (std::thread& t : jobs) t.join();
  std::vector<int> count(home.size(), 0);
  for (const auto& t : taken)
    for (std::size_t i : t) ++count[i];
  CHECK(std::all_of(count.begin(), count.end(), [](int n) { return n == 1; }));
}

TEST_CASE("benchmark view: a sweep with two jobs equals core run_sweep with one") {
  check_sweep_equals_core(2);
}

TEST_CASE("benchmark view: cancel stops every job between pairs, and resume finishes") {
  TempDir tmp;
  const PairSet set = set_with_broken_pair(tmp);
  studio::BenchWorker worker;
  worker.set_jobs(2);
  worker.open(set, semreg_config());
  // At once: before its first pair no job runs one; a pair that fails at once (the broken one)
  // may be done before the cancel arrives on a busy machine (seen in CI: 1 of 3).
  worker.cancel();
  for (int i = 0; i < 60000 && !(worker.status().cancelled && !worker.status().busy); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  studio::BenchStatus st = worker.status();
  CHECK(st.cancelled);
  CHECK(st.done < st.total);
  CHECK(st.error == "cancelled after " + std::to_string(st.done) + " of 3 pairs");
  int current_at_cancel = 0;
  for (const studio::BenchRow& r : worker.rows()) current_at_cancel += r.current;
  CHECK(current_at_cancel == st.done);
  // Cancelled once the first pair is done: the jobs stop after the pairs in progress (or the
  // pass had finished), and the rows done are the count the status gives.
  worker.rerun();
  while (worker.status().done == 0 && !worker.wait_idle(0.01)) {
  }
  worker.cancel();
  for (int i = 0; i < 60000 && worker.status().busy; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  st = worker.status();
  CHECK_FALSE(st.busy);
  int current = 0;
  for (const studio::BenchRow& r : worker.rows()) current += r.current;
  CHECK(current == st.done);
  if (st.cancelled)
    CHECK(st.done < st.total);
  else
    CHECK(st.done == st.total);
  worker.rerun();
  wait(worker);
  CHECK(worker.status().done == 3);
  CHECK_FALSE(worker.status().cancelled);
  // A sweep cancelled on two jobs leaves no result.
  SweepGrid grid;
  grid.add("verification.mu", {0.5, 1.0, 2.0});
  worker.sweep(sweep_settings(semreg_config(), grid), semreg_config());
  worker.cancel();
  for (int i = 0; i < 60000 && worker.status().sweeping; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  CHECK_FALSE(worker.sweep_result());
  CHECK(worker.status().sweep_error.rfind("the sweep was cancelled", 0) == 0);
  // Cancelled once a pair's settings are done: no result, unless the sweep had finished.
  worker.sweep(sweep_settings(semreg_config(), grid), semreg_config());
  for (int i = 0; i < 60000 && worker.status().sweeping && worker.status().sweep_done == 0; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  worker.cancel();
  for (int i = 0; i < 60000 && worker.status().sweeping; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  st = worker.status();
  CHECK_FALSE(st.sweeping);
  if (worker.sweep_result()) {
    CHECK(st.sweep_done == st.sweep_total);
  } else {
    CHECK(st.sweep_done < st.sweep_total);
    CHECK(st.sweep_error.rfind("the sweep was cancelled after", 0) == 0);
  }
}

TEST_CASE("plots: round ticks, CSV with units, and a PNG") {
  CHECK(studio::nice_ticks(0, 100) == std::vector<double>{0, 20, 40, 60, 80, 100});
  CHECK(studio::nice_ticks(0.013, 0.18).front() == Approx(0.0));
  CHECK(studio::nice_ticks(0.013, 0.18)[1] == Approx(0.05));
  studio::Plot p;
  p.kind = studio::PlotKind::bars;
  p.value_label = "success";
  p.value_unit = "%";
  p.categories = {"mu=0.5", "mu=1"};
  p.series = {{"success", {}, {50, 100}}, {"upper bound", {}, {100, 100}}};
  CHECK(studio::plot_csv(p) ==
        "\"category\",\"success [%]\",\"upper bound [%]\"\n\"mu=0.5\",50,100\n\"mu=1\",100,100\n");
  studio::Plot l;
  l.kind = studio::PlotKind::lines;
  l.x_label = "mu";
  l.x_unit = "m";
  l.value_label = "success";
  l.value_unit = "%";
  l.series = {{"success", {0.5, 1}, {50, 100}}};
  CHECK(studio::plot_csv(l) ==
        "\"mu [m]\",\"series\",\"success [%]\"\n0.5,\"success\",50\n1,\"success\",100\n");

  TempDir tmp;
  const std::string png = tmp.file("plot.png");
  studio::export_plot_png(p, png, 400, 300);
  std::ifstream in(png, std::ios::binary);
  char magic[8] = {};
  in.read(magic, 8);
  CHECK(std::string(magic + 1, 3) == "PNG");
  CHECK_THROWS_AS(studio::export_plot_png(p, tmp.file("no/such/dir/plot.png"), 400, 300),
                  InputError);
}

TEST_CASE("picking statistics count selections and lone successes per level") {
  PairOutcome a, b, neg;
  a.loaded = b.loaded = neg.loaded = true;
  a.has_ground_truth = b.has_ground_truth = true;
  a.selected_level = 1;
  a.success = true;
  a.level_success = {false, true, true};
  b.selected_level = 0;
  b.level_success = {false, false, true};
  neg.negative = true;
  neg.selected_level = 2;
  neg.level_success = {true, true, true};  // never counted: no ground truth for negatives
  a.score = 10;
  const studio::Plot p = studio::picking_plot(summarize({a, b, neg}));
  REQUIRE(p.categories.size() == 3);
  CHECK(p.series[0].y == std::vector<double>{1, 1, 0});  // selected
  CHECK(p.series[1].y == std::vector<double>{0, 1, 2});  // alone would succeed
  CHECK(p.series[2].y == std::vector<double>{0, 1, 0});  // selected and succeeded
}

TEST_CASE("benchmark view: state saved and restored with the session") {
  TempDir tmp;
  studio::AppState s = synthetic_state(tmp);
  s.main_view = studio::MainView::benchmark;
  s.bench.open = true;
  s.bench.source = studio::BenchSource::kitti_pairs;
  s.bench.path = "pairs.txt";
  s.bench.filter = "0";
  s.bench.sort = 3;
  s.bench.descending = true;
  s.bench.budget_mib = 300;
  s.bench.sweep_path = "gnc.noise_bound";
  s.bench.sweep_values = "0.5,1";
  studio::save_session(s, tmp.file("s.json"));
  studio::AppState r;
  studio::load_session(tmp.file("s.json"), r);
  CHECK(r.main_view == studio::MainView::benchmark);
  CHECK(r.bench.open);
  CHECK(r.bench.source == studio::BenchSource::kitti_pairs);
  CHECK(r.bench.path == "pairs.txt");
  CHECK(r.bench.filter == "0");
  CHECK(r.bench.sort == 3);
  CHECK(r.bench.descending);
  CHECK(r.bench.budget_mib == 300);
  CHECK(r.bench.sweep_path == "gnc.noise_bound");
  CHECK(r.bench.sweep_values == "0.5,1");
  // A session written before sweeps took any parameter: its mu values become a sweep of mu.
  std::ofstream(tmp.file("old.json"))
      << R"({"schema": "pagor.session/1", "benchmark": {"sweep_mu": "0.2,0.4"}})";
  studio::load_session(tmp.file("old.json"), r);
  CHECK(r.bench.sweep_path == "verification.mu");
  CHECK(r.bench.sweep_values == "0.2,0.4");
  // The row filter is stored as the number it always was (0 all ... 4 rejected).
  s.bench.show = studio::RowFilter::accepted;
  studio::save_session(s, tmp.file("s.json"));
  CHECK(nlohmann::json::parse(std::ifstream(tmp.file("s.json")))["benchmark"]["show"] == 3);
  std::ofstream(tmp.file("rejected.json"))
      << R"({"schema": "pagor.session/1", "benchmark": {"show": 4}})";
  studio::load_session(tmp.file("rejected.json"), r);
  CHECK(r.bench.show == studio::RowFilter::rejected);
  std::ofstream(tmp.file("bad.json"))
      << R"({"schema": "pagor.session/1", "benchmark": {"show": 9}})";
  CHECK_THROWS_WITH(studio::load_session(tmp.file("bad.json"), r),
                    Catch::Contains("benchmark") && Catch::Contains("show"));
}

TEST_CASE("benchmark view: jobs saved with the session, 1 when absent, checked when read") {
  TempDir tmp;
  studio::AppState s = synthetic_state(tmp);
  s.bench.jobs = 3;
  studio::save_session(s, tmp.file("s.json"));
  CHECK(nlohmann::json::parse(std::ifstream(tmp.file("s.json")))["benchmark"]["jobs"] == 3);
  studio::AppState r;
  studio::load_session(tmp.file("s.json"), r);
  CHECK(r.bench.jobs == 3);
  std::ofstream(tmp.file("old.json")) << R"({"schema": "pagor.session/1", "benchmark": {}})";
  studio::load_session(tmp.file("old.json"), r);
  CHECK(r.bench.jobs == 1);
  for (const char* bad : {"0", "1e9", "\"x\"", "65", "2.5"}) {
    INFO("jobs: " << bad);
    std::ofstream(tmp.file("bad.json"))
        << R"({"schema": "pagor.session/1", "benchmark": {"jobs": )" << bad << "}}";
    CHECK_THROWS_WITH(studio::load_session(tmp.file("bad.json"), r),
                      Catch::Contains("benchmark.jobs"));
  }
}

TEST_CASE("every widget of the benchmark view, driven") {
  TempDir tmp;
  studio::AppState s = semreg_files_state(tmp);
  s.bench.path = semreg_manifest(tmp, {"03", "05"});
  s.bench.plot_path = tmp.file("plot");
  UiDriver d(s);
  d.settle();
  d.open_and_run_bench();
  d.settle_bench();
  CHECK(d.studio().bench().status().done == 2);
  // A row opens its pair in the pair view; the data panel leads back with the table kept.
  REQUIRE(d.click_widget("03##bench_row0"));
  d.settle();
  CHECK(d.state().main_view == studio::MainView::pair);
  CHECK(d.state().data.source.find("03/source.pcd") != std::string::npos);
  REQUIRE(d.click_widget("back to the benchmark", "Pagor Studio"));
  d.frames(2);
  CHECK(d.studio().bench().rows().size() == 2);
  const int acted = exercise_every_widget(
      d,
      [&] {
        // Back to the view with the set open (after 'pair view', 'close' or a row click).
        hide_clouds(d.state());
        d.state().dialog.open = false;  // the file browser has a test of its own
        if (d.state().main_view == studio::MainView::benchmark && d.studio().bench().can_rerun())
          return;
        d.state().bench.path = semreg_manifest(tmp, {"03", "05"});
        d.state().bench.source = studio::BenchSource::manifest;
        if (!d.studio().bench().can_rerun()) d.studio().open_benchmark_now();
        d.state().main_view = studio::MainView::benchmark;
        d.frames(2);
      },
      200, "Benchmark",
      // The cancel buttons would stop the sweep this test applies below (studio_cancel_test
      // drives them).
      [](const studio::ui::WidgetRecord& w) { return w.label.rfind("cancel", 0) == 0; });
  d.settle_bench();
  // A sweep's table applies a setting to the session. The walk clicks 'run sweep' at a moment
  // its order and the build's speed decide (the set may be reopening, or the swept parameter
  // one that re-runs the front end per setting, which takes minutes in a sanitizer build), so
  // wait for its sweep by the clock, and if it left none, sweep mu over the set here.
  d.state().bench.show = studio::RowFilter::all;
  d.state().bench.filter.clear();
  const auto wait_sweep = [&] {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(15);
    while (d.studio().bench().status().sweeping && std::chrono::steady_clock::now() < deadline)
      d.frame();
    d.frames(3);
  };
  wait_sweep();
  if (!d.studio().bench().sweep_result()) {
    INFO("the walk's sweep: " << d.studio().bench().status().sweep_error);
    REQUIRE(d.studio().bench().can_rerun());
    SweepGrid grid;
    grid.add("verification.mu", {0.5, 1.0});
    d.studio().bench().sweep(sweep_settings(d.state().config, grid), d.state().config);
    wait_sweep();
  }
  const auto sweep = d.studio().bench().sweep_result();
  INFO("sweep error: " << d.studio().bench().status().sweep_error);
  REQUIRE(sweep);
  REQUIRE(d.click_widget("apply##sweep0"));
  d.frames(2);
  CHECK(d.state().config.verification.mu ==
        sweep->result.settings[0].setting.config.verification.mu);
  d.state().bench.source = studio::BenchSource::kitti_pairs;
  d.frames(2);
  CHECK(d.find("KITTI root##bench", "Benchmark"));
  std::set<std::string> benchmark_widgets;
  for (const std::string& t : d.touched())
    if (t.rfind("Benchmark/", 0) == 0) benchmark_widgets.insert(t);
  CHECK(benchmark_widgets.size() >= 15);
  WARN("acted " << acted << ", benchmark widgets touched: " << benchmark_widgets.size());
}

TEST_CASE("sweep line plots: success and one pair's D against mu, none for mixed grids") {
  SweepGrid grid;
  grid.add("verification.mu", {0.5, 1.0});
  SweepResult r;
  for (const SweepSetting& s : sweep_settings(default_config(), grid)) {
    PairOutcome o;
    o.name = "p";
    o.loaded = o.has_ground_truth = true;
    o.success = s.config.verification.mu > 0.7;
    o.accepted = o.success;
    o.score = 100 * s.config.verification.mu;
    SweepSettingResult sr{s, {o}, summarize({o}), 0.0};
    r.settings.push_back(sr);
  }
  const studio::Plot line = studio::sweep_line_plot(r);
  REQUIRE(line.series.size() == 4);  // success, upper bound, verdict precision and recall
  CHECK(line.x_unit == "m");
  CHECK(line.series[0].x == std::vector<double>{0.5, 1.0});
  CHECK(line.series[0].y == std::vector<double>{0, 100});
  CHECK(line.series[2].label == "verdict precision");
  CHECK(line.series[3].label == "verdict recall");
  CHECK(std::isnan(line.series[2].y[0]));  // nothing accepted: undefined, not 0 %
  CHECK(line.series[2].y[1] == 100);
  CHECK(line.series[3].y[1] == 100);
  const studio::Plot pair = studio::sweep_pair_plot(r, 0);
  REQUIRE(pair.series.size() == 2);
  CHECK(pair.series[0].x == std::vector<double>{1.0});   // success
  CHECK(pair.series[1].y == std::vector<double>{50.0});  // failure, D = 50 m
  // Values that are not numbers (a choice) have no line.
  r.settings[0].setting.values[0].second = "\"ratio\"";
  CHECK(studio::sweep_line_plot(r).series.empty());
}

TEST_CASE("rates of nothing are n/a, not 0 % or 100 %") {
  BenchmarkSummary none;  // an empty set: no pair with a ground truth, nothing accepted
  const studio::Plot p = studio::rates_plot(none);
  REQUIRE(p.series.size() == 1);
  REQUIRE(p.series[0].y.size() == 4);
  for (double y : p.series[0].y) CHECK(std::isnan(y));
  CHECK(studio::plot_csv(p).find("nan") == std::string::npos);
  BenchmarkSummary some;
  some.with_truth = 4;
  some.successes = 3;
  some.upper_bound = 4;
  some.accepted = 2;
  some.true_accepts = 2;
  const studio::Plot q = studio::rates_plot(some);
  CHECK(q.series[0].y == std::vector<double>{75, 100, 100, 100.0 * (2.0 / 3.0)});
  CHECK(studio::summary_text(none) ==
        "success 0/0 (n/a), upper bound 0/0 (n/a); verdict: 0 accepted (0 without truth), "
        "precision n/a, recall n/a; mean time 0 ms per pair");
  CHECK_THAT(studio::summary_text(some),
             Catch::StartsWith("success 3/4 (75.0 %), upper bound 4/4 (100.0 %); verdict: 2 "
                               "accepted (0 without truth), precision 100.0 %, recall 66.7 %"));
  some.accepted_unjudged = 1;  // a row that says "accept" without a truth is counted too
  CHECK_THAT(studio::summary_text(some), Catch::Contains("verdict: 3 accepted (1 without truth)"));
  BenchmarkSummary failed;  // every pair failed: no rate, but the line says why
  failed.skipped = 6;
  CHECK_THAT(studio::summary_text(failed),
             Catch::StartsWith("6 pairs failed (in no rate: see their rows); success 0/0 (n/a)"));
}

TEST_CASE("a session reopens its set in the view it was saved in") {
  TempDir tmp;
  for (const studio::MainView view : {studio::MainView::pair, studio::MainView::benchmark}) {
    studio::AppState s = files_state(tmp);
    s.config = semreg_config();
    s.bench.path = semreg_manifest(tmp, {"03", "05"});
    s.bench.open = true;  // a set is open, and the view is `view` (a row opened: the pair view)
    s.main_view = view;
    studio::save_session(s, tmp.file("s.json"));
    studio::AppState loaded = files_state(tmp);
    loaded.session_path = tmp.file("s.json");
    UiDriver d(loaded);
    d.studio().load_session_now();
    CHECK(d.state().bench.open);
    CHECK(d.state().main_view == view);
  }
}
