// pagor bench: every pair of a pairs set (KITTI pairs file or generic manifest), a row per pair,
// the success rate, the acceptance verdict's precision and recall, and stage times. With --out,
// results go through a journal (bench_journal.hpp) so a killed run loses nothing and --resume
// continues it.

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <optional>
#include <thread>

#include "bench_journal.hpp"
#include "command.hpp"
#include "common/outputs.hpp"
#include "pagor/errors.hpp"
#include "pagor/eval/benchmark.hpp"
#include "pagor/eval/runner.hpp"
#include "pagor/io/atomic_file.hpp"
#include "pagor/io/file_input.hpp"

namespace pagor::cli {
namespace {

void print_row(const PairOutcome& o) {
  if (!o.loaded) {  // the pair failed: its row says why
    std::printf("%-14s failed: %s\n", o.name.c_str(), o.load_error.c_str());
    std::fflush(stdout);
    return;
  }
  const char* verdict = o.accepted ? "accept" : "reject";
  const char* truth = o.negative ? "neg" : (o.has_ground_truth ? (o.success ? "yes" : "no") : "-");
  char time[16] = "resumed";
  if (o.timed) std::snprintf(time, sizeof(time), "%.1f", o.total_ms);
  const char* diagnosis = o.diagnosis.empty() ? "-" : o.diagnosis.c_str();
  // The one outcome a loop-closing user cannot afford: marked, in red on a terminal.
  const std::string mark = !o.accepted_wrong()      ? ""
                           : isatty(fileno(stdout)) ? "  \033[1;31m<- WRONG POSE ACCEPTED\033[0m"
                                                    : "  <- WRONG POSE ACCEPTED";
  if (o.error)
    std::printf("%-14s %6d %10.2f %11.2f %8s %6s %8s %10s  %s%s\n", o.name.c_str(),
                o.selected_level, o.error->translation, o.error->rotation_deg, truth,
                o.upper_bound ? "yes" : "no", verdict, time, diagnosis, mark.c_str());
  else
    std::printf("%-14s %6s %10s %11s %8s %6s %8s %10s  %s%s\n", o.name.c_str(),
                o.selected_level >= 0 ? std::to_string(o.selected_level).c_str() : "-", "-", "-",
                truth, o.has_ground_truth ? (o.upper_bound ? "yes" : "no") : "-", verdict, time,
                diagnosis, mark.c_str());
  std::fflush(stdout);
}

void print_summary(const BenchmarkSummary& s, const Config& config) {
  std::printf("\npairs run: %d%s\n", s.pairs_run,
              s.skipped ? (" (" + std::to_string(s.skipped) + " more failed)").c_str() : "");
  if (s.with_truth > 0) {
    std::printf("success (selected pose, %.1f m / %.1f deg): %d/%d = %s\n",
                config.evaluation.max_translation_error, config.evaluation.max_rotation_error,
                s.successes, s.with_truth, rate_text(s.success_rate()).c_str());
    std::printf("upper bound (any level succeeds):       %d/%d = %s\n", s.upper_bound, s.with_truth,
                rate_text(s.upper_bound_rate()).c_str());
  }
  // Every pair whose row says "accept" is counted here; the precision judges those that can be.
  std::printf(
      "verdict: %d accepted; precision %s (%d right, %d wrong), recall %s of the %d successful "
      "pairs; %d known negatives\n",
      s.accepted_total(), rate_text(s.precision()).c_str(), s.true_accepts, s.false_accepts,
      rate_text(s.recall()).c_str(), s.successes, s.negatives);
  if (s.accepted_unjudged > 0)
    std::printf("         of the %d accepted, %d without a ground truth to judge them by\n",
                s.accepted_total(), s.accepted_unjudged);
  std::printf("\n%-18s %10s %12s\n", "stage", "mean [ms]", "median [ms]");
  for (int i = 0; i < kStageCount; ++i)
    std::printf("%-18s %10.2f %12.2f\n", stage_name(static_cast<Stage>(i)),
                s.mean_ms[static_cast<std::size_t>(i)], s.median_ms[static_cast<std::size_t>(i)]);
  std::printf("%-18s %10.2f %12.2f\n", "total", s.mean_total_ms, s.median_total_ms);
  if (!s.diagnoses.empty()) {  // e.g. "diagnosis: 9 success, 1 clique-missed"
    std::printf("diagnosis (pairs with ground truth):");
    for (std::size_t i = 0; i < s.diagnoses.size(); ++i)
      std::printf("%s %d %s", i ? "," : "", s.diagnoses[i].second, s.diagnoses[i].first.c_str());
    std::printf("\n");
  }
}

}  // namespace

std::vector<Option> bench_options() {
  return joined(
      pair_set_options(),
      {{{"out", 1, "FILE", "write one JSON line per pair (pagor.register/1 without config)"},
        {"resume", 0, "", "with --out: continue a killed run, skipping pairs already written"},
        threads_option(),
        jobs_option(),
        {"compare-thresholds", 0, "",
         "instead: the pyramid vs each threshold alone vs each alone with the exact maximum "
         "clique (TEASER++-like), success rates"}},
       config_options_for("default, indoor when every target is a floor plan")});
}

namespace {

// The tool and its build, which results are keyed by: the version and a fingerprint of this very
// executable (a rebuild with other code gives other keys).
std::string tool_version() {
  std::string build = "unknown";
  try {
    build = fingerprint(file_fingerprint("/proc/self/exe", "executable", kMaxCloudFileBytes));
  } catch (const InputError&) {  // no /proc: the version alone
  }
  return std::string("pagor ") + PAGOR_VERSION + " (build " + build + ")";
}

// A pair's result key (run_key, runner.hpp: the tool, the configuration and a fingerprint of the
// pair's files); empty for a pair whose files cannot be read (it fails when run).
std::string key_of(const PairEntry& e, const Config& config, const std::string& tool) {
  try {
    return run_key(tool, config, e);
  } catch (const InputError&) {
    return {};
  }
}

// Every pair's key, on `jobs` threads (each key its own thread's).
std::vector<std::string> all_keys(const PairSet& set, const Config& config, const std::string& tool,
                                  int jobs) {
  std::vector<std::string> keys(set.pairs.size());
  const auto n = static_cast<std::size_t>(std::max(1, jobs));
  std::vector<std::thread> threads;
  for (std::size_t w = 0; w < n; ++w)
    threads.emplace_back([&, w] {
      for (std::size_t k = w; k < keys.size(); k += n) keys[k] = key_of(set.pairs[k], config, tool);
    });
  for (std::thread& t : threads) t.join();
  return keys;
}

}  // namespace

int run_bench(const Args& args) {
  const PairSet set = pair_set_from_args(args, "bench");
  const Config config = config_for_targets(args, pair_targets(set)).config;
  if (args.has("compare-thresholds")) return run_threshold_comparison(args, config, set);
  if (args.has("resume") && !args.has("out")) throw UsageError("--resume goes with --out FILE");
  const int jobs = jobs_from_args(args);
  std::optional<BenchJournal> journal;
  // Each pair's result key. A resumed run needs them all first, to know what the journal holds; a
  // fresh one makes each as its pair starts, on the thread that runs it (hooks.prepare), so no
  // file is read twice on the main thread before the first pair starts.
  std::vector<std::string> keys(set.pairs.size());
  bool resuming = false;
  if (args.has("out")) {
    std::vector<NamedPath> inputs = option_inputs(args), pairs = set_inputs(set);
    inputs.insert(inputs.end(), pairs.begin(), pairs.end());
    check_outputs({{"--out", args.get("out")}}, inputs);
    journal.emplace(args.get("out"), args.has("resume"), tool_version());
    resuming = journal->recorded() > 0;
    if (resuming) keys = all_keys(set, config, journal->tool(), jobs);
  }

  std::vector<std::unique_ptr<SetRunner>> runners =
      make_runners(set, jobs, args.get_int("threads", 1));
  std::printf("%-14s %6s %10s %11s %8s %6s %8s %10s  %s\n", "pair", "level", "t err [m]",
              "r err [deg]", "success", "bound", "verdict", "time [ms]", "diagnosis");
  const bool progress = isatty(STDERR_FILENO);  // in a log it would run into the next line
  RunSetHooks hooks;
  hooks.prepare = [&](std::size_t k) {
    if (journal && !resuming) keys[k] = key_of(set.pairs[k], config, journal->tool());
  };
  hooks.reuse = [&](std::size_t k) -> std::optional<PairOutcome> {
    const nlohmann::json* done = resuming && !keys[k].empty() ? journal->find(keys[k]) : nullptr;
    if (!done) return std::nullopt;
    PairOutcome o = outcome_from_json_line(
        done->dump(-1, ' ', false, nlohmann::json::error_handler_t::replace), journal->partial());
    o.timed = false;  // its times are not counted
    return o;
  };
  // As each pair finishes (in any order with --jobs): its line to the journal at once.
  hooks.finished = [&](std::size_t k, const PairOutcome& o) {
    if (journal && o.loaded && o.timed && !keys[k].empty())
      journal->append(bench_result_line(o.report_json, set.pairs[k].name, keys[k], journal->tool()),
                      keys[k]);
  };
  hooks.done = [&](std::size_t, const PairOutcome& o) {  // rows in set order
    if (progress) std::fprintf(stderr, "%70s\r", "");
    for (const std::string& w : o.load_warnings) warn(w);
    print_row(o);
  };
  hooks.progress = [&](const SetProgress& p) {
    if (!progress) return;
    std::fprintf(stderr, "%-70s\r", progress_text(p).c_str());
    std::fflush(stderr);
  };
  std::vector<PairOutcome> outcomes;
  with_config_origin(args, [&] { outcomes = run_set(runners, config, hooks); });
  if (progress) std::fprintf(stderr, "%70s\r", "");
  const BenchmarkSummary s = summarize(outcomes);
  if (s.pairs_run == 0)
    throw InputError(set.origin + ": no pair could be run (first: " + outcomes.front().load_error +
                     ")");
  print_summary(s, config);
  const auto resumed = std::count_if(outcomes.begin(), outcomes.end(),
                                     [](const PairOutcome& o) { return o.loaded && !o.timed; });
  if (resumed > 0)
    std::printf("of which %ld taken from %s (--resume); stage times cover the others\n",
                static_cast<long>(resumed), journal->partial().c_str());
  if (journal) {
    journal->finish(keys);
    std::printf("\nwrote %s\n", args.get("out").c_str());
  }
  return 0;
}

}  // namespace pagor::cli
