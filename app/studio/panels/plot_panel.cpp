#include "panels/plot_panel.hpp"

#include <cstdio>
#include <filesystem>

#include "pagor/errors.hpp"
#include "pagor/io/atomic_file.hpp"
#include "pagor/sets/sweep.hpp"
#include "widgets/bench_plots.hpp"
#include "widgets/widgets.hpp"

namespace pagor::studio {

std::string absolute_path(const std::string& path) {
  if (path.empty()) return path;
  std::error_code ec;
  const auto p = std::filesystem::absolute(path, ec);
  return ec ? path : p.lexically_normal().string();
}

void plot_with_exports(const PlotExports& to, const char* id, const Plot& plot, float width,
                       float height) {
  ImGui::BeginGroup();
  ImGui::PushID(id);
  plot_widget(id, plot, ImVec2(width, height));
  // Absolute, so that the message after an export says where the file went (made on a click,
  // not every frame).
  const auto base = [&] { return absolute_path(to.base + "-" + id); };
  if (ui::small_button("PNG", "write the plot as PNG (path below the plots)"))
    to.actions.export_plot(plot, base() + ".png");
  ImGui::SameLine();
  if (ui::small_button("CSV", "write the plotted numbers as CSV")) {
    const std::string path = base() + ".csv";
    try {
      write_file_atomic(path, plot_csv(plot));
      to.actions.notify(Message::info("wrote " + path));
    } catch (const Error& e) {
      to.actions.notify(Message::error(e.what()));
    }
  }
  ImGui::PopID();
  ImGui::EndGroup();
}

void sweep_section(AppState& state, BenchWorker& bench, const BenchStatus& st,
                   StudioActions& actions) {
  BenchViewState& v = state.bench;
  ui::input_text("mu values [m]##sweep", &v.sweep_mu, "comma-separated, e.g. 0.5,1,2");
  ui::input_text("threshold sets##sweep", &v.sweep_thresholds,
                 "sets separated by ';', e.g. 0.02,0.04;0.05 (empty: the current set only)");
  if (ui::button("run sweep##sweep", ImVec2(0, 0),
                 "every combination over the open set, reusing each pair's cached stages")) {
    try {
      SweepGrid grid;
      if (!v.sweep_mu.empty())
        grid.dimensions.push_back(
            parse_sweep_dimension(state.config, "verification.mu", v.sweep_mu, "mu values"));
      if (!v.sweep_thresholds.empty())
        grid.dimensions.push_back(parse_sweep_dimension(state.config, "graph.thresholds",
                                                        v.sweep_thresholds, "threshold sets"));
      bench.sweep(sweep_settings(state.config, grid));
    } catch (const Error& e) {
      actions.notify(Message::error(e.what()));
    }
  }
  if (st.sweeping) {
    ImGui::SameLine();
    char text[64];
    std::snprintf(text, sizeof(text), "%d / %d runs", st.sweep_done, st.sweep_total);
    ImGui::ProgressBar(st.sweep_total ? float(st.sweep_done) / st.sweep_total : 0.0f, ImVec2(-1, 0),
                       text);
  }
  if (!st.sweep_error.empty())
    ImGui::TextColored(ImVec4(1, 0.45f, 0.4f, 1), "%s", st.sweep_error.c_str());
  const auto result = bench.sweep_result();
  if (!result) return;
  if (ImGui::BeginTable("##sweep_rows", 5, ImGuiTableFlags_RowBg | ImGuiTableFlags_Borders)) {
    for (const char* c : {"setting", "success", "upper bound", "mean time [ms]", ""})
      ImGui::TableSetupColumn(c);
    ImGui::TableHeadersRow();
    for (std::size_t k = 0; k < result->settings.size(); ++k) {
      const SweepSettingResult& r = result->settings[k];
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(r.setting.label.c_str());
      ImGui::TableNextColumn();
      ImGui::Text("%d/%d", r.summary.successes, r.summary.with_truth);
      ImGui::TableNextColumn();
      ImGui::Text("%d/%d", r.summary.upper_bound, r.summary.with_truth);
      ImGui::TableNextColumn();
      ImGui::Text("%.0f", r.summary.mean_total_ms);
      ImGui::TableNextColumn();
      if (ui::small_button(("apply##sweep" + std::to_string(k)).c_str(),
                           "use this setting's parameters in the session")) {
        state.config = r.setting.config;
        actions.submit_config();
      }
    }
    ImGui::EndTable();
  }
  const float w = ImGui::GetContentRegionAvail().x;
  const Plot line = sweep_line_plot(*result);
  const PlotExports to{v.plot_path, actions};
  plot_with_exports(to, "sweep", sweep_success_plot(*result),
                    line.series.empty() ? w : w * 0.5f - 4);
  if (!line.series.empty()) {
    ImGui::SameLine();
    plot_with_exports(to, "sweep-line", line, w * 0.5f - 4);
  }
}

}  // namespace pagor::studio
