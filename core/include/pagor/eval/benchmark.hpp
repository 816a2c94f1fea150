#pragma once
/// \file benchmark.hpp
/// What a pair gave, and the rates over a set of pairs: each rate defined once here (undefined,
/// shown "n/a", when it is a ratio of nothing). Pairs are run by the runner (runner.hpp); the CLI
/// and the studio only present what these say.

#include <array>
#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "pagor/eval/pair_set.hpp"
#include "pagor/pipeline.hpp"
#include "pagor/registration.hpp"

namespace pagor {

/// What one pair gave.
struct PairOutcome {
  std::string name;        ///< the pair's name in its set
  bool negative = false;   ///< a known non-overlapping pair
  bool loaded = false;     ///< false: the pair failed, its files or data unusable (`load_error`)
  std::string load_error;  ///< why it failed, naming the file
  /// What loading its clouds had to say (points dropped, ...), each naming the file.
  std::vector<std::string> load_warnings;
  bool has_ground_truth = false;
  int selected_level = -1;         ///< -1: no valid candidate
  std::optional<PoseError> error;  ///< errors of the selected pose (ground truth known)
  bool success = false;            ///< selected pose within the criterion
  bool upper_bound = false;        ///< any level's candidate within the criterion
  bool accepted = false;           ///< the acceptance verdict on the selected pose
  std::string diagnosis;  ///< verdict_name() of the diagnosis (diagnosis.hpp); empty without truth
  bool timed = true;      ///< false: taken from an earlier run; its times are not counted
  std::array<double, kStageCount> stage_ms{};  ///< wall time per stage [ms]
  std::array<bool, kStageCount> ran{};         ///< the stages this run ran (the others were kept)
  double total_ms = 0.0;                       ///< sum of the stage times [ms]
  std::string report_json;  ///< the pagor.register/1 result without its config, one line
  std::string source_name, target_name;  ///< the clouds' files or descriptions
  std::vector<bool> level_success;       ///< per level: its candidate alone within the criterion
  double margin = 0.0;  ///< D margin of the selection, fraction of mu * points (acceptance.hpp)
  double score = 0.0;   ///< D of the selected candidate [m]; NaN when none was selected
  std::optional<Transform> T_target_source;     ///< the selected pose (refined when applied)
  std::optional<Transform> T_target_source_gt;  ///< the ground truth, when known
  std::vector<double> level_epsilons;  ///< each level's TRIM threshold ([m] or a ratio, `trim`)
  std::optional<TrimKind> trim;        ///< the TRIM the thresholds are of (unknown: read from a
                                       ///< results file written before the line named it)

  /// Whether the verdict trusted a pose it must not have: a negative accepted, or an accepted
  /// pose its ground truth calls wrong (Registration::accepted_wrong, with negatives). What the
  /// bench rows mark and the summaries count as false accepts.
  bool accepted_wrong() const { return accepted && (negative || (has_ground_truth && !success)); }
};

/// Loads a pair and runs it through `pipeline` with the pipeline's configuration (and the pair's
/// own label scheme, if its description sets one), and diagnoses it when it has ground truth (the
/// report's `diagnosis`, null without). A pair that fails on its own account comes back with
/// `loaded == false` and the reason naming the file: its files cannot be read (InputError while
/// loading), the stages refuse its data (InputError while running), or it does not fit in memory.
/// A ConfigError (the configuration's fault, which would hit every pair) throws, and so does
/// Cancelled when `cancel` becomes true.
PairOutcome run_pair(Pipeline& pipeline, const PairEntry& entry,
                     const std::atomic<bool>* cancel = nullptr);

/// The outcome of a pipeline that has run on `entry`'s clouds (`source_name`, `target_name` as
/// run_pair reported them). After run_pair, a new configuration, `Pipeline::run` (which re-runs
/// only the invalidated stages) and this give what a fresh run_pair would. Stage times are each
/// stage's last run, so `total_ms` is the cost of a whole run with this configuration.
PairOutcome pair_outcome(const Pipeline& pipeline, const PairEntry& entry,
                         const std::string& source_name, const std::string& target_name);

/// The outcome of a registration of `entry`: the row `pagor bench` prints and writes.
PairOutcome pair_outcome(const Registration& registration, const PairEntry& entry);

/// A rate as shown: "93.3 %", or "n/a" when undefined (a ratio of nothing).
std::string rate_text(std::optional<double> rate);

/// n / of, undefined when `of` is 0.
inline std::optional<double> ratio(int n, int of) {
  return of > 0 ? std::optional<double>(static_cast<double>(n) / of) : std::nullopt;
}

/// What the pairs with ground truth did at one pyramid level.
struct LevelPicks {
  std::optional<double> epsilon;   ///< the level's threshold (from the first outcome that has it)
  int selected = 0;                ///< pairs whose selected candidate came from this level
  int selected_and_succeeded = 0;  ///< of those, the ones whose pose was right
  int alone_succeeds = 0;          ///< pairs whose candidate at this level alone was right
};

/// Rates and times over a set of outcomes.
struct BenchmarkSummary {
  int pairs_run = 0;          ///< pairs that ran
  int skipped = 0;            ///< pairs that failed (files unreadable, data the stages refused)
  int with_truth = 0;         ///< loaded positives with ground truth
  int successes = 0;          ///< of `with_truth`: selected pose within the criterion
  int upper_bound = 0;        ///< of `with_truth`: any level within the criterion
  int negatives = 0;          ///< loaded known negatives
  int true_accepts = 0;       ///< positives accepted and successful
  int false_accepts = 0;      ///< negatives accepted, or positives accepted with a wrong pose
  int accepted = 0;           ///< accepted pairs that can be judged (negatives, or with truth)
  int accepted_unjudged = 0;  ///< accepted pairs that cannot be judged (no truth, not negative)
  /// Every accepted pair: as many as the rows that say "accept".
  int accepted_total() const { return accepted + accepted_unjudged; }
  /// Success rate: successes / pairs with ground truth.
  std::optional<double> success_rate() const { return ratio(successes, with_truth); }
  /// Upper bound: pairs where any level succeeds / pairs with ground truth.
  std::optional<double> upper_bound_rate() const { return ratio(upper_bound, with_truth); }
  /// Verdict precision: true accepts / accepted pairs that can be judged.
  std::optional<double> precision() const { return ratio(true_accepts, accepted); }
  /// Verdict recall: true accepts / positives whose selected pose succeeded.
  std::optional<double> recall() const { return ratio(true_accepts, successes); }
  std::vector<LevelPicks> levels;  ///< per pyramid level, over the pairs with ground truth
  std::optional<TrimKind> trim;    ///< the TRIM of the levels' thresholds, when known
  std::vector<std::pair<std::string, int>> diagnoses;  ///< pairs per diagnosis verdict, in order
  std::array<double, kStageCount> mean_ms{}, median_ms{};  ///< per stage, timed pairs [ms]
  double mean_total_ms = 0.0, median_total_ms = 0.0;       ///< per pair [ms]
};

/// Summarises outcomes.
BenchmarkSummary summarize(const std::vector<PairOutcome>& outcomes);

}  // namespace pagor

namespace pagor {

/// Reads the results a `pagor bench --out FILE` run wrote (one pagor.register/1 line per pair):
/// names, verdicts, errors, levels and stage times, marked untimed when no timings are present.
/// Throws InputError naming the file and line of a line that is not such a result.
std::vector<PairOutcome> read_bench_results(const std::string& path);

/// One results line (pagor.register/1 with `pair`, as `pagor bench --out` writes) as an outcome,
/// with its diagnosis verdict; untimed when it has no timings. Members of an unexpected type
/// count as absent. Throws InputError naming `where` when it is not such a line.
PairOutcome outcome_from_json_line(const std::string& line, const std::string& where);

}  // namespace pagor
