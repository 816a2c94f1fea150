// The History panel (undo/redo, the last runs) and the Session panel.

#include <imgui.h>

#include <cmath>
#include <string>

#include "panels/panels.hpp"
#include "widgets/widgets.hpp"

namespace pagor::studio {
namespace {
const ImVec4 kRed(1.0f, 0.4f, 0.4f, 1.0f);
}  // namespace

void history_panel(const ParamHistory& params, const RunHistory& runs, StudioActions& actions) {
  undo_redo_buttons(params, actions, "history");
  ImGui::SameLine();
  ImGui::TextDisabled("%zu undo, %zu redo", params.undo_steps(), params.redo_steps());
  if (runs.runs().empty()) {
    ImGui::TextDisabled("no runs yet");
    return;
  }
  const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit;
  if (ImGui::BeginTable("runs", 4, flags)) {
    ImGui::TableSetupColumn("run");
    ImGui::TableSetupColumn("sel");
    ImGui::TableSetupColumn("outcome");
    ImGui::TableSetupColumn("change");
    ImGui::TableHeadersRow();
    for (const RunRecord& r : runs.runs()) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::Text("#%llu", static_cast<unsigned long long>(r.request));
      ImGui::TableNextColumn();
      ImGui::Text("L%d", r.selected);
      ImGui::TableNextColumn();
      // Without clouds there is no D (the selection went by the correspondences' support).
      const std::string d = r.selected >= 0 && std::isfinite(r.best_d)
                                ? ui::format("D %.0f m", r.best_d)
                                : std::string("D n/a");
      if (r.success)
        ImGui::TextColored(*r.success ? ImVec4(0.35f, 0.9f, 0.45f, 1) : kRed, "%s %s",
                           *r.success ? "ok" : "FAIL", d.c_str());
      else
        ImGui::TextUnformatted(d.c_str());
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(r.change.c_str());
    }
    ImGui::EndTable();
  }
}

void session_panel(SessionFiles files, StudioActions& actions) {
  ui::input_text("session", &files.session_path,
                 "Session file: data, parameters, camera, layers, level and layout.");
  if (ui::button("save session", ImVec2(0, 0), "Writes the session file (Ctrl+S)."))
    actions.save_session_now();
  ImGui::SameLine();
  if (ui::button("load session", ImVec2(0, 0), "Reads the session file (Ctrl+O)."))
    actions.load_session_now();
  ui::input_text("PNG", &files.screenshot_path, "Where a screenshot is written.");
  if (ui::button("save screenshot", ImVec2(0, 0), "Writes the whole window as a PNG (S)."))
    actions.save_screenshot();
  ui::input_text("export path", &files.export_path,
                 "The pair view's exports (the result JSON, the levels and diagnosis tables as "
                 "CSV) are written to <export path>-<name>. The benchmark view has its own.");
}

}  // namespace pagor::studio
