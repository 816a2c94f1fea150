// The View panel's camera views: saved under a name and restored with a click (kept in the
// session), and copied or pasted as one line of JSON, the session's "camera" object.

#include <imgui.h>

#include "pagor/errors.hpp"
#include "panels/panels.hpp"
#include "state/camera_views.hpp"
#include "widgets/widgets.hpp"

namespace pagor::studio {

void camera_views_panel(std::vector<CameraView>& views, CameraControl camera,
                        StudioActions& actions) {
  ImGui::BeginDisabled(views.size() >= kMaxCameraViews);
  if (ui::button("save view", ImVec2(0, 0),
                 "Keep the camera as it is now under a name (kept in the session); a click on "
                 "the name brings it back.")) {
    views.push_back({next_view_name(views), camera.camera});
    actions.notify(Message::info("saved the camera as \"" + views.back().name + "\"",
                                 camera_text(camera.camera)));
  }
  ImGui::EndDisabled();
  ImGui::SameLine();
  if (ui::button("copy view", ImVec2(0, 0),
                 "Put the camera on the clipboard as JSON (the session's \"camera\" object): "
                 "paste it into another studio, a session file or a note."))
    actions.copy_text(camera_text(camera.camera), "the camera view as JSON");
  ImGui::SameLine();
  if (ui::button("paste view", ImVec2(0, 0),
                 "Set the camera from JSON on the clipboard (what \"copy view\" puts there).")) {
    const char* text = ImGui::GetClipboardText();
    try {
      camera.camera = camera_from_text(text ? text : "", camera.camera, "the clipboard: camera");
      camera.fitted = true;  // kept: not framed again when data arrives
      actions.notify(Message::info("camera set from the clipboard"));
    } catch (const InputError& e) {
      actions.notify(Message::error(e.what()));
    }
  }
  for (std::size_t i = 0; i < views.size(); ++i) {
    ImGui::PushID(static_cast<int>(i));
    const CameraView& v = views[i];
    const std::string tip = "Back to this camera: " + camera_text(v.camera);
    if (ui::button(v.name.c_str(), ImVec2(0, 0), tip.c_str())) {
      camera.camera = v.camera;
      camera.fitted = true;
    }
    ImGui::SameLine(0, 2);
    const bool remove = ui::small_button("x##view", "Forget this view.");
    ImGui::PopID();
    if (remove) {
      views.erase(views.begin() + static_cast<std::ptrdiff_t>(i));
      break;
    }
    // The next name on this line when it fits, else on the next.
    if (i + 1 < views.size()) {
      const ImGuiStyle& st = ImGui::GetStyle();
      const float next_w = ImGui::CalcTextSize(views[i + 1].name.c_str()).x +
                           ImGui::CalcTextSize("x").x + 4 * st.FramePadding.x + 2 +
                           st.ItemSpacing.x;
      const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
      if (ImGui::GetItemRectMax().x + next_w < right) ImGui::SameLine();
    }
  }
}

}  // namespace pagor::studio
