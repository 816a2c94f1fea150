// pagor sweep: a grid of settings (any parameter by key path; named options for the threshold
// sets, mu, TRIM kind, pose model and clique solver) over a pairs set, each pair loaded once and
// its cached stages reused across the settings (sweep.hpp).
// Prints a table like the paper's ablation; writes JSON lines, CSV and a plot (PNG and CSV).

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <sstream>

#include "bench_journal.hpp"
#include "command.hpp"
#include "common/outputs.hpp"
#include "pagor/config.hpp"
#include "pagor/errors.hpp"
#include "pagor/eval/sweep.hpp"
#include "pagor/io/atomic_file.hpp"
#ifdef PAGOR_CLI_PLOT
#include "widgets/bench_plots.hpp"
#include "widgets/plot_export.hpp"
#endif

namespace pagor::cli {
namespace {

// The dimensions the options name, each a key path of the configuration: the named options
// (--thresholds, --mu, --trim, --model, --solver) and any parameter by `--param PATH=v1,v2,...`.
SweepGrid grid_from_args(const Args& args, const Config& base) {
  SweepGrid g;
  const std::pair<const char*, const char*> named[] = {{"thresholds", "graph.thresholds"},
                                                       {"mu", "verification.mu"},
                                                       {"trim", "graph.trim"},
                                                       {"model", "gnc.model"},
                                                       {"solver", "clique.solver"}};
  for (const auto& [option, path] : named)
    if (args.has(option))
      g.dimensions.push_back(
          parse_sweep_dimension(base, path, args.get(option), std::string("--") + option));
  if (args.has("param")) {
    std::stringstream in(args.get("param"));
    std::string spec;
    while (in >> spec) g.dimensions.push_back(parse_sweep_spec(base, spec, "--param"));
  }
  return g;
}

void print_table(const SweepResult& r, const Config& base) {
  std::size_t w = 7;
  for (const auto& s : r.settings) w = std::max(w, s.setting.label.size());
  std::printf("\n%-*s %14s %14s %9s %10s %8s %6s %14s %12s\n", static_cast<int>(w), "setting",
              "success", "upper bound", "accepted", "precision", "recall", "wrong",
              "mean time [ms]", "wall [ms]");
  for (const auto& s : r.settings) {
    const BenchmarkSummary& m = s.summary;
    char succ[48], bound[48];
    std::snprintf(succ, sizeof(succ), "%d/%d %s", m.successes, m.with_truth,
                  rate_text(m.success_rate()).c_str());
    std::snprintf(bound, sizeof(bound), "%d/%d %s", m.upper_bound, m.with_truth,
                  rate_text(m.upper_bound_rate()).c_str());
    std::printf("%-*s %14s %14s %9d %10s %8s %6d %14.1f %12.1f\n", static_cast<int>(w),
                s.setting.label.c_str(), succ, bound, m.accepted, rate_text(m.precision()).c_str(),
                rate_text(m.recall()).c_str(), m.false_accepts, m.mean_total_ms, s.wall_ms);
  }
  std::printf(
      "\nsuccess: %.1f m / %.1f deg; precision: accepted pairs whose pose is right; recall: right "
      "poses that were accepted; wrong: poses accepted although wrong (or negatives); mean time: a "
      "whole run per pair with that setting; "
      "wall: this setting after the previous one's caches\n",
      base.evaluation.max_translation_error, base.evaluation.max_rotation_error);
  std::printf("stage runs over %d pairs x %zu settings:", r.pairs, r.settings.size());
  for (int i = 0; i < kStageCount; ++i)
    std::printf(" %s %d", stage_name(static_cast<Stage>(i)),
                r.stage_runs[static_cast<std::size_t>(i)]);
  std::printf("\n");
}

// An enum's names as a --trim/--model/--solver list takes them: "difference,ratio".
template <class E>
std::string names_of() {
  std::string out;
  for (const auto& e : enum_entries(E{})) out += (out.empty() ? "" : ",") + std::string(e.name);
  return out;
}

}  // namespace

std::vector<Option> sweep_options() {
  return joined(
      pair_set_options(),
      {{{"thresholds", 1, "SETS", "threshold sets, e.g. '0.02,0.04,0.08;0.03,0.06'"},
        {"mu", 1, "LIST", "verification truncations [m], e.g. '0.5,1,2'"},
        {"trim", 1, "LIST", "TRIM kinds: " + names_of<TrimKind>()},
        {"model", 1, "LIST", "pose models: " + names_of<PoseModel>()},
        {"solver", 1, "LIST", "clique solvers: " + names_of<CliqueSolver>()},
        {"param", 1, "PATH=LIST",
         "any parameter by key path, e.g. 'gnc.noise_bound=0.5,1,2'; several separated by "
         "spaces (pagor config --describe lists the paths)"},
        {"out", 1, "FILE", "write one JSON line per setting (pagor.sweep/1)"},
        {"csv", 1, "FILE", "write the table as CSV"},
        {"plot", 1, "PNG", "draw success and upper bound per setting as a PNG"},
        {"plot-csv", 1, "FILE", "write the plotted numbers as CSV"},
        threads_option(),
        jobs_option()},
       config_options_for()});
}

int run_sweep_command(const Args& args) {
  const Config base = config_from_args(args).config;
  const PairSet set = pair_set_from_args(args, "sweep");
  std::vector<NamedPath> outputs, inputs = option_inputs(args), pairs = set_inputs(set);
  inputs.insert(inputs.end(), pairs.begin(), pairs.end());
  for (const char* key : {"out", "csv", "plot", "plot-csv"})
    if (args.has(key)) outputs.push_back({std::string("--") + key, args.get(key)});
  check_outputs(outputs, inputs);
  std::vector<SweepSetting> settings;
  with_config_origin(args, [&] { settings = sweep_settings(base, grid_from_args(args, base)); });
#ifndef PAGOR_CLI_PLOT
  if (args.has("plot") || args.has("plot-csv"))
    throw UsageError("--plot needs the studio's renderer: build with PAGOR_BUILD_STUDIO=ON");
#endif
  std::printf("%zu settings x %zu pairs\n", settings.size(), set.pairs.size());
  const int jobs = jobs_from_args(args);
  const bool tty = isatty(STDERR_FILENO);  // in a log it would run into the next line
  const auto t0 = std::chrono::steady_clock::now();
  SetProgress progress{0, set.pairs.size(), 0, set.pairs.size(), 0.0};
  SweepResult result;
  with_config_origin(args, [&] {
    result = run_sweep(
        set, settings, args.get_int("threads", 1),
        [&](int, int k, const PairOutcome&) {
          if (static_cast<std::size_t>(k) + 1 < settings.size()) return;  // the pair is done
          ++progress.done;
          ++progress.ran;
          progress.elapsed_s =
              std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
          if (tty) std::fprintf(stderr, "%-70s\r", progress_text(progress).c_str());
        },
        nullptr, jobs);
  });
  if (tty) std::fprintf(stderr, "%70s\r", "");
  for (const auto& o : result.settings.front().outcomes)
    if (!o.loaded) warn("pair " + o.name + " failed: " + o.load_error);
  print_table(result, base);
  if (args.has("out")) write_file_atomic(args.get("out"), sweep_json_lines(result));
  if (args.has("csv")) write_file_atomic(args.get("csv"), sweep_csv(result));
#ifdef PAGOR_CLI_PLOT
  const studio::Plot plot = studio::sweep_success_plot(result);
  if (args.has("plot")) studio::export_plot_png(plot, args.get("plot"));
  if (args.has("plot-csv")) write_file_atomic(args.get("plot-csv"), studio::plot_csv(plot));
#endif
  for (const char* key : {"out", "csv", "plot", "plot-csv"})
    if (args.has(key)) std::printf("wrote %s\n", args.get(key).c_str());
  return 0;
}

}  // namespace pagor::cli
