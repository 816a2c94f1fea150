// The studio's keyboard shortcuts and the help overlay that lists them.

#include <imgui.h>

#include <algorithm>
#include <vector>

#include "panels/panels.hpp"
#include "studio.hpp"
#include "widgets/widgets.hpp"

namespace pagor::studio {
namespace {

// Key codes as GLFW numbers them (the window backend fills ImGui's KeysDown with these; the
// headless driver and tests use the same codes).
namespace key {
constexpr int F = 'F', R = 'R', T = 'T', S = 'S', O = 'O', Z = 'Z', Y = 'Y', H = 'H';
constexpr int F1 = 290, Escape = 256, Left = 263, Right = 262;
}  // namespace key

}  // namespace

const std::vector<Shortcut>& shortcuts() {
  static const std::vector<Shortcut> list = {
      {"F", "fit the view to everything shown"},
      {"R", "reset the camera"},
      {"T", "toggle top-down (orthographic) view"},
      {"+ / -", "larger / smaller points"},
      {"Left / Right", "previous / next pair of the pairs file or manifest"},
      {"S", "save a screenshot (PNG path in the Session panel)"},
      {"Ctrl+S / Ctrl+O", "save / load the session"},
      {"Ctrl+Z / Ctrl+Y", "undo / redo a parameter change"},
      {"F1 or H", "show or hide this help"},
      {"mouse", "left drag orbits, right drag pans, wheel zooms"},
      {"click", "pick the point under the mouse: its coordinates, class, label and distance to "
                "the nearest target point (top right of the 3D view)"},
      {"Shift+click", "pick a second point: the distance between the two [m]"},
      {"click on nothing", "clear the picks"},
      {"View panel", "save view, copy view / paste view: cameras kept in the session, or moved "
                     "as JSON"},
  };
  return list;
}

void Studio::queue_key(int key, bool ctrl, bool shift) {
  keys_.push_back({key, ctrl, shift});
}

void Studio::handle_shortcuts() {
  const ImGuiIO& io = ImGui::GetIO();
  std::vector<KeyPress> keys;
  keys.swap(keys_);
  if (io.WantTextInput) return;  // keys go to the field being edited
  ViewState& v = state_.view;
  for (const KeyPress& k : keys) {
    if (k.ctrl) {
      if (k.key == key::Z && k.shift)
        redo();
      else if (k.key == key::Z)
        undo();
      else if (k.key == key::Y)
        redo();
      else if (k.key == key::S)
        save_session_now();
      else if (k.key == key::O)
        load_session_now();
      continue;
    }
    switch (k.key) {
      case key::F:
        state_.camera_fitted = false;
        break;
      case key::R:
        camera_control().reset();
        break;
      case key::T:
        state_.camera.top_down = !state_.camera.top_down;
        state_.camera_fitted = false;
        break;
      case key::S:
        save_screenshot();
        break;
      case key::Left:
        step_pair(state_, -1, *this);
        break;
      case key::Right:
        step_pair(state_, 1, *this);
        break;
      case key::F1:
      case key::H:
        state_.show_help = !state_.show_help;
        break;
      case key::Escape:
        state_.show_help = false;
        break;
      default:
        break;
    }
  }
  // + and - as characters: the same on every keyboard layout and on the keypad.
  for (ImWchar c : io.InputQueueCharacters) {
    if (c == '+' || c == '=') v.point_size += 0.5f;
    if (c == '-') v.point_size -= 0.5f;
  }
  v.point_size = std::clamp(v.point_size, ViewLimits::min_point_size, ViewLimits::max_point_size);
}

void Studio::help_overlay(float W, float H) {
  ImGui::SetNextWindowPos(ImVec2(W * 0.5f, H * 0.5f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowBgAlpha(0.94f);
  if (ImGui::Begin("Shortcuts (F1 or H to close)", nullptr,
                   ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                       ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoMove)) {
    if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) {
      ImGui::TableSetupColumn("keys");
      ImGui::TableSetupColumn("action", ImGuiTableColumnFlags_WidthFixed,
                              std::min(520.0f, std::max(200.0f, W * 0.5f)));
      for (const Shortcut& s : shortcuts()) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ui::figure(s.keys, ImVec4(1.0f, 0.85f, 0.4f, 1.0f));
        ImGui::TableNextColumn();
        ui::figure(s.action, ImVec4(0, 0, 0, 0), true);
      }
      ImGui::EndTable();
    }
    if (ui::button("close##help", ImVec2(-1, 0))) state_.show_help = false;
  }
  ImGui::End();
}

}  // namespace pagor::studio
