// The status bar: the worker's progress or the last run's stage times, the frame time, the
// run's warnings, and the worker's error or else the last message for the user.

#include <imgui.h>

#include <string>

#include "panels/panels.hpp"
#include "widgets/widgets.hpp"

namespace pagor::studio {
namespace {

const ImVec4 kErrorColor(1.0f, 0.35f, 0.35f, 1.0f), kWarningColor(1.0f, 0.8f, 0.3f, 1.0f);

// The worker's error first (the results shown are not of the last request), else the message.
void message_line(const std::string& worker_error, const Message& message) {
  if (!worker_error.empty()) {
    ImGui::SameLine();
    ImGui::TextColored(kErrorColor, "| error: %s", worker_error.c_str());
    return;
  }
  if (message.text.empty()) return;
  ImGui::SameLine();
  switch (message.level) {
    case MessageLevel::error:
      ImGui::TextColored(kErrorColor, "| error: %s", message.text.c_str());
      break;
    case MessageLevel::warning:
      ImGui::TextColored(kWarningColor, "| warning: %s", message.text.c_str());
      break;
    case MessageLevel::info:
      ImGui::TextDisabled("| %s", message.text.c_str());
      break;
  }
  if (!message.detail.empty() && ImGui::IsItemHovered()) {
    ImGui::BeginTooltip();
    ImGui::TextUnformatted(message.detail.c_str());
    ImGui::EndTooltip();
  }
}

}  // namespace

void status_bar(const WorkerStatus& status, const Snapshot* snapshot, const Message& message,
                double frame_ms) {
  if (status.busy) {
    ImGui::ProgressBar(static_cast<float>(status.fraction), ImVec2(160, 0));
    ImGui::SameLine();
    ImGui::Text("%s ...", status.activity.empty() ? "working" : status.activity.c_str());
  } else if (snapshot) {
    const Snapshot& s = *snapshot;
    std::string ran, times;
    double total = 0;
    for (int i = 0; i < kStageCount; ++i) {
      const auto k = static_cast<std::size_t>(i);
      if (!s.stage_ran[k]) continue;
      ran += std::string(ran.empty() ? "" : ", ") + stage_name(static_cast<Stage>(i));
      total += s.stage_ms[k];
    }
    ImGui::Text("ready | last run %.0f ms: %s", total,
                ran.empty() ? "nothing to recompute" : ran.c_str());
    if (ImGui::IsItemHovered()) {
      ImGui::BeginTooltip();
      for (int i = 0; i < kStageCount; ++i)
        ImGui::Text("%-18s %8.1f ms%s", stage_name(static_cast<Stage>(i)),
                    s.stage_ms[static_cast<std::size_t>(i)],
                    s.stage_ran[static_cast<std::size_t>(i)] ? "" : " (cached)");
      ImGui::EndTooltip();
    }
  } else {
    ImGui::TextDisabled("no data open");
  }
  ImGui::SameLine();
  ImGui::TextDisabled("| frame %.1f ms", frame_ms);
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
    if (ui::figure(std::string("| diagnosis: ") + verdict_name(d.verdict) + ": " + d.explanation,
                   ok ? ImVec4(0.45f, 0.85f, 0.45f, 1.0f) : kErrorColor))
      ImGui::SetTooltip("%s\n%s", verdict_sentence(d.verdict), d.explanation.c_str());
  }
}

}  // namespace pagor::studio
