#pragma once
/// \file benchmark_view.hpp
/// The benchmark view: a pairs set (KITTI pairs file or manifest) or a `pagor bench` results
/// file as a sortable, filterable table with rates and picking statistics as plots; parameter
/// changes re-evaluate the set live (bench_worker.hpp); a sweep over mu and thresholds as a table
/// and plots; a row opens that pair in the pair view with the same parameters.

#include <string>

#include "runners/bench_worker.hpp"
#include "state/app_state.hpp"

namespace pagor::studio {

/// Opens what `state.view` names in `bench` with `state.config`. Throws pagor::Error (an
/// unreadable pairs or results file) naming the file.
void open_benchmark(BenchPanelState& state, BenchWorker& bench);

/// The progress bar's text: "3/40 pairs, 1.90 pairs/s, 19 s left (running); 1.58 s with 2 jobs"
/// while a pass runs; after it, the pairs and the rate, "(cancelled)" when it was, and no time
/// left. Rate, time left and wall time are timings: "--" in regression renders.
std::string progress_line(const BenchStatus& status);

}  // namespace pagor::studio
