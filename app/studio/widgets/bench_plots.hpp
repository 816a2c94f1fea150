#pragma once
/// \file bench_plots.hpp
/// The plots of many-pair work, built from the core's results: a sweep's success and upper bound
/// per setting, and a benchmark's picking statistics (the paper's "picking times" figure). Shared
/// by the studio's views and `pagor sweep --plot`.

#include <optional>
#include <string>
#include <vector>

#include "pagor/eval/benchmark.hpp"
#include "pagor/eval/sweep.hpp"
#include "pagor/indoor/floor_plan.hpp"
#include "widgets/plot.hpp"

namespace pagor::studio {

/// Bars per setting: success rate and upper bound over the pairs with ground truth [%].
Plot sweep_success_plot(const SweepResult& result);

/// Lines over the innermost swept parameter when its values are numbers (or single thresholds):
/// success [%] per value, with the upper bound when it is the only dimension that varies, or one
/// success series per value of a second varying dimension. Empty series otherwise (more than two
/// varying dimensions, or values that are not numbers).
Plot sweep_line_plot(const SweepResult& result);

/// One pair over the swept parameter (1-D sweeps, as sweep_line_plot): D of the selected pose [m],
/// as points split by success and failure. Empty series otherwise.
Plot sweep_pair_plot(const SweepResult& result, std::size_t pair);

/// Bars per level: how often it was selected and how often its candidate alone would succeed
/// [pairs], over the pairs with ground truth. Each level is labelled by its epsilon with its unit
/// (level_label).
Plot picking_plot(const BenchmarkSummary& summary);

/// "level 2: ε = 0.15 m" (difference TRIM), "level 2: ε = 0.15" (ratio, unitless), or
/// "level 2" when the threshold is not known.
std::string level_label(int level, std::optional<double> epsilon, std::optional<TrimKind> trim);

/// The re-localized trajectory of a sequence (the paper's trajectory figure), a map in metres:
/// the ground-truth positions as a thin line, each pair's selected position (the translation of
/// its T_target_source) as a dot coloured by its index in `outcomes` (the scan's time), pairs
/// whose error exceeds the criterion as red crosses, rejected ones grey; over the plan's walls
/// and columns when `plan` is given. Entries without a selected pose are left out; a hovered
/// point names the pair, its errors [m, deg] and the level picked.
Plot trajectory_plot(const std::vector<PairOutcome>& outcomes, const FloorPlan* plan);

/// Bars: success rate and upper bound of a benchmark run so far [%].
Plot rates_plot(const BenchmarkSummary& summary);

/// The set's summary in one line: success, upper bound, verdict precision and recall (each "n/a"
/// when it is a rate of nothing) and the mean time per pair [ms].
std::string summary_text(const BenchmarkSummary& summary);

}  // namespace pagor::studio
