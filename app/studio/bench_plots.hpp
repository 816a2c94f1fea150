#pragma once
/// \file bench_plots.hpp
/// The plots of many-pair work, built from the core's results: a sweep's success and upper bound
/// per setting, and a benchmark's picking statistics (the paper's "picking times" figure). Shared
/// by the studio's views and `pagor sweep --plot`.

#include <vector>

#include "pagor/benchmark.hpp"
#include "pagor/sweep.hpp"
#include "plot.hpp"

namespace pagor::studio {

/// Bars per setting: success rate and upper bound over the pairs with ground truth [%].
Plot sweep_success_plot(const SweepResult& result);

/// Lines over mu or a single threshold, when the sweep varies only that: success [%] per value.
/// Empty series when the sweep varies anything else.
Plot sweep_line_plot(const SweepResult& result);

/// One pair over mu or a single threshold (as sweep_line_plot): D of the selected pose [m],
/// as points split by success and failure. Empty series when the sweep varies anything else.
Plot sweep_pair_plot(const SweepResult& result, std::size_t pair);

/// Bars per level: how often it was selected and how often its candidate alone would succeed
/// [pairs], over the pairs with ground truth.
Plot picking_plot(const std::vector<PairOutcome>& outcomes);

/// Bars: success rate and upper bound of a benchmark run so far [%].
Plot rates_plot(const BenchmarkSummary& summary);

}  // namespace pagor::studio
