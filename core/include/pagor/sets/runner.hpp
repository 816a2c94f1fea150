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
#include <vector>

#include "pagor/config.hpp"
#include "pagor/sets/benchmark.hpp"
#include "pagor/sets/pair_set.hpp"

namespace pagor {

class SetRunner {
 public:
  /// `threads` for each pipeline's parallel stages.
  explicit SetRunner(PairSet set, int threads = 1);
  ~SetRunner();
  SetRunner(const SetRunner&) = delete;
  SetRunner& operator=(const SetRunner&) = delete;

  const PairSet& set() const { return set_; }
  std::size_t size() const { return set_.pairs.size(); }

  /// Runs pair `i` with `config`. A kept pipeline re-runs only the stages the configuration
  /// invalidates; otherwise the pair is loaded from its files (with `config.indoor`). A pair that
  /// fails on its own account (unreadable files, data the stages refuse, out of memory) comes
  /// back with `loaded == false` and the reason naming its files, and the set goes on. Throws
  /// Cancelled when `cancel` becomes true, and a ConfigError (a work budget the configuration
  /// exceeds: the same for every pair) as it comes.
  /// Afterwards the pair's pipeline is kept when it fits the cache budget, and the last pair
  /// run is always kept (consecutive runs of one pair reuse it).
  PairOutcome run(std::size_t i, const Config& config, const std::atomic<bool>* cancel = nullptr);

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

/// What a caller of run_set may do around each pair.
struct RunSetHooks {
  /// Before pair i runs: an outcome to use instead (a result taken from an earlier run, with
  /// `timed = false`), or nullopt to run it.
  std::function<std::optional<PairOutcome>(std::size_t i)> reuse;
  /// After pair i has an outcome (run or reused).
  std::function<void(std::size_t i, const PairOutcome& outcome)> done;
  /// The order to run the pairs in (empty: set order). Outcomes come back in set order anyway.
  std::vector<std::size_t> order;
  const std::atomic<bool>* cancel = nullptr;  ///< checked between pairs and stages
};

/// Runs every pair of the runner's set with `config`: the outcomes in set order. Throws as
/// SetRunner::run does.
std::vector<PairOutcome> run_set(SetRunner& runner, const Config& config,
                                 const RunSetHooks& hooks = {});

}  // namespace pagor
