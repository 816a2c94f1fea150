#pragma once
/// \file plot_panel.hpp
/// Plots in the benchmark view: a plot with its PNG and CSV export buttons, and the sweep section
/// (grid fields, progress, the table of settings and its plots).

#include <string>

#include "panels/exports.hpp"
#include "panels/panels.hpp"
#include "runners/bench_worker.hpp"
#include "widgets/plot.hpp"

namespace pagor::studio {

/// Height of the benchmark view's plots [px].
constexpr float kPlotHeight = 260.0f;

/// The plot `width` x `height` pixels, then buttons writing it to `<base>-<id>.png / .svg /
/// .csv`.
void plot_with_exports(const Exports& to, const char* id, const Plot& plot, float width,
                       float height = kPlotHeight);

/// The sweep over the open set (sweep_panel.cpp): one or two parameters by key path and their
/// values, run, progress, whether the result still matches the parameters and the set, the table
/// of settings ("apply" sets only the swept values), the flip view between two settings, plots.
void sweep_section(BenchPanelState& state, BenchWorker& bench, const BenchStatus& status,
                   StudioActions& actions);

}  // namespace pagor::studio
