#pragma once
/// \file history.hpp
/// Undo/redo of parameter changes, and a short history of runs: what each run gave, and what
/// changed from the run before (selected level, D per level, success flips) so the UI can show it.

#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "pagor/config.hpp"
#include "runners/worker.hpp"

namespace pagor::studio {

/// Undo/redo over whole configurations. A slider drag is one step: `commit` is called once the
/// edit ends.
class ParamHistory {
 public:
  static constexpr std::size_t kMaxSteps = 100;

  /// Forgets everything; `current` is the state undo returns to last.
  void reset(const Config& current);
  /// Records `now` as a new step when it differs from the last committed configuration; clears
  /// redo. True when a step was recorded.
  bool commit(const Config& now);
  bool can_undo() const { return !past_.empty(); }
  bool can_redo() const { return !future_.empty(); }
  /// The configuration before the last step (nullopt when there is none).
  std::optional<Config> undo();
  std::optional<Config> redo();
  std::size_t undo_steps() const { return past_.size(); }
  std::size_t redo_steps() const { return future_.size(); }

 private:
  std::deque<std::string> past_, future_;  // configurations as JSON
  std::string current_;
};

/// What changed for one level between two runs on the same data; levels are matched by their ε
/// (inserting a level does not make every later level "change").
struct LevelChange {
  std::optional<double> d_delta;  ///< D after - D before [m] (both valid)
  bool validity_flipped = false;  ///< became valid or invalid
  bool success_flipped = false;   ///< success against ground truth changed
  bool added = false;             ///< no level with this ε before, nor one edited into it
  /// The ε of the level at the same place before, when this level's ε was edited (the runs have
  /// as many levels, and the old ε is gone): compared with it.
  std::optional<double> epsilon_before;
};

/// What changed between two runs.
struct RunChanges {
  bool comparable = false;                        ///< same data, so a comparison means something
  int selected_before = -1, selected_after = -1;  ///< level indices in their own runs
  double selected_eps_before = 0, selected_eps_after = 0;
  /// The TRIM of each run: a difference TRIM's epsilon is a length [m], a ratio's has no unit.
  TrimKind trim_before = TrimKind::ratio, trim_after = TrimKind::ratio;
  std::vector<LevelChange> levels;  ///< one per level of the new run
  /// The selection moved to another ε (or to / from no valid level).
  bool selected_changed() const {
    return comparable && ((selected_before < 0) != (selected_after < 0) ||
                          selected_eps_before != selected_eps_after);
  }
  bool any() const;
};

RunChanges compare_runs(const Snapshot& before, const Snapshot& after);

/// The best and second-best finite D of a run; nullopt without two valid levels.
struct DGap {
  double best = 0, second = 0;
  int best_level = -1, second_level = -1;
};
std::optional<DGap> d_gap(const Snapshot& s);

/// One finished run, as the history lists it.
struct RunRecord {
  std::uint64_t request = 0;
  std::string data;  ///< description of the data
  int levels = 0, selected = -1;
  double best_d = 0;            ///< D of the selected level [m]
  std::optional<bool> success;  ///< against ground truth, when known
  double total_ms = 0;          ///< stages recomputed by this run [ms]
  std::string change;           ///< what changed from the run before, in words
};

RunRecord summarize(const Snapshot& s, const RunChanges& changes);

/// Keeps the last `kMaxRuns` records, newest first.
class RunHistory {
 public:
  static constexpr std::size_t kMaxRuns = 8;
  /// Adds `s` when it is a new run; returns the changes from the previous run. While `dragging`
  /// (a value being dragged re-runs at every step), the runs in between are compared with the run
  /// shown when the drag began, not with one another, and so is the first run after it.
  const RunChanges& observe(const std::shared_ptr<const Snapshot>& s, bool dragging = false);
  const std::deque<RunRecord>& runs() const { return runs_; }
  const RunChanges& changes() const { return changes_; }

 private:
  std::shared_ptr<const Snapshot> last_;
  std::shared_ptr<const Snapshot> before_drag_;  ///< the run shown when a drag began
  std::deque<RunRecord> runs_;
  RunChanges changes_;
};

}  // namespace pagor::studio
