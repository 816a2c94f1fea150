#pragma once
/// \file benchmark_view.hpp
/// The benchmark view: a pairs set (KITTI pairs file or manifest) or a `pagor bench` results
/// file as a sortable, filterable table with rates and picking statistics as plots; parameter
/// changes re-evaluate the set live (bench_worker.hpp); a sweep over mu and thresholds as a table
/// and plots; a row opens that pair in the pair view with the same parameters.

#include "runners/bench_worker.hpp"
#include "state/app_state.hpp"

namespace pagor::studio {

/// Opens what `state.bench` names in `bench` with `state.config`. Throws pagor::Error (an
/// unreadable pairs or results file) naming the file.
void open_benchmark(AppState& state, BenchWorker& bench);

}  // namespace pagor::studio
