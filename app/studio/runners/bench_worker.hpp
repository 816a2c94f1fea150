#pragma once
/// \file bench_worker.hpp
/// The benchmark view's runner: every pair of a set through the core's SetRunner on a background
/// thread, which keeps a pipeline per pair within a memory budget. A new configuration
/// re-evaluates the whole set: each kept pair re-runs only the stages the change invalidated
/// (kept pairs first, so the rates update fast), the others run from their files. With jobs > 1
/// the pairs (and a sweep's pairs) run on that many runners at once, each on a thread of its own.

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "pagor/eval/benchmark.hpp"
#include "pagor/eval/runner.hpp"
#include "pagor/eval/sweep.hpp"
#include "pagor/indoor/floor_plan.hpp"

namespace pagor::studio {

/// Most pairs the benchmark view evaluates at once (its "jobs"): each job holds a pipeline and
/// its clouds, so far more jobs than cores would only add memory.
inline constexpr int kMaxBenchJobs = 64;

/// One row of the table.
struct BenchRow {
  PairOutcome outcome;   ///< the latest outcome (of an earlier configuration until `current`)
  bool done = false;     ///< has an outcome at all
  bool current = false;  ///< the outcome is of the configuration being evaluated
  bool cached = false;   ///< its pipeline is kept in memory
  double last_ms = 0;    ///< wall time of its last evaluation (only invalidated stages) [ms]
};

/// A finished sweep and what it ran on, so that the view can tell when it no longer matches the
/// parameters or the set shown.
struct SweepRecord {
  SweepResult result;
  Config base;            ///< the configuration the swept values were set on
  std::uint64_t set = 0;  ///< the set it ran over (BenchStatus::set_generation)
};

/// Why `record` no longer describes the open set with `config` (empty when it does): another set
/// was opened, or a parameter other than the swept ones changed (the swept ones may differ: that
/// is what "apply" does).
std::string sweep_stale_reason(const SweepRecord& record, const Config& config,
                               std::uint64_t set_generation);

/// The pairs whose outcome differs between two settings of a sweep: success, the acceptance
/// verdict or the diagnosis verdict. Indices into the set, in set order.
std::vector<std::size_t> flipped_pairs(const SweepResult& result, std::size_t a, std::size_t b);

/// The pair a row of `pagor bench --out` results ran on (read from `results_file`), to open it
/// again: a KITTI pair when both clouds are scans of one sequence (sequences/SS/velodyne/N.bin,
/// with the sequence's ground truth), else the two files (paths as written, or beside the results
/// file) with the ground truth the row recorded. nullopt when the files are not there.
std::optional<PairEntry> result_pair(const PairOutcome& outcome, const std::string& results_file);

struct BenchStatus {
  bool busy = false;
  int total = 0, done = 0;              ///< pairs in the set; with an outcome of the current config
  int cached = 0;                       ///< pairs whose pipeline is kept
  std::size_t cache_bytes = 0;          ///< estimated memory of the kept pipelines [bytes]
  std::size_t budget_bytes = 0;         ///< the budget [bytes]
  double pass_ms = 0;                   ///< wall time of the last pass (or of this one so far) [ms]
  int jobs = 1;                         ///< runners the pass in progress (or the last) runs on
  std::uint64_t generation = 0;         ///< increases with every open or configuration
  std::uint64_t set_generation = 0;     ///< increases with every set or results file opened
  std::uint64_t finished = 0;           ///< generation of the last complete pass
  std::string error;                    ///< why the last pass stopped (empty when fine)
  bool sweeping = false;                ///< a sweep is queued or running
  int sweep_done = 0, sweep_total = 0;  ///< (pair, setting) runs of the sweep
  std::string sweep_error;              ///< why the last sweep stopped
  bool cancelled = false;  ///< the last pass was stopped by cancel() before its end (a sweep's
                           ///< cancel is in sweep_error)

  /// How far the pass has come, for progress_text: every pair of a pass runs (none is reused).
  SetProgress pass_progress() const {
    const auto d = static_cast<std::size_t>(done), t = static_cast<std::size_t>(total);
    return {d, t, d, t, pass_ms / 1000.0};
  }
};

class BenchWorker {
 public:
  BenchWorker();
  ~BenchWorker();
  BenchWorker(const BenchWorker&) = delete;
  BenchWorker& operator=(const BenchWorker&) = delete;

  /// Opens a set and evaluates it with `config` (drops every cache).
  void open(PairSet set, const Config& config);
  /// Shows results read from a file; nothing runs (no pairs to re-evaluate).
  void show_results(std::vector<PairOutcome> outcomes, const std::string& origin);
  /// Re-evaluates the open set with a new configuration (nothing when no set is open).
  void set_config(const Config& config);
  /// Memory budget of the per-pair caches [bytes]; pipelines beyond it are dropped after use.
  /// With several jobs each runner keeps at most its share (bytes / jobs).
  void set_budget(std::size_t bytes);
  /// Pairs evaluated at once, each job on a runner of its own (clamped to 1 .. kMaxBenchJobs of
  /// app_state.hpp). Takes effect at the next pass or sweep; a new number drops the caches then.
  /// The outcomes do not depend on it, only the times do.
  void set_jobs(int jobs);
  /// Queues a sweep over the open set, after the current pass; the cached pipelines are reused
  /// (a parameter change cancels it). `base`: the configuration the settings' values were set on.
  void sweep(std::vector<SweepSetting> settings, const Config& base);
  /// The last finished sweep (null before the first).
  std::shared_ptr<const SweepRecord> sweep_result() const;
  /// Drops every pair (the view is closed).
  void close();
  /// Stops the pass in progress and the sweep queued or running, between pairs (a stage in
  /// progress ends first). Rows evaluated keep their outcomes; the status says `cancelled`, and
  /// how far the pass got, until the next pass or sweep.
  void cancel();
  /// Evaluates the open set again with the current parameters (after a cancel: the pairs kept in
  /// the caches re-run only what they miss). Nothing when the set cannot re-run.
  void rerun();

  std::vector<BenchRow> rows() const;
  BenchStatus status() const;
  /// The set open (empty when none or when showing results from a file).
  PairSet set() const;
  /// The pairs set or results file shown.
  std::string origin() const;
  /// The floor plan of an indoor set (the target of its first pair against a plan), read by the
  /// worker thread; null for other sets or until read (a plan that cannot be read: null, and
  /// the status's error says why).
  std::shared_ptr<const FloorPlan> plan() const;
  bool can_rerun() const;
  /// Blocks until the current pass is complete or `timeout_s` passes; true when complete.
  bool wait_idle(double timeout_s) const;

 private:
  void loop();
  void run_pending_sweep();
  /// Marks every row stale and starts a new pass (a changed configuration, a re-run; mutex held).
  void start_pass_locked();
  /// Reads the plan `pending_plan_` names, if any (worker thread).
  void load_pending_plan();
  /// Takes a new set, and builds the runners anew when there is one or the jobs changed
  /// (with the mutex held, no pass or sweep running).
  void prepare_runners();
  /// Evaluates one pair on runner `job`; false when cancelled or the generation moved on.
  bool evaluate(int job, std::size_t pair, const Config& config, std::uint64_t generation);
  /// Evaluates the pairs of `order` with one runner, or every pair with several at once (each
  /// runner's kept pairs on it); false when cancelled or the generation moved on.
  bool evaluate_all(const std::vector<std::size_t>& order, const Config& config,
                    std::uint64_t generation);
  /// Which pairs runner `job` keeps, read on the thread using it; then the rows and the status.
  void note_cache(int job);

  mutable std::mutex mutex_;
  mutable std::condition_variable changed_;
  PairSet set_;                         // the thread's set
  std::optional<PairSet> pending_set_;  // a new set, taken by the thread at its next pass
  std::string origin_;
  std::optional<std::string> pending_plan_;  // a plan to read (empty path: none)
  std::shared_ptr<const FloorPlan> plan_;
  std::uint64_t plan_generation_ = 0;  // counts opened sets and results files
  bool rerunnable_ = false;
  Config config_;
  std::vector<BenchRow> rows_;
  std::vector<std::unique_ptr<SetRunner>> runners_;  // the thread's, replaced under the mutex
  int jobs_ = 1;                                     // asked for by set_jobs
  struct CacheView {
    std::vector<char> cached;  // per pair: the runner keeps its pipeline
    std::size_t bytes = 0;     // [bytes]
  };
  std::vector<CacheView> cache_views_;                // per runner, as last read by its thread
  std::uint64_t runners_set_ = 0;                     // the set generation the runners run
  std::chrono::steady_clock::time_point pass_start_;  // of the pass in progress
  std::optional<std::vector<SweepSetting>> pending_sweep_;
  Config sweep_base_;
  std::shared_ptr<const SweepRecord> sweep_result_;
  BenchStatus status_;
  std::atomic<bool> cancel_{false};
  std::uint64_t cancelled_generation_ = 0;  // the pass cancel() stopped (or will, not yet begun)
  bool sweep_cancelled_ = false;            // cancel() stopped the running sweep
  bool stop_ = false;
  std::thread thread_;
};

}  // namespace pagor::studio
