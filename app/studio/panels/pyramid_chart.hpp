#pragma once
/// \file pyramid_chart.hpp
/// Beside the pyramid's table: the bar chart of D per level, the D gap between the best and the
/// runner-up level, the acceptance verdict with its margin (two different quantities, named so
/// that they cannot be confused), what refinement did, the diagnosis verdict and the run's
/// warnings.

#include "runners/worker.hpp"
#include "state/history.hpp"

namespace pagor::studio {

/// The bar chart of D per level (from zero; green / red by success with a ground truth), the gap
/// to the runner-up level, the acceptance verdict and refinement.
void bar_chart(const Snapshot& s, int shown, const RunChanges& changes);

/// The D gap between the lowest and the second-lowest D of the levels [m]: "D gap to the
/// runner-up level: ..."; "n/a" with fewer than two valid levels.
std::string level_gap_text(const Snapshot& s);
/// The acceptance verdict with the acceptance margin (acceptance.hpp: D below the best distinct
/// candidate's, as a share of mu times the points) and its threshold.
std::string acceptance_text(const Snapshot& s);

/// The diagnosis verdict (its name and reason) in its colour; nothing without a ground truth.
void diagnosis_verdict_line(const Snapshot& s);
/// The run's warnings, each on its own line (the first few; the status bar counts them all).
void warning_lines(const Snapshot& s);

}  // namespace pagor::studio
