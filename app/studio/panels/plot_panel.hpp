#pragma once
/// \file plot_panel.hpp
/// Plots in the benchmark view: a plot with its PNG and CSV export buttons, and the sweep section
/// (grid fields, progress, the table of settings and its plots).

#include <string>

#include "runners/bench_worker.hpp"
#include "panels/panels.hpp"
#include "widgets/plot.hpp"

namespace pagor::studio {

/// `path` made absolute and normal (relative to the working directory); unchanged when empty or
/// when the working directory cannot be read.
std::string absolute_path(const std::string& path);

/// Height of the benchmark view's plots [px].
constexpr float kPlotHeight = 260.0f;

/// The plot `width` x `height` pixels, then buttons writing it to `<plot_path>-<id>.png / .csv`.
void plot_with_exports(UiContext& ui, const char* id, const Plot& plot, float width,
                       float height = kPlotHeight);

/// The sweep over the open set: mu values and threshold sets, run, progress, the table of
/// settings (each can be applied to the session) and the success plots.
void sweep_section(UiContext& ui, BenchWorker& bench, const BenchStatus& st);

}  // namespace pagor::studio
