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

/// Two candidate poses closer than these are the same pose (levels whose cliques agree).
constexpr double kSamePoseTranslation = 1e-3;  ///< [m]
constexpr double kSamePoseRotationDeg = 1e-3;  ///< [deg]
bool same_pose(const Transform& a, const Transform& b);

/// The D gap between the lowest D and the lowest D of a level with another pose [m]: "D gap to
/// the runner-up pose: ...", naming the levels that found the selected pose again; "n/a" with
/// fewer than two valid levels, or when all found one pose.
std::string level_gap_text(const Snapshot& s);

/// The selected pose's outcome against the ground truth: the refined errors and the candidate's
/// before refinement, each labelled ("selected: SUCCESS (L2), refined 0.31 m / 0.80° (candidate
/// before refinement 0.52 m / 1.10°)"). Needs `s.selected_error`.
std::string selected_text(const Snapshot& s);
/// The refined pose's errors against the ground truth: the selected pose's, unless the verdict
/// adopted an alternative in its place (then the refinement's own). Empty without a ground truth.
std::optional<PoseError> refined_error(const Snapshot& s);
/// The acceptance verdict with the acceptance margin (acceptance.hpp: D below the best distinct
/// candidate's, as a share of mu times the points) and its threshold.
std::string acceptance_text(const Snapshot& s);

/// The diagnosis verdict (its name and reason) in its colour; nothing without a ground truth.
void diagnosis_verdict_line(const Snapshot& s);
/// The run's warnings, each on its own line (the first few; the status bar counts them all).
void warning_lines(const Snapshot& s);

}  // namespace pagor::studio
