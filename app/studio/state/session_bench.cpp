// The benchmark view's part of the session file.

#include "pagor/errors.hpp"
#include "runners/bench_worker.hpp"
#include "state/app_state.hpp"
#include "state/session_json.hpp"

namespace pagor::studio {

using namespace session_json;

json bench_json(const SessionState& s) {
  const BenchViewState& b = s.bench;
  return {{"shown", s.main_view == MainView::benchmark},
          {"open", b.open},
          {"source", b.source == BenchSource::kitti_pairs ? "kitti_pairs"
                     : b.source == BenchSource::results   ? "results"
                                                          : "manifest"},
          {"path", b.path},
          {"kitti_root", b.kitti_root},
          {"sequence", b.sequence},
          {"config_path", b.config_path},
          {"filter", b.filter},
          {"show", static_cast<int>(b.show)},
          {"sort", b.sort},
          {"descending", b.descending},
          {"budget_mib", b.budget_mib},
          {"jobs", b.jobs},
          {"plot_path", b.plot_path},
          {"sweep_path", b.sweep_path},
          {"sweep_values", b.sweep_values},
          {"sweep_path2", b.sweep_path2},
          {"sweep_values2", b.sweep_values2}};
}

void read_bench(const json& j, const std::string& where, AppState& s) {
  if (!j.is_object()) throw InputError(where + ": expected an object");
  reject_unknown(j, where,
                 {"shown", "open", "source", "path", "kitti_root", "sequence", "config_path",
                  "filter", "show", "sort", "descending", "budget_mib", "jobs", "plot_path",
                  "sweep_path", "sweep_values", "sweep_path2", "sweep_values2", "sweep_mu",
                  "sweep_thresholds"});
  BenchViewState& b = s.bench;
  const std::string source = get_string(j, "source", where, "manifest");
  if (source != "manifest" && source != "kitti_pairs" && source != "results")
    throw InputError(where + ": source: expected manifest, kitti_pairs or results, got \"" +
                     source + "\"");
  b.source = source == "kitti_pairs" ? BenchSource::kitti_pairs
             : source == "results"   ? BenchSource::results
                                     : BenchSource::manifest;
  b.path = get_string(j, "path", where, b.path);
  b.kitti_root = get_string(j, "kitti_root", where, b.kitti_root);
  b.sequence = get_string(j, "sequence", where, b.sequence);
  b.config_path = get_string(j, "config_path", where, b.config_path);
  b.open = get_bool(j, "open", where, false) && !b.path.empty();
  b.filter = get_string(j, "filter", where, "");
  b.show = static_cast<RowFilter>(
      get_int(j, "show", where, 0, 0, static_cast<int>(RowFilter::rejected)));
  b.sort = get_int(j, "sort", where, 0, 0, 9);  // a column of the benchmark table
  b.descending = get_bool(j, "descending", where, false);
  b.budget_mib = get_int(j, "budget_mib", where, b.budget_mib, 64, 8192);
  b.jobs = get_int(j, "jobs", where, 1, 1, kMaxBenchJobs);  // sessions before jobs: one
  b.plot_path = get_string(j, "plot_path", where, b.plot_path);
  // Sessions written before sweeps took any parameter named mu values and threshold sets.
  if (const std::string mu = get_string(j, "sweep_mu", where, ""); !mu.empty())
    b.sweep_path = "verification.mu", b.sweep_values = mu;
  if (const std::string t = get_string(j, "sweep_thresholds", where, ""); !t.empty())
    b.sweep_path2 = "graph.thresholds", b.sweep_values2 = t;
  b.sweep_path = get_string(j, "sweep_path", where, b.sweep_path);
  b.sweep_values = get_string(j, "sweep_values", where, b.sweep_values);
  b.sweep_path2 = get_string(j, "sweep_path2", where, b.sweep_path2);
  b.sweep_values2 = get_string(j, "sweep_values2", where, b.sweep_values2);
  s.main_view = get_bool(j, "shown", where, false) && b.open ? MainView::benchmark : MainView::pair;
}

}  // namespace pagor::studio
