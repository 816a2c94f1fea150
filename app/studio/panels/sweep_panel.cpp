// The sweep section of the benchmark view: one or two parameters of the configuration (any that
// is a number, a choice or a list of numbers, by key path) over the open set, the table of
// settings ("apply" sets only the swept values), the flip view between two settings, and plots.

#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "pagor/errors.hpp"
#include "pagor/eval/sweep.hpp"
#include "panels/param_editor.hpp"
#include "panels/plot_panel.hpp"
#include "widgets/bench_plots.hpp"
#include "widgets/timings.hpp"
#include "widgets/widgets.hpp"

namespace pagor::studio {
namespace {

const ImVec4 kAmber(1.0f, 0.75f, 0.25f, 1.0f), kRed(1, 0.45f, 0.4f, 1),
    kGood(0.35f, 0.9f, 0.45f, 1);

bool sweepable(FieldKind k) {
  return k == FieldKind::number || k == FieldKind::integer || k == FieldKind::flag ||
         k == FieldKind::choice || k == FieldKind::numbers;
}

const ConfigField* find_field(const std::vector<ConfigField>& fields, const std::string& path) {
  for (const ConfigField& f : fields)
    if (f.path == path) return &f;
  return nullptr;
}

// Values around the current one: five steps, geometric on a log scale, within the range.
std::string values_around(const ConfigField& f, const Config& c) {
  if (f.kind == FieldKind::choice) {
    std::string out;
    for (const std::string& n : f.choices) out += (out.empty() ? "" : ",") + n;
    return out;
  }
  if (f.kind == FieldKind::flag) return "0,1";
  const auto v = field_number(c, f.path);
  if (!v) return field_json(c, f.path);
  std::string out;
  for (int k = -2; k <= 2; ++k) {
    double x = f.info.log_scale || *v <= 0 ? *v * std::pow(2.0, k) : *v * (1.0 + 0.25 * k);
    if (*v == 0) x = f.info.range.min + (k + 2) * 0.25 * (f.info.range.max - f.info.range.min);
    if (f.kind == FieldKind::integer) x = std::round(x);
    if (!f.info.range.contains(x)) continue;
    const std::string t = number_text(x);
    if (out.find("," + t + ",") == std::string::npos && out.rfind(t, 0) != 0)
      out += (out.empty() ? "" : ",") + t;
  }
  return out.empty() ? number_text(*v) : out;
}

// One dimension: the parameter (a combo over every sweepable path that matches `search`) and
// its values.
void dimension_fields(const char* id, std::string& path, std::string& values, const Config& c,
                      const std::string& search) {
  ImGui::PushID(id);
  const std::vector<ConfigField> fields = config_fields(c);
  const ConfigField* current = find_field(fields, path);
  if (ui::begin_combo("parameter", path.empty() ? "(none)" : path.c_str(),
                      "The parameter to sweep, by its key path (pagor config --describe); the "
                      "list holds those that match \"find\" above.")) {
    int listed = 0;
    for (const ConfigField& f : fields) {
      if (!sweepable(f.kind) || !field_matches(f, search)) continue;
      ++listed;
      if (ui::selectable(f.path.c_str(), f.path == path)) {
        path = f.path;
        values = values_around(f, c);
      }
    }
    if (listed == 0) ImGui::TextDisabled("no parameter matches \"%s\"", search.c_str());
    ui::end_combo();
  }
  std::string tip = "Comma-separated values; threshold sets separated by ';' (0.02,0.04;0.05).";
  if (current) {
    tip = std::string(current->info.doc) + "\n" + tip;
    if (current->kind == FieldKind::number || current->kind == FieldKind::integer)
      tip += "\nrange " + current->info.range.text() +
             (current->info.unit[0] ? std::string(" ") + current->info.unit : "");
  }
  ui::input_text("values", &values, tip.c_str());
  ImGui::PopID();
}

// The settings of the grid the fields describe; throws Error naming the field at fault.
std::vector<SweepSetting> settings_of(const BenchViewState& v, const Config& base) {
  SweepGrid grid;
  grid.dimensions.push_back(parse_sweep_dimension(base, v.sweep_path, v.sweep_values, "values"));
  if (!v.sweep_path2.empty())
    grid.dimensions.push_back(
        parse_sweep_dimension(base, v.sweep_path2, v.sweep_values2, "second values"));
  return sweep_settings(base, grid);
}

std::string outcome_text(const PairOutcome& o) {
  if (!o.loaded) return "skipped";
  std::string t = o.negative ? "negative" : o.success ? "success" : "failure";
  t += o.accepted ? ", accepted" : ", rejected";
  if (!o.diagnosis.empty()) t += ", " + o.diagnosis;
  return t;
}

// The pairs whose outcome differs between settings A and B; a click opens the pair with B.
void flip_view(BenchPanelState& state, const SweepResult& r, const PairSet& set,
               StudioActions& actions) {
  BenchViewState& v = state.view;
  const int n = static_cast<int>(r.settings.size());
  v.flip_a = std::clamp(v.flip_a, 0, n - 1);
  v.flip_b = std::clamp(v.flip_b, 0, n - 1);
  const auto pick = [&](const char* label, int& which) {
    if (ui::begin_combo(label, r.settings[static_cast<std::size_t>(which)].setting.label.c_str(),
                        "A setting of the sweep to compare")) {
      for (int k = 0; k < n; ++k)
        if (ui::selectable((r.settings[static_cast<std::size_t>(k)].setting.label + "##" + label +
                            std::to_string(k))
                               .c_str(),
                           k == which))
          which = k;
      ui::end_combo();
    }
  };
  ImGui::SetNextItemWidth(260);
  pick("A##flip", v.flip_a);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(260);
  pick("B##flip", v.flip_b);
  const auto flips =
      flipped_pairs(r, static_cast<std::size_t>(v.flip_a), static_cast<std::size_t>(v.flip_b));
  ui::figure(
      ui::format("%zu of %zu pairs changed between A and B (success, acceptance or "
                 "diagnosis verdict)",
                 flips.size(), r.settings[0].outcomes.size()));
  if (flips.empty() ||
      !ImGui::BeginTable("##flips", 3, ImGuiTableFlags_RowBg | ImGuiTableFlags_Borders))
    return;
  for (const char* c : {"pair (click: open with B)", "A", "B"}) ImGui::TableSetupColumn(c);
  ImGui::TableHeadersRow();
  const SweepSettingResult& b = r.settings[static_cast<std::size_t>(v.flip_b)];
  for (std::size_t i : flips) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    const std::string label = b.outcomes[i].name + "##flip" + std::to_string(i);
    if (ui::selectable(label.c_str(), false) && i < set.pairs.size()) {
      try {
        set_fields_json(state.config, b.setting.values);
        actions.open_pair(set.pairs[i], std::nullopt);
      } catch (const Error& e) {
        actions.notify(Message::error(e.what()));
      }
    }
    ImGui::TableNextColumn();
    ui::figure(outcome_text(r.settings[static_cast<std::size_t>(v.flip_a)].outcomes[i]));
    ImGui::TableNextColumn();
    ui::figure(outcome_text(b.outcomes[i]));
  }
  ImGui::EndTable();
}

// One row per setting with its rates; "apply" sets the swept values only.
void settings_table(Config& config, const SweepResult& r, StudioActions& actions) {
  // The figures' columns as wide as their text; the setting (two parameters' values in a 2-D
  // sweep) takes the rest and wraps, so the last column is never cut.
  if (!ImGui::BeginTable(
          "##sweep_rows", 6,
          ImGuiTableFlags_RowBg | ImGuiTableFlags_Borders | ImGuiTableFlags_SizingFixedFit))
    return;
  ImGui::TableSetupColumn("setting", ImGuiTableColumnFlags_WidthStretch);
  for (const char* c : {"success", "upper bound", "prec./recall/wrong", "mean time [ms]", ""})
    ImGui::TableSetupColumn(c, ImGuiTableColumnFlags_WidthFixed);
  ImGui::TableHeadersRow();
  for (std::size_t k = 0; k < r.settings.size(); ++k) {
    const SweepSettingResult& x = r.settings[k];
    const BenchmarkSummary& m = x.summary;
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ui::figure(x.setting.label, ImVec4(0, 0, 0, 0), true);
    ImGui::TableNextColumn();
    ui::figure(
        ui::format("%d/%d (%s)", m.successes, m.with_truth, rate_text(m.success_rate()).c_str()));
    ImGui::TableNextColumn();
    ui::figure(ui::format("%d/%d (%s)", m.upper_bound, m.with_truth,
                          rate_text(m.upper_bound_rate()).c_str()));
    ImGui::TableNextColumn();
    // Precision beside recall, and the wrong accepts a loop-closing user cannot afford (in red).
    ui::figure(ui::format("%s / %s / %d", rate_text(m.precision()).c_str(),
                          rate_text(m.recall()).c_str(), m.false_accepts),
               m.false_accepts > 0 ? kRed : ImVec4(0, 0, 0, 0));
    ImGui::TableNextColumn();
    ui::figure(ui::timing("%.0f", m.mean_total_ms));
    ImGui::TableNextColumn();
    if (ui::small_button(("apply##sweep" + std::to_string(k)).c_str(),
                         "Set this setting's swept values in the session's parameters; every "
                         "other parameter stays as it is.")) {
      try {
        set_fields_json(config, x.setting.values);
        actions.submit_config();
      } catch (const Error& e) {
        actions.notify(Message::error(e.what()));
      }
    }
  }
  ImGui::EndTable();
  ui::figure(
      "prec.: accepted pairs whose pose is right; recall: right poses that were accepted; wrong: "
      "poses accepted although wrong (or negatives)",
      ImGui::GetStyle().Colors[ImGuiCol_TextDisabled], true);
}

void run_controls(BenchPanelState& state, BenchWorker& bench, const BenchStatus& st,
                  StudioActions& actions) {
  BenchViewState& v = state.view;
  ui::input_text("find##sweep", &state.sweep_search,
                 "Narrow the parameter lists below to the keys or descriptions that hold every "
                 "word typed here (case-insensitive).");
  dimension_fields("dim1", v.sweep_path, v.sweep_values, state.config, state.sweep_search);
  bool two = !v.sweep_path2.empty();
  if (ui::checkbox("second parameter (2-D)##sweep", &two,
                   "Sweep every combination of two parameters.")) {
    if (two && v.sweep_path2.empty())
      v.sweep_path2 = "gnc.noise_bound", v.sweep_values2 = "0.5,1,2";
    if (!two) v.sweep_path2.clear();
  }
  if (two)
    dimension_fields("dim2", v.sweep_path2, v.sweep_values2, state.config, state.sweep_search);
  if (ui::button("run sweep##sweep", ImVec2(0, 0),
                 "Every combination over the open set, reusing each pair's cached stages, with the "
                 "view's jobs (pairs at once).")) {
    try {
      bench.sweep(settings_of(v, state.config), state.config);
    } catch (const Error& e) {
      actions.notify(Message::error(e.what()));
    }
  }
  if (st.sweeping) {
    ImGui::SameLine();
    if (ui::button("cancel sweep##sweep", ImVec2(0, 0),
                   "Stop the sweep after the run in progress; its partial results are dropped."))
      bench.cancel();
    ImGui::SameLine();
    char text[64];
    std::snprintf(text, sizeof(text), "%d / %d runs", st.sweep_done, st.sweep_total);
    ImGui::ProgressBar(st.sweep_total ? float(st.sweep_done) / st.sweep_total : 0.0f, ImVec2(-1, 0),
                       text);
  }
  if (!st.sweep_error.empty()) ui::figure(st.sweep_error, kRed, true);
}

}  // namespace

void sweep_section(BenchPanelState& state, BenchWorker& bench, const BenchStatus& st,
                   StudioActions& actions) {
  run_controls(state, bench, st, actions);
  const auto record = bench.sweep_result();
  if (!record) return;
  const SweepResult& r = record->result;
  const std::string stale = sweep_stale_reason(*record, state.config, st.set_generation);
  if (!stale.empty())
    ui::figure("STALE: the sweep below is of other inputs (" + stale + ")", kAmber, true);
  else
    ui::figure("the sweep below is of these parameters and this set", kGood);
  ImGui::PushStyleVar(ImGuiStyleVar_Alpha, stale.empty() ? 1.0f : 0.55f);
  settings_table(state.config, r, actions);
  if (ui::header("Flip view: pairs that changed between two settings##sweep", true))
    flip_view(state, r, bench.set(), actions);
  const float w = ImGui::GetContentRegionAvail().x;
  const Plot line = sweep_line_plot(r);
  const Exports to{state.view.plot_path, actions};
  plot_with_exports(to, "sweep", sweep_success_plot(r), line.series.empty() ? w : w * 0.5f - 4);
  if (!line.series.empty()) {
    ImGui::SameLine();
    plot_with_exports(to, "sweep-line", line, w * 0.5f - 4);
  }
  ImGui::PopStyleVar();
}

}  // namespace pagor::studio
