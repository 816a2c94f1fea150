#pragma once
/// \file runner.hpp
/// The one runner over many pairs. `pagor bench`, sweeps, the threshold comparison and the
/// studio's benchmark view all run their pairs through a SetRunner: it loads a pair, runs it
/// through a pipeline with the configuration given, and keeps pipelines between runs so that a
/// new configuration re-runs only the stages it invalidates. What they do with the outcomes
/// (print rows, write a journal, fill a table) is theirs; the rates come from `summarize`.

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "pagor/config.hpp"
#include "pagor/eval/benchmark.hpp"
#include "pagor/eval/pair_set.hpp"

namespace pagor {

class SetRunner {
 public:
  /// `threads` for each pipeline's parallel stages.
  explicit SetRunner(PairSet set, int threads = 1);
  ~SetRunner();
  SetRunner(const SetRunner&) = delete;
  SetRunner& operator=(const SetRunner&) = delete;

  const PairSet& set() const { return set_; }
  int threads() const { return threads_; }
  std::size_t size() const { return set_.pairs.size(); }

  /// Runs pair `i` with `config`. A kept pipeline re-runs only the stages the configuration
  /// invalidates; otherwise the pair is loaded from its files (with `config.indoor`). A pair that
  /// fails on its own account (unreadable files, data the stages refuse, out of memory) comes
  /// back with `loaded == false` and the reason naming its files, and the set goes on. Throws
  /// Cancelled when `cancel` becomes true, and a ConfigError (a work budget the configuration
  /// exceeds: the same for every pair) as it comes.
  /// Afterwards the pair's pipeline is kept when it fits the cache budget, and the last pair
  /// run is always kept (consecutive runs of one pair reuse it). `lent`, when given, counts the
  /// workers lent to this pair while it runs (Pipeline::lend_threads: a parallel set's idle
  /// workers lend theirs to the pairs still running); the outcome is the same.
  PairOutcome run(std::size_t i, const Config& config, const std::atomic<bool>* cancel = nullptr,
                  const std::atomic<int>* lent = nullptr);

  /// Memory the kept pipelines may hold besides the last one [bytes] (default 0).
  void set_cache_budget(std::size_t bytes);
  /// Whether pair `i`'s pipeline is kept.
  bool cached(std::size_t i) const;
  int cached_count() const;
  /// Estimated memory of the kept pipelines [bytes].
  std::size_t cache_bytes() const;
  /// Drops every kept pipeline.
  void clear_cache();
  /// Runs of each stage over every pair since construction (what a sweep reused).
  const std::array<int, kStageCount>& stage_runs() const { return stage_runs_; }

  /// Estimated memory a pipeline holds: its clouds, verification clouds and kd-tree [bytes].
  static std::size_t estimate_bytes(const Pipeline& pipeline);

 private:
  struct Slot;
  void enforce_budget();

  PairSet set_;
  int threads_;
  std::size_t budget_ = 0;
  std::vector<std::unique_ptr<Slot>> slots_;
  std::optional<std::size_t> last_;
  std::uint64_t clock_ = 0;
  std::array<int, kStageCount> stage_runs_{};
};

/// How far a run over a set has come: what a progress line shows.
struct SetProgress {
  std::size_t done = 0;    ///< pairs with an outcome (run or reused)
  std::size_t total = 0;   ///< pairs in the set
  std::size_t ran = 0;     ///< of `done`, the pairs run now (not reused)
  std::size_t to_run = 0;  ///< pairs this run has to run (total minus the reused)
  double elapsed_s = 0.0;  ///< wall time since the run started [s]
  /// Pairs run per second of wall time; undefined before the first pair has run.
  std::optional<double> rate() const {
    return ran > 0 && elapsed_s > 0 ? std::optional<double>(ran / elapsed_s) : std::nullopt;
  }
  /// Wall time left at that rate [s]; undefined while the rate is.
  std::optional<double> seconds_left() const {
    const auto r = rate();
    return r ? std::optional<double>((to_run - ran) / *r) : std::nullopt;
  }
};

/// "12/40 pairs, 1.9 pairs/s, 15 s left" (the rate and time left "n/a" while undefined).
std::string progress_text(const SetProgress& progress);

/// What a caller of run_set may do around each pair. Every hook but `prepare` is called on the
/// calling thread, one call at a time, also when the pairs run on several worker threads.
struct RunSetHooks {
  /// Just before pair i runs, on the thread that runs it: with jobs > 1 a worker thread, and calls
  /// for different pairs at once. Work per pair that need not hold up the others (the result keys
  /// of `pagor bench --out` fingerprint the pair's files here); what it writes for pair i is
  /// visible to `finished(i)` and `done(i)`. Not called for a reused pair.
  std::function<void(std::size_t i)> prepare;
  /// Before pair i runs: an outcome to use instead (a result taken from an earlier run, with
  /// `timed = false`), or nullopt to run it. With jobs > 1 it is asked for every pair first.
  std::function<std::optional<PairOutcome>(std::size_t i)> reuse;
  /// As soon as pair i has run, in the order the pairs finish (which, with jobs > 1, is not the
  /// set's): where results go that must not be lost when the run is killed (a journal).
  std::function<void(std::size_t i, const PairOutcome& outcome)> finished;
  /// After pair i has an outcome (run or reused), in the order of `order` (the set's by default),
  /// out-of-order finishes held back until those before them are done: where rows are printed.
  std::function<void(std::size_t i, const PairOutcome& outcome)> done;
  /// After each pair's outcome: how far the run has come.
  std::function<void(const SetProgress& progress)> progress;
  /// The order to run the pairs in (empty: set order). Outcomes come back in set order anyway.
  std::vector<std::size_t> order;
  const std::atomic<bool>* cancel = nullptr;  ///< checked between pairs and stages
};

/// Runs every pair of the runner's set with `config`: the outcomes in set order. Throws as
/// SetRunner::run does.
std::vector<PairOutcome> run_set(SetRunner& runner, const Config& config,
                                 const RunSetHooks& hooks = {});

/// The same on `runners.size()` worker threads, pairs in parallel: each worker takes the next pair
/// (in `hooks.order`) and runs it on its own runner, so each runner and its pipelines are used by
/// one thread at a time. The outcomes are those of one runner alone, times apart. The first
/// exception a pair throws (a ConfigError, Cancelled) stops the others after their current pair
/// and is rethrown here. Every runner must be over the same set.
std::vector<PairOutcome> run_set(std::vector<std::unique_ptr<SetRunner>>& runners,
                                 const Config& config, const RunSetHooks& hooks = {});

/// `jobs` runners over `set`, each with `threads` for its pipelines' parallel stages.
std::vector<std::unique_ptr<SetRunner>> make_runners(const PairSet& set, int jobs, int threads = 1);

/// Runs `work(worker, i, lent)` for each i of `order` on `jobs` threads (worker: 0 .. jobs - 1,
/// each thread its own), and `finished(i)` on the calling thread, one at a time, as each returns.
/// `*lent` counts the workers lent to the call while it runs: 0 while every worker has work;
/// once workers find nothing left to take, the idle ones are shared among the calls still
/// running (the last of 3 pairs on 2 workers gets the other worker when it is done). The
/// `stop` given to `work` becomes true when `cancel` does or another call has thrown; the first
/// exception is rethrown here once every thread has ended. What both run parallel set loops on.
void run_parallel(int jobs, const std::vector<std::size_t>& order,
                  const std::function<void(int worker, std::size_t i, const std::atomic<int>* lent,
                                           const std::atomic<bool>* stop)>& work,
                  const std::function<void(std::size_t i)>& finished,
                  const std::atomic<bool>* cancel = nullptr);

/// The worker threads `text` asks for: a whole number >= 1, or "auto" for the machine's cores.
/// Throws InputError naming `what` (e.g. "--jobs") otherwise.
int parse_jobs(const std::string& text, const std::string& what);

/// What a result line of `pagor bench --out` is filed under (its `run_key`): a fingerprint of the
/// tool and its build (`tool`), the whole configuration, and the pair's name and the content of
/// every file it reads (pair_fingerprint). Throws InputError naming a file that cannot be read.
std::string run_key(const std::string& tool, const Config& config, const PairEntry& entry);

/// A result line as `pagor bench --out` writes it (without the newline): the pair's report
/// (PairOutcome::report_json) with "pair", "run_key" and "tool_version" added, keys in order. The
/// CLI and the Python package both write their lines with this.
std::string bench_result_line(const std::string& report_json, const std::string& pair,
                              const std::string& key, const std::string& tool);

}  // namespace pagor
