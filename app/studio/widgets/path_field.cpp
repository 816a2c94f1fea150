// The path field: a path too long for its frame shows its start and its end; a path naming
// nothing is drawn as a warning.

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <string>

#include "widgets/widget_record.hpp"
#include "widgets/widgets.hpp"

namespace pagor::studio::ui {

namespace {

// The start and the end of `path` around "...", as much of both as fits in `room` pixels: the end
// keeps the file name whole when it fits, the start gets up to a third of what is left.
std::string elide_middle(const std::string& path, float room) {
  const auto width = [](const std::string& t) { return ImGui::CalcTextSize(t.c_str()).x; };
  const std::size_t slash = path.find_last_of('/');
  const std::string name = slash == std::string::npos ? path : path.substr(slash);
  const float head_room = std::clamp(room - width("..." + name), 0.0f, room / 3);
  std::size_t head = 0;
  while (head < path.size() && width(path.substr(0, head + 1) + "...") <= head_room) ++head;
  std::size_t start = head;
  while (start < path.size() && width(path.substr(0, head) + "..." + path.substr(start)) > room)
    ++start;
  return path.substr(0, head) + "..." + path.substr(start);
}

}  // namespace

bool input_path(const char* label, std::string* path, const char* tip, bool found) {
  const ImGuiID id = ImGui::GetID(label);
  const float frame_w = ImGui::CalcItemWidth();
  const ImGuiStyle& style = ImGui::GetStyle();
  const ImVec4 warning(1.0f, 0.45f, 0.35f, 1.0f);
  if (!found) ImGui::PushStyleColor(ImGuiCol_Text, warning);
  const bool r = ImGui::InputText(label, path);
  if (!found) ImGui::PopStyleColor();
  WidgetRecord& rec = record_last(WidgetKind::input_text, label, id, frame_w);
  rec.text = *path;
  rec.warned = !found;
  // Not being edited and too long for the frame: draw its start and end over it; a click edits
  // the whole path underneath.
  const float room = frame_w - 2 * style.FramePadding.x;
  if (!ImGui::IsItemActive() && ImGui::CalcTextSize(path->c_str()).x > room) {
    const std::string shown = elide_middle(*path, room);
    rec.text = shown;  // what the field shows
    const ImVec2 a = ImGui::GetItemRectMin();
    const ImVec2 b(a.x + frame_w, ImGui::GetItemRectMax().y);
    ImDrawList* dl = ImGui::GetWindowDrawList();
    // Opaque: the frame's colour is translucent, and the path under it must not show through.
    const ImVec4 w = style.Colors[ImGuiCol_WindowBg];
    const ImVec4 f =
        style.Colors[ImGui::IsItemHovered() ? ImGuiCol_FrameBgHovered : ImGuiCol_FrameBg];
    const ImVec4 bg(w.x + (f.x - w.x) * f.w, w.y + (f.y - w.y) * f.w, w.z + (f.z - w.z) * f.w,
                    1.0f);
    dl->AddRectFilled(a, b, ImGui::GetColorU32(bg), style.FrameRounding);
    dl->AddText(ImVec2(a.x + style.FramePadding.x, a.y + style.FramePadding.y),
                found ? ImGui::GetColorU32(ImGuiCol_Text) : ImGui::GetColorU32(warning),
                shown.c_str());
  }
  if (tip)
    tooltip((std::string(tip) + (path->empty() ? "" : "\n" + *path) +
             (found ? "" : "\nnot found: no file or directory has this path"))
                .c_str());
  return r;
}

}  // namespace pagor::studio::ui
