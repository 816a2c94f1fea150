// Cancelling the benchmark view's pass and its sweeps: between pairs, with the rows done kept, a
// resume that finishes the set, and the worker usable afterwards; the buttons, driven.

#include <catch2/catch.hpp>
#include <chrono>
#include <fstream>
#include <thread>

#include "panels/benchmark_view.hpp"
#include "runners/bench_worker.hpp"
#include "studio_test_util.hpp"
#include "ui_driver.hpp"

using namespace pagor;
using namespace pagor::test;

namespace {

// Waits (up to 10 min) until `done` holds for the worker's status.
template <class Done>
studio::BenchStatus wait_for(const studio::BenchWorker& w, Done done) {
  for (int i = 0; i < 6000; ++i) {
    const studio::BenchStatus st = w.status();
    if (done(st)) return st;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  FAIL("the benchmark worker did not get there in 10 minutes");
  return {};
}

}  // namespace

TEST_CASE("benchmark view: a cancelled pass stops between pairs, and resume finishes it") {
  TempDir tmp;
  const PairSet set = read_pair_manifest(semreg_manifest(tmp, {"03", "04", "05", "06"}));
  studio::BenchWorker worker;
  worker.open(set, semreg_config());
  worker.cancel();  // before its first pair: none runs
  const studio::BenchStatus st =
      wait_for(worker, [](const studio::BenchStatus& s) { return s.cancelled && !s.busy; });
  CHECK(st.done == 0);
  CHECK(st.total == 4);
  CHECK(st.error == "cancelled after 0 of 4 pairs");
  CHECK(st.finished != st.generation);
  for (const studio::BenchRow& r : worker.rows()) CHECK_FALSE(r.current);
  worker.rerun();
  REQUIRE(worker.wait_idle(600));
  CHECK(worker.status().done == 4);
  CHECK_FALSE(worker.status().cancelled);
  CHECK(worker.status().error.empty());
}

TEST_CASE("benchmark view: a cancelled sweep leaves no result, and the next sweep runs") {
  TempDir tmp;
  const PairSet set = read_pair_manifest(semreg_manifest(tmp, {"03", "04", "05", "06"}));
  studio::BenchWorker worker;
  worker.open(set, semreg_config());
  REQUIRE(worker.wait_idle(600));
  SweepGrid grid;
  grid.add("verification.mu", {0.5, 1.0, 2.0});
  const auto settings = sweep_settings(semreg_config(), grid);
  worker.sweep(settings, semreg_config());
  worker.cancel();
  const studio::BenchStatus st =
      wait_for(worker, [](const studio::BenchStatus& s) { return !s.sweeping; });
  CHECK_FALSE(worker.sweep_result());
  CHECK(st.sweep_error.rfind("the sweep was cancelled", 0) == 0);
  CHECK(st.sweep_done < st.sweep_total);
  CHECK_FALSE(st.cancelled);  // the pass before it was whole: no "(cancelled)", no "resume"
  CHECK(st.done == st.total);
  // The worker goes on: the same sweep again completes with a result for every setting.
  worker.sweep(settings, semreg_config());
  wait_for(worker, [&](const studio::BenchStatus& s) {
    return !s.sweeping && worker.sweep_result() != nullptr;
  });
  REQUIRE(worker.sweep_result());
  CHECK(worker.sweep_result()->result.settings.size() == 3);
  CHECK(worker.status().sweep_error.empty());
}

TEST_CASE("benchmark view: the cancel and resume buttons, driven") {
  TempDir tmp;
  studio::AppState s = semreg_files_state(tmp);
  s.bench.path = semreg_manifest(tmp, {"03", "04", "05", "06"});
  UiDriver d(s);
  d.settle();
  d.open_and_run_bench();
  d.frame();
  REQUIRE(d.find("cancel##bench", "Benchmark"));  // four pairs take seconds
  const studio::BenchStatus running = d.studio().bench().status();
  REQUIRE(running.busy);
  CHECK_THAT(studio::progress_line(running), Catch::Contains(" left (running)"));
  REQUIRE(d.click_widget("cancel##bench", "Benchmark"));
  wait_for(d.studio().bench(), [](const studio::BenchStatus& st) { return !st.busy; });
  d.frames(2);
  const studio::BenchStatus st = d.studio().bench().status();
  CHECK(st.cancelled);
  CHECK(st.done < st.total);
  // Nothing is left to wait for: the line says cancelled and gives no time left.
  CHECK_THAT(studio::progress_line(st),
             Catch::Contains("(cancelled)") && !Catch::Contains("left") &&
                 Catch::StartsWith(std::to_string(st.done) + "/4 pairs"));
  CHECK_FALSE(d.find("cancel##bench", "Benchmark"));
  CHECK_FALSE(d.texts("cancelled after", "Benchmark").empty());  // the reason, shown
  REQUIRE(d.click_widget("resume##bench", "Benchmark"));
  d.settle_bench();
  CHECK(d.studio().bench().status().done == 4);
  CHECK_FALSE(d.find("resume##bench", "Benchmark"));
}
