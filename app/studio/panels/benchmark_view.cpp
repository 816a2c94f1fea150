#include "panels/benchmark_view.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "pagor/errors.hpp"
#include "pagor/io/atomic_file.hpp"
#include "panels/panels.hpp"
#include "panels/plot_panel.hpp"
#include "widgets/bench_plots.hpp"
#include "widgets/plot.hpp"
#include "widgets/timings.hpp"
#include "widgets/widgets.hpp"

namespace pagor::studio {
namespace {

// "margin": the acceptance margin (acceptance.hpp), D below the best distinct candidate's as a
// share of mu times the points.
const char* const kColumns[] = {"pair",  "verdict",         "success",   "t err [m]", "r err [deg]",
                                "level", "margin [%]", "time [ms]", "cached",    "diagnosis"};
constexpr int kColumnCount = 10;
constexpr int kDiagnosisColumn = 9;  // sorted by name, like the pair
// The choices of the "show" combo, in RowFilter's order.
const std::pair<RowFilter, const char*> kShow[] = {{RowFilter::all, "all pairs"},
                                                   {RowFilter::failures, "failures"},
                                                   {RowFilter::successes, "successes"},
                                                   {RowFilter::accepted, "accepted"},
                                                   {RowFilter::rejected, "rejected"}};
constexpr float kTrajectoryHeight = 420.0f;  // [px]

const char* truth_text(const PairOutcome& o) {
  if (!o.loaded) return "failed";
  if (o.negative) return "negative";
  if (!o.has_ground_truth) return "-";
  return o.success ? "yes" : "no";
}

// Sort key of a column (numbers; strings compare by name).
double key(const BenchRow& r, int column) {
  const PairOutcome& o = r.outcome;
  const double none = -1e300;
  switch (column) {
    case 1:
      return o.accepted;
    case 2:
      return o.negative ? 2 : (o.success ? 1 : 0);
    case 3:
      return o.error ? o.error->translation : none;
    case 4:
      return o.error ? o.error->rotation_deg : none;
    case 5:
      return o.selected_level;
    case 6:
      return o.margin;
    case 7:
      return r.last_ms;
    case 8:
      return r.cached;
    default:
      return 0;
  }
}

bool shown(const BenchRow& r, const BenchViewState& v) {
  const PairOutcome& o = r.outcome;
  if (!v.filter.empty() && o.name.find(v.filter) == std::string::npos) return false;
  switch (v.show) {
    case RowFilter::failures:
      return r.done && (!o.loaded || (!o.negative && !o.success) || (o.negative && o.accepted));
    case RowFilter::successes:
      return r.done && o.success;
    case RowFilter::accepted:
      return r.done && o.accepted;
    case RowFilter::rejected:
      return r.done && !o.accepted;
    case RowFilter::all:
      break;
  }
  return true;
}

void source_controls(BenchPanelState& state, BenchWorker& bench, StudioActions& actions) {
  BenchViewState& v = state.view;
  ui::radio("manifest", &v.source, BenchSource::manifest,
            "a generic manifest: SOURCE TARGET [gt=...] per line (pagor bench --manifest)");
  ImGui::SameLine();
  ui::radio("KITTI pairs file", &v.source, BenchSource::kitti_pairs,
            "frame numbers 'source target' per line, with a KITTI root");
  ImGui::SameLine();
  ui::radio("bench results", &v.source, BenchSource::results,
            "the JSON lines of pagor bench --out (shown as they are; nothing re-runs)");
  ImGui::PushItemWidth(-std::min(220.0f, ImGui::GetContentRegionAvail().x * 0.3f));
  ui::input_path("file##bench_path", &v.path, "path of the manifest, pairs file or results file");
  ImGui::SameLine();
  if (ui::button("...##bench_path", ImVec2(0, 0), "choose the file in a browser"))
    actions.browse(FilePurpose::bench, v.path);
  ImGui::PopItemWidth();
  if (v.source == BenchSource::kitti_pairs) {
    ui::input_text("KITTI root##bench", &v.kitti_root, "directory holding sequences/");
    ui::input_text("sequence##bench", &v.sequence, "KITTI sequence, e.g. 00");
  }
  ui::input_text("parameters file##bench", &v.config_path,
                 "a configuration JSON for this set, e.g. bench/manifests/semreg-dev.json");
  ImGui::SameLine();
  if (ui::button("load##bench_config", ImVec2(0, 0),
                 "use the file's parameters in the session (absent keys: the preset's)"))
    actions.open_file(resolve_path(state.base_dir, v.config_path), FilePurpose::config);
  if (ui::button("open and run##bench", ImVec2(0, 0),
                 v.source == BenchSource::results
                     ? "read the results file and show its rows as recorded (nothing re-runs)"
                     : "read the file and run every pair with the current parameters")) {
    try {
      open_benchmark(state, bench);
      actions.notify(Message::info("opened " + v.path));
    } catch (const Error& e) {
      actions.notify(Message::error(e.what()));
    }
  }
  ImGui::SameLine();
  if (ui::button("close##bench", ImVec2(0, 0), "forget the set and its caches")) {
    bench.close();
    v.open = false;
  }
  ImGui::SameLine();
  if (ui::button("pair view##bench", ImVec2(0, 0), "back to the 3D view of the current pair"))
    state.main_view = MainView::pair;
}

}  // namespace

std::string progress_line(const BenchStatus& st) {
  const SetProgress p = st.pass_progress();
  std::string text;
  if (st.busy) {
    text = ui::timings_shown() ? progress_text(p)
                               : std::to_string(p.done) + "/" + std::to_string(p.total) +
                                     " pairs, " + ui::kHiddenTiming + " pairs/s, " +
                                     ui::kHiddenTiming + " s left";
    text += " (running); ";
  } else {  // nothing is left to wait for: no time left
    const auto rate = p.rate();
    text = std::to_string(p.done) + "/" + std::to_string(p.total) + " pairs, " +
           (!ui::timings_shown() ? ui::kHiddenTiming
            : rate              ? ui::format("%.2f", *rate)
                                : std::string("n/a")) +
           " pairs/s" + (st.cancelled ? " (cancelled); " : "; ");
  }
  return text + ui::timing("%.2f s", st.pass_ms / 1000.0) + " with " + std::to_string(st.jobs) +
         (st.jobs == 1 ? " job" : " jobs");
}

namespace {

// The number of pairs evaluated at once, and a button for one per core.
void jobs_controls(BenchViewState& v, BenchWorker& bench) {
  ImGui::SetNextItemWidth(110);
  if (ui::input_int("jobs##bench", &v.jobs, 1, kMaxBenchJobs, 1, true,
                    "pairs evaluated at once, each on a runner of its own with its share of the "
                    "budget (pagor bench --jobs); the rows are the same for any number, only the "
                    "times differ. Takes effect at the next pass or sweep, which starts with empty "
                    "caches"))
    bench.set_jobs(v.jobs);
  ImGui::SameLine();
  const int cores = std::min(parse_jobs("auto", "jobs"), kMaxBenchJobs);
  const std::string tip = "one job per core: " + std::to_string(cores) + " on this machine";
  if (ui::button("all cores##bench_jobs", ImVec2(0, 0), tip.c_str())) {
    v.jobs = cores;
    bench.set_jobs(v.jobs);
  }
}

void progress_and_cache(BenchViewState& v, BenchWorker& bench, const BenchStatus& st) {
  const std::string text = progress_line(st);
  // Cancel while the pass runs; after a cancel, run the rest.
  if (st.busy) {
    if (ui::button("cancel##bench", ImVec2(0, 0),
                   "stop evaluating the set after the pair in progress (rows done stay)"))
      bench.cancel();
    ImGui::SameLine();
  } else if (st.cancelled) {
    if (ui::button("resume##bench", ImVec2(0, 0),
                   "evaluate the set again with these parameters (cached pairs are quick)"))
      bench.rerun();
    ImGui::SameLine();
  }
  ImGui::ProgressBar(st.total ? float(st.done) / st.total : 0.0f, ImVec2(-1, 0), text.c_str());
  ImGui::Text("caches: %d of %d pairs kept, %.0f MiB of %d MiB", st.cached, st.total,
              double(st.cache_bytes) / (1 << 20), v.budget_mib);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(160);
  if (ui::slider_int(
          "budget [MiB]##bench", &v.budget_mib, 64, 8192, true,
          "memory the per-pair caches may hold; pairs beyond it re-run from their files"))
    bench.set_budget(std::size_t(v.budget_mib) << 20);
  ImGui::SameLine();
  jobs_controls(v, bench);
  if (!st.error.empty()) ui::figure(st.error, ImVec4(1, 0.45f, 0.4f, 1));
}

void summary_line(const BenchmarkSummary& s) {
  ui::figure(summary_text(s));
}

void table_controls(BenchViewState& v) {
  ImGui::SetNextItemWidth(160);
  ui::input_text("filter##bench", &v.filter, "show the pairs whose name contains this");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(130);
  if (ui::begin_combo("show##bench", kShow[static_cast<int>(v.show)].second,
                      "which rows to list")) {
    for (const auto& [filter, name] : kShow)
      if (ui::selectable((std::string(name) + "##show").c_str(), v.show == filter)) v.show = filter;
    ui::end_combo();
  }
  ImGui::SameLine();
  ImGui::SetNextItemWidth(130);
  if (ui::begin_combo("sort by##bench", kColumns[std::clamp(v.sort, 0, kColumnCount - 1)],
                      "column the rows are sorted by")) {
    for (int i = 0; i < kColumnCount; ++i)
      if (ui::selectable((std::string(kColumns[i]) + "##sort").c_str(), v.sort == i)) v.sort = i;
    ui::end_combo();
  }
  ImGui::SameLine();
  ui::checkbox("descending##bench", &v.descending, "reverse the order");
}

// The cells after the name of a row that has an outcome.
void row_cells(const BenchRow& r) {
  const PairOutcome& o = r.outcome;
  ImGui::TableNextColumn();
  ImGui::TextUnformatted(!o.loaded ? "failed" : o.accepted ? "accept" : "reject");
  if (!o.loaded) ui::tooltip(o.load_error.c_str());
  ImGui::TableNextColumn();
  ImGui::TextUnformatted(truth_text(o));
  ImGui::TableNextColumn();
  if (o.error)
    ImGui::Text("%.2f", o.error->translation);
  else
    ImGui::TextUnformatted("-");
  ImGui::TableNextColumn();
  if (o.error)
    ImGui::Text("%.2f", o.error->rotation_deg);
  else
    ImGui::TextUnformatted("-");
  ImGui::TableNextColumn();
  if (o.selected_level >= 0)
    ImGui::Text("%d", o.selected_level);
  else
    ImGui::TextUnformatted("-");
  ImGui::TableNextColumn();
  ImGui::Text("%.1f", 100.0 * o.margin);
  ImGui::TableNextColumn();
  ui::figure(ui::timing("%.0f", r.last_ms));
  ImGui::TableNextColumn();
  ImGui::TextUnformatted(r.cached ? "yes" : "no");
  ImGui::TableNextColumn();  // the stage at fault (diagnosis.hpp); needs the ground truth
  ui::figure(o.diagnosis.empty() ? (o.has_ground_truth ? "n/a" : "no truth") : o.diagnosis);
  if (!o.diagnosis.empty())
    ui::tooltip(
        "the diagnosis against the ground truth: open the pair and switch the bottom "
        "panel to 'diagnosis' for why");
}

// Opens row `i` in the pair view: the set's pair, or the pair a results row names.
void open_row(const PairSet& set, bool results, const BenchWorker& bench, const BenchRow& row,
              std::size_t i, StudioActions& actions) {
  if (!results) {
    if (i < set.pairs.size()) actions.open_pair(set.pairs[i], std::nullopt);
  } else {
    const PairOutcome& o = row.outcome;
    const auto entry = result_pair(o, bench.origin());
    if (!entry) {
      actions.notify(Message::error("pair " + o.name + ": its files are not there (" +
                                    o.source_name + ", " + o.target_name + ")"));
      return;
    }
    // A file pair keeps the truth its row recorded; a KITTI pair has the sequence's.
    actions.open_pair(*entry, entry->source.kind == PairSource::Kind::files
                                  ? o.T_target_source_gt
                                  : std::optional<Transform>());
  }
}

void rows_table(const BenchViewState& v, const std::vector<BenchRow>& rows, BenchWorker& bench,
                StudioActions& actions) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < rows.size(); ++i)
    if (shown(rows[i], v)) order.push_back(i);
  const auto text = [&](std::size_t i) -> const std::string& {
    return v.sort == kDiagnosisColumn ? rows[i].outcome.diagnosis : rows[i].outcome.name;
  };
  const bool by_text = v.sort == 0 || v.sort == kDiagnosisColumn;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const bool less = by_text ? text(a) < text(b) : key(rows[a], v.sort) < key(rows[b], v.sort);
    const bool more = by_text ? text(b) < text(a) : key(rows[b], v.sort) < key(rows[a], v.sort);
    return v.descending ? more : less;
  });
  const float h = std::min(ImGui::GetTextLineHeightWithSpacing() * (order.size() + 1.5f), 300.0f);
  if (!ImGui::BeginTable("##bench_rows", kColumnCount,
                         ImGuiTableFlags_RowBg | ImGuiTableFlags_Borders | ImGuiTableFlags_ScrollY,
                         ImVec2(0, h)))
    return;
  ImGui::TableSetupScrollFreeze(0, 1);
  for (const char* c : kColumns) ImGui::TableSetupColumn(c);
  ImGui::TableHeadersRow();
  const PairSet set = bench.set();
  const bool results = !bench.can_rerun();  // rows of a results file: their own files
  for (std::size_t i : order) {
    const BenchRow& r = rows[i];
    const PairOutcome& o = r.outcome;
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    if (!r.current) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.55f, 0.55f, 0.6f, 1));
    const std::string label = o.name + "##bench_row" + std::to_string(i);
    if (ui::selectable(label.c_str(), false)) open_row(set, results, bench, r, i, actions);
    ui::tooltip(results ? "open this pair (its files as the results name them, with the ground "
                          "truth they recorded) in the pair view with these parameters"
                        : "open this pair in the pair view with these parameters");
    if (!r.done) {  // not run yet with any parameters
      for (int c = 1; c < kColumnCount; ++c) {
        ImGui::TableNextColumn();
        ImGui::TextUnformatted("...");
      }
    } else {
      row_cells(r);
    }
    if (!r.current) ImGui::PopStyleColor();
  }
  ImGui::EndTable();
}

}  // namespace

void open_benchmark(BenchPanelState& state, BenchWorker& bench) {
  BenchViewState& v = state.view;
  const std::string path = resolve_path(state.base_dir, v.path);
  if (v.path.empty()) throw InputError("benchmark: name a file to open");
  if (v.source == BenchSource::results) {
    bench.show_results(read_bench_results(path), path);
  } else {
    PairSet set = v.source == BenchSource::kitti_pairs
                      ? kitti_pair_set(resolve_path(state.base_dir, v.kitti_root), v.sequence, path)
                      : read_pair_manifest(path);
    bench.set_budget(std::size_t(std::max(1, v.budget_mib)) << 20);
    bench.set_jobs(v.jobs);
    bench.open(std::move(set), state.config);
  }
  v.open = true;
  state.main_view = MainView::benchmark;
}

void benchmark_view(BenchPanelState state, BenchWorker& bench, StudioActions& actions) {
  const BenchStatus st = bench.status();
  const std::vector<BenchRow> rows = bench.rows();
  source_controls(state, bench, actions);
  if (!bench.origin().empty()) ImGui::Text("open: %s", bench.origin().c_str());
  indoor_preset_hint(state.config, state.preset, bench.plan() != nullptr, "bench", actions);
  if (bench.can_rerun()) progress_and_cache(state.view, bench, st);
  std::vector<PairOutcome> outcomes;
  for (const BenchRow& r : rows)
    if (r.done && r.current) outcomes.push_back(r.outcome);
  const BenchmarkSummary summary = summarize(outcomes);
  summary_line(summary);
  table_controls(state.view);
  rows_table(state.view, rows, bench, actions);
  const float w = ImGui::GetContentRegionAvail().x;
  const Exports to{state.view.plot_path, actions};
  plot_with_exports(to, "rates", rates_plot(summary), w * 0.5f - 4);
  ImGui::SameLine();
  plot_with_exports(to, "picking", picking_plot(summary), w * 0.5f - 4);
  if (const auto plan = bench.plan()) {              // an indoor set: its trajectory over the plan
    std::vector<PairOutcome> sequence(rows.size());  // by scan index; not yet run: left out
    for (std::size_t i = 0; i < rows.size(); ++i)
      if (rows[i].done && rows[i].current) sequence[i] = rows[i].outcome;
    plot_with_exports(to, "trajectory", trajectory_plot(sequence, plan.get()), w,
                      kTrajectoryHeight);
  }
  ui::input_text("export path##bench", &state.view.plot_path,
                 "plots are written to PATH-<plot>.png and .csv");
  ImGui::PushID("sweep_section");
  if (ui::header("Sweep", true)) {
    if (bench.can_rerun())
      sweep_section(state, bench, st, actions);
    else
      ui::figure_dim("open a manifest or pairs file above to sweep parameters over its pairs");
  }
  ImGui::PopID();
}

}  // namespace pagor::studio
