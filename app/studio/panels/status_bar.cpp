// The status bar: the worker's progress or the last run's stage times, the frame time, the
// run's warnings, and the worker's error or else the last message for the user.

#include <imgui.h>

#include <string>

#include "panels/panels.hpp"
#include "widgets/timings.hpp"
#include "widgets/widgets.hpp"

namespace pagor::studio {
namespace {

const ImVec4 kErrorColor(1.0f, 0.35f, 0.35f, 1.0f), kWarningColor(1.0f, 0.8f, 0.3f, 1.0f);

// The worker's error first (the results shown are not of the last request), else the message.
// The bar is one line: hovering it shows the whole text (a long error is cut at the window's
// edge) and any detail.
void message_line(const std::string& worker_error, const Message& message) {
  Message m = worker_error.empty() ? message : Message::error(worker_error);
  if (m.text.empty()) return;
  ImGui::SameLine();
  const std::string text = (m.level == MessageLevel::error     ? "| error: "
                            : m.level == MessageLevel::warning ? "| warning: "
                                                               : "| ") +
                           m.text;
  const ImVec4 color = m.level == MessageLevel::error     ? kErrorColor
                       : m.level == MessageLevel::warning ? kWarningColor
                                                          : ImGui::GetStyle().Colors[ImGuiCol_TextDisabled];
  ui::figure(text, color);
  const std::string full = m.text + (m.detail.empty() ? "" : "\n\n" + m.detail);
  ui::tooltip(full.c_str());
}

// Stages the pipeline passes over without clouds (a matcher's correspondences alone): no
// landmarks to extract, no clouds to verify, refine or accept on.
bool needs_clouds(Stage stage) {
  return stage == Stage::landmarks || stage == Stage::verification_prep ||
         stage == Stage::refinement || stage == Stage::acceptance;
}

}  // namespace

std::string run_stages_text(const Snapshot& s) {
  const bool clouds = s.source != nullptr;
  std::string ran, skipped;
  double total = 0;
  for (int i = 0; i < kStageCount; ++i) {
    const auto k = static_cast<std::size_t>(i);
    if (!s.stage_ran[k]) continue;
    const Stage stage = static_cast<Stage>(i);
    total += s.stage_ms[k];
    std::string& list = !clouds && needs_clouds(stage) ? skipped : ran;
    const std::string name = !clouds && stage == Stage::verification
                                 ? "selection by S (no clouds)"
                                 : stage_name(stage);
    list += (list.empty() ? "" : ", ") + name;
  }
  std::string text = ui::timing("last run %.0f ms: ", total) +
                     (ran.empty() ? "nothing to recompute" : ran);
  if (!skipped.empty()) text += "; skipped without clouds: " + skipped;
  return text;
}

void status_bar(const WorkerStatus& status, const Snapshot* snapshot, const Message& message,
                double frame_ms) {
  if (status.busy) {
    ImGui::ProgressBar(static_cast<float>(status.fraction), ImVec2(160, 0));
    ImGui::SameLine();
    ImGui::Text("%s ...", status.activity.empty() ? "working" : status.activity.c_str());
  } else if (snapshot) {
    const Snapshot& s = *snapshot;
    if (ui::figure("ready | " + run_stages_text(s))) {
      ImGui::BeginTooltip();
      for (int i = 0; i < kStageCount; ++i) {
        const Stage stage = static_cast<Stage>(i);
        const auto k = static_cast<std::size_t>(i);
        ImGui::Text("%-18s %8s%s", stage_name(stage), ui::timing("%.1f ms", s.stage_ms[k]).c_str(),
                    !s.source && needs_clouds(stage) ? " (skipped: no clouds)"
                    : s.stage_ran[k]                 ? ""
                                                     : " (cached)");
      }
      ImGui::EndTooltip();
    }
  } else {
    ImGui::TextDisabled("no data open");
  }
  ImGui::SameLine();
  ImGui::TextDisabled("%s", ui::timing("| frame %.1f ms", frame_ms).c_str());
  if (snapshot && !snapshot->warnings.empty()) {
    ImGui::SameLine();
    ImGui::TextColored(kWarningColor, "| %zu warnings", snapshot->warnings.size());
    if (ImGui::IsItemHovered()) {
      ImGui::BeginTooltip();
      for (const auto& w : snapshot->warnings) ImGui::TextUnformatted(w.c_str());
      ImGui::EndTooltip();
    }
  }
  message_line(status.error, message);
  if (snapshot && snapshot->diagnosis) {  // the stage at fault, in words, not only on hover
    const Diagnosis& d = *snapshot->diagnosis;
    ImGui::SameLine();
    const bool ok = d.verdict == DiagnosisVerdict::success;
    ui::figure(std::string("| diagnosis: ") + verdict_name(d.verdict) + ": " + d.explanation,
               ok ? ImVec4(0.45f, 0.85f, 0.45f, 1.0f) : kErrorColor);
    ui::hover_tooltip(std::string(verdict_sentence(d.verdict)) + "\n" + d.explanation);
  }
}

}  // namespace pagor::studio
