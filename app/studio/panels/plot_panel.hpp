#pragma once
/// \file plot_panel.hpp
/// Plots in the benchmark view: a plot with its PNG and CSV export buttons, and the sweep section
/// (grid fields, progress, the table of settings and its plots).

#include <string>

#include "panels/panels.hpp"
#include "runners/bench_worker.hpp"
#include "widgets/plot.hpp"

namespace pagor::studio {

/// `path` made absolute and normal (relative to the working directory); unchanged when empty or
/// when the working directory cannot be read.
std::string absolute_path(const std::string& path);

/// Height of the benchmark view's plots [px].
constexpr float kPlotHeight = 260.0f;

/// Where a plot's export buttons write: `<base>-<id>.png / .csv`.
struct PlotExports {
  const std::string& base;  ///< the benchmark view's export path
  StudioActions& actions;   ///< renders the PNG; says where the files went
};

/// The plot `width` x `height` pixels, then buttons writing it to `<base>-<id>.png / .csv`.
void plot_with_exports(const PlotExports& to, const char* id, const Plot& plot, float width,
                       float height = kPlotHeight);

/// The sweep over the open set: mu values and threshold sets, run, progress, the table of
/// settings (each can be applied to the session's configuration) and the success plots.
void sweep_section(AppState& state, BenchWorker& bench, const BenchStatus& status,
                   StudioActions& actions);

}  // namespace pagor::studio
