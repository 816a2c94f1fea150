#pragma once
/// \file sweep.hpp
/// A grid of settings over a set of pairs (the paper's ablations): every pair is loaded once and
/// kept in one cached Pipeline while the settings change, so a new mu re-scores, a new threshold
/// set rebuilds the graphs, and the landmarks and correspondences are computed once per pair
/// (unless a setting changes them). Each setting's numbers equal a separate benchmark run.

#include <array>
#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "pagor/config.hpp"
#include "pagor/sets/benchmark.hpp"
#include "pagor/sets/pair_set.hpp"
#include "pagor/sets/runner.hpp"

namespace pagor {

/// The values each dimension takes; an empty dimension keeps the base configuration's value.
struct SweepGrid {
  std::vector<std::vector<double>> threshold_sets;  ///< graph.thresholds [TRIM unit]
  std::vector<double> mus;                          ///< verification.mu [m]
  std::vector<TrimKind> trims;                      ///< graph.trim
  std::vector<PoseModel> models;                    ///< gnc.model
  std::vector<CliqueSolver> solvers;                ///< clique.solver
};

/// One point of the grid.
struct SweepSetting {
  std::string label;  ///< the values of the dimensions that vary, e.g. "mu=0.5 solver=exact"
  Config config;
};

/// Every combination of the grid on top of `base`, ordered so that consecutive settings
/// invalidate as few stages as possible (mu varies fastest, the TRIM kind slowest). An empty grid
/// gives one setting, `base`. Throws ConfigError naming the setting when one is invalid.
std::vector<SweepSetting> sweep_settings(const Config& base, const SweepGrid& grid);

/// One setting's outcomes over the set.
struct SweepSettingResult {
  SweepSetting setting;
  std::vector<PairOutcome> outcomes;  ///< in set order
  BenchmarkSummary summary;
  double wall_ms = 0.0;  ///< time spent on this setting with the caches of the previous [ms]
};

struct SweepResult {
  std::vector<SweepSettingResult> settings;   ///< in sweep_settings order
  std::array<int, kStageCount> stage_runs{};  ///< stage runs over all pairs and settings
  int pairs = 0;                              ///< pairs in the set
};

/// Called after each (pair, setting): indices and that run's outcome.
using SweepProgressFn = std::function<void(int pair, int setting, const PairOutcome& outcome)>;

/// Runs every setting on every pair of the runner's set, pair by pair (so each pair's pipeline
/// carries its caches across the settings). A pair that cannot be loaded is skipped in every
/// setting (as `pagor bench` does). Throws Cancelled when `cancel` becomes true, ConfigError when
/// a setting exceeds a work budget.
SweepResult run_sweep(SetRunner& runner, const std::vector<SweepSetting>& settings,
                      const SweepProgressFn& progress = {},
                      const std::atomic<bool>* cancel = nullptr);
/// The same on a runner of its own.
SweepResult run_sweep(const PairSet& set, const std::vector<SweepSetting>& settings,
                      int threads = 1, const SweepProgressFn& progress = {},
                      const std::atomic<bool>* cancel = nullptr);

/// Parses a list like "0.5,1,2" (comma-separated numbers); `what` names it in errors. Threshold
/// sets are separated by ';' ("0.02,0.04;0.02,0.04,0.08"). Throws InputError.
std::vector<double> parse_number_list(const std::string& text, const std::string& what);
std::vector<std::vector<double>> parse_threshold_sets(const std::string& text,
                                                      const std::string& what);

/// Per setting: label, pairs, successes, upper bound, rates, verdict precision/recall, mean time.
/// CSV with a header line; JSON lines with schema "pagor.sweep/1", one line per setting.
std::string sweep_csv(const SweepResult& result);
std::string sweep_json_lines(const SweepResult& result);

}  // namespace pagor
