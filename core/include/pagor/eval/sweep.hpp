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
#include <utility>
#include <vector>

#include "pagor/config.hpp"
#include "pagor/eval/benchmark.hpp"
#include "pagor/eval/pair_set.hpp"
#include "pagor/eval/runner.hpp"

namespace pagor {

/// One dimension of a grid: a parameter by its key path in the configuration's catalog
/// (config.hpp: `config_fields`, e.g. "verification.mu", "landmarks.classes[0].voxel_size") and
/// the values it takes, each as JSON (`0.5`, `"exact"`, `[0.02, 0.04]`).
struct SweepDimension {
  std::string path;
  std::vector<std::string> values;
};

/// The dimensions of a grid, in any order; each setting takes one value of every dimension. An
/// empty grid gives the base configuration alone.
struct SweepGrid {
  std::vector<SweepDimension> dimensions;
  /// Adds a dimension of numbers (a number, integer or flag parameter).
  SweepGrid& add(const std::string& path, const std::vector<double>& values);
  /// Adds a dimension of JSON values (names of a choice, lists of numbers, ...).
  SweepGrid& add_json(const std::string& path, std::vector<std::string> values);
};

/// One point of the grid.
struct SweepSetting {
  std::string label;  ///< the values of the dimensions that vary, e.g. "mu=0.5 m solver=exact"
  Config config;      ///< the base with `values` set
  /// The value of every dimension in this setting (key path, JSON): what "apply" sets on another
  /// configuration, leaving everything else as it is.
  std::vector<std::pair<std::string, std::string>> values;
};

/// Every combination of the grid on top of `base`, ordered so that consecutive settings
/// invalidate as few stages as possible: the dimensions in the configuration's document order
/// (pipeline order), the first varying slowest (so mu varies faster than the thresholds, which
/// vary faster than the TRIM kind). Throws ConfigError naming the setting when one is invalid,
/// and naming the path when it is no parameter of `base`.
std::vector<SweepSetting> sweep_settings(const Config& base, const SweepGrid& grid);

/// Parses one dimension's values as text for the parameter at `path` of `base`: numbers
/// "0.5,1,2" for a number, integer or flag; names "ratio,difference" for a choice; sets of numbers
/// separated by ';' ("0.02,0.04;0.05") for a list of numbers. Throws InputError naming `what` and
/// the element, or a path that names no parameter (or one that cannot be swept).
SweepDimension parse_sweep_dimension(const Config& base, const std::string& path,
                                     const std::string& values, const std::string& what);
/// Parses "PATH=VALUES" (as parse_sweep_dimension). Throws InputError naming `what`.
SweepDimension parse_sweep_spec(const Config& base, const std::string& spec,
                                const std::string& what);

/// The short name of a swept parameter in labels: "eps" (graph.thresholds), "mu", "trim",
/// "model", "solver", else the path itself.
std::string sweep_dimension_name(const std::string& path);

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
/// The same on runners of its own: `jobs` worker threads each take the next pair and run every
/// setting on it (runner.hpp: run_parallel), each with `threads` for the pipelines' parallel
/// stages. The outcomes equal those of one job, times apart; `progress` is called on the calling
/// thread, for each setting of a pair once the pair is done (pairs in the order they finish), and
/// a setting's `wall_ms` is then the sum of its time on every worker.
SweepResult run_sweep(const PairSet& set, const std::vector<SweepSetting>& settings,
                      int threads = 1, const SweepProgressFn& progress = {},
                      const std::atomic<bool>* cancel = nullptr, int jobs = 1);
/// The same on runners the caller keeps (the studio's, with pipelines cached from earlier passes):
/// one worker thread per runner, each runner used by its thread alone, as above; one runner runs
/// the set as the first overload does. `stage_runs` counts this sweep's runs only. Every runner
/// must be over the same set.
SweepResult run_sweep(std::vector<std::unique_ptr<SetRunner>>& runners,
                      const std::vector<SweepSetting>& settings,
                      const SweepProgressFn& progress = {},
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
