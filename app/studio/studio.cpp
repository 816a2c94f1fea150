#include "studio.hpp"

#include <imgui.h>

#include <algorithm>
#include <cassert>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "pagor/errors.hpp"
#include "panels/benchmark_view.hpp"
#include "panels/panels.hpp"
#include "render/png.hpp"
#include "render/ui_font.hpp"
#include "widgets/plot_export.hpp"
#include "widgets/widgets.hpp"

namespace pagor::studio {
namespace {

constexpr float kStatusHeight = 28.0f, kSplitter = 6.0f, kMinPane = 80.0f;  // [px]
constexpr float kMaxLeftShare = 0.45f;  // of the window width: the view keeps the larger part
constexpr ImGuiWindowFlags kPanelFlags =
    ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
    ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus;
constexpr ImGuiWindowFlags kBarFlags = kPanelFlags | ImGuiWindowFlags_NoTitleBar |
                                       ImGuiWindowFlags_NoScrollbar |
                                       ImGuiWindowFlags_NoScrollWithMouse;

// Key codes as GLFW numbers them (the window backend fills ImGui's KeysDown with these; the
// headless driver and tests use the same codes).
namespace key {
constexpr int F = 'F', R = 'R', T = 'T', S = 'S', O = 'O', Z = 'Z', Y = 'Y', H = 'H';
constexpr int F1 = 290, Escape = 256, Left = 263, Right = 262;
}  // namespace key

void place(float x, float y, float w, float h) {
  ImGui::SetNextWindowPos(ImVec2(x, y));
  ImGui::SetNextWindowSize(ImVec2(std::max(w, 1.0f), std::max(h, 1.0f)));
}

}  // namespace

const std::vector<Shortcut>& shortcuts() {
  static const std::vector<Shortcut> list = {
      {"F", "fit the view to everything shown"},
      {"R", "reset the camera"},
      {"T", "toggle top-down (orthographic) view"},
      {"+ / -", "larger / smaller points"},
      {"Left / Right", "previous / next pair of the pairs file"},
      {"S", "save a screenshot (PNG path in the Session panel)"},
      {"Ctrl+S / Ctrl+O", "save / load the session"},
      {"Ctrl+Z / Ctrl+Y", "undo / redo a parameter change"},
      {"F1 or H", "show or hide this help"},
      {"mouse", "left drag orbits, right drag pans, wheel zooms"},
  };
  return list;
}

Studio::Studio(const Gl& gl, AppState state) : gl_(gl), state_(std::move(state)) {
  params_.reset(state_.config);
}

Studio::~Studio() {
  scene_.shutdown();
  imgui_renderer_.shutdown();
}

bool Studio::init(std::string& error) {
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // the layout lives in the session
  if (io.KeyMap[ImGuiKey_Tab] < 0) {
    // No platform backend (headless): map ImGui's named keys to the same codes GLFW uses.
    const std::pair<ImGuiKey_, int> keys[] = {
        {ImGuiKey_Tab, 258},        {ImGuiKey_LeftArrow, 263},
        {ImGuiKey_RightArrow, 262}, {ImGuiKey_UpArrow, 265},
        {ImGuiKey_DownArrow, 264},  {ImGuiKey_PageUp, 266},
        {ImGuiKey_PageDown, 267},   {ImGuiKey_Home, 268},
        {ImGuiKey_End, 269},        {ImGuiKey_Insert, 260},
        {ImGuiKey_Delete, 261},     {ImGuiKey_Backspace, 259},
        {ImGuiKey_Space, 32},       {ImGuiKey_Enter, 257},
        {ImGuiKey_Escape, 256},     {ImGuiKey_KeyPadEnter, 335},
        {ImGuiKey_A, 'A'},          {ImGuiKey_C, 'C'},
        {ImGuiKey_V, 'V'},          {ImGuiKey_X, 'X'},
        {ImGuiKey_Y, 'Y'},          {ImGuiKey_Z, 'Z'}};
    for (const auto& [k, code] : keys) io.KeyMap[k] = code;
  }
  if (!load_ui_font(kUiFontSize, error)) return false;
  ImGui::StyleColorsDark();
  ImGuiStyle& style = ImGui::GetStyle();
  style.WindowRounding = 0.0f;
  style.FrameRounding = 3.0f;
  style.ItemSpacing = ImVec2(6, 4);
  style.WindowMinSize = ImVec2(1, 1);  // splitter bars are a few pixels wide
  return imgui_renderer_.init(gl_, error) && scene_.init(gl_, error);
}

void Studio::submit_data() {
  if (!state_.have_data) return;
  // A scan against a floor plan is planar: new indoor data is looked at from above (a camera
  // restored from a session stays as it was).
  if (!state_.camera_fitted && is_indoor(state_.data)) {
    state_.camera.top_down = true;
    state_.camera.yaw_deg = kPlanYawDeg;
  }
  worker_.submit(resolved_data(state_), state_.config);
}

void Studio::submit_config() {
  try {
    validate(state_.config, "parameters");
  } catch (const ConfigError&) {
    return;  // shown at the widgets and as stale results; sent once valid again
  }
  worker_.submit(std::nullopt, state_.config);
  bench_.set_config(state_.config);  // the open benchmark set follows the parameters
}

void Studio::open_benchmark_now() {
  try {
    open_benchmark(state_, bench_);
  } catch (const Error& e) {
    state_.bench.open = false;
    state_.message = e.what();
    state_.message_is_error = true;
  }
}

void Studio::write_plot_exports(int width, int height) {
  std::vector<PlotExport> exports;
  exports.swap(plot_exports_);
  for (const PlotExport& e : exports) {
    const int w = std::min(width, kPlotPngWidth), h = std::min(height, kPlotPngHeight);
    try {
      render_plot(gl_, imgui_renderer_, e.plot, w, h);
      write_framebuffer_png(gl_, e.path, w, h);
      state_.message =
          "wrote " + e.path + " (" + std::to_string(w) + "x" + std::to_string(h) + " px)";
      state_.message_is_error = false;
    } catch (const Error& ex) {
      state_.message = ex.what();
      state_.message_is_error = true;
    }
  }
}

void Studio::undo() {
  if (auto c = params_.undo()) {
    state_.config = std::move(*c);
    state_.message = "undo (" + std::to_string(params_.undo_steps()) + " more)";
    state_.message_is_error = false;
    submit_config();
  }
}

void Studio::redo() {
  if (auto c = params_.redo()) {
    state_.config = std::move(*c);
    state_.message = "redo (" + std::to_string(params_.redo_steps()) + " more)";
    state_.message_is_error = false;
    submit_config();
  }
}

void Studio::save_session_now() {
  try {
    save_session(state_, state_.session_path);
    state_.message = "saved " + state_.session_path;
    state_.message_is_error = false;
  } catch (const Error& e) {
    state_.message = e.what();
    state_.message_is_error = true;
  }
}

void Studio::load_session_now() {
  try {
    load_session(state_.session_path, state_);
    state_.message = "loaded " + state_.session_path;
    state_.message_is_error = false;
    params_.reset(state_.config);
    if (state_.have_data) submit_data();
    if (state_.bench.open) open_benchmark_now();
  } catch (const Error& e) {
    state_.message = e.what();
    state_.message_is_error = true;
  }
}

void Studio::queue_key(int key, bool ctrl, bool shift) {
  keys_.push_back({key, ctrl, shift});
}

void Studio::handle_shortcuts(UiContext& ui) {
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
      case key::R: {
        const bool top_down = state_.camera.top_down;
        state_.camera = Camera{};
        state_.camera.top_down = top_down;
        state_.camera_fitted = false;
        break;
      }
      case key::T:
        state_.camera.top_down = !state_.camera.top_down;
        state_.camera_fitted = false;
        break;
      case key::S:
        state_.want_screenshot = true;
        break;
      case key::Left:
        step_pair(ui, state_.pair_index < 0 ? 0 : -1);
        break;
      case key::Right:
        step_pair(ui, 1);
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

void Studio::update_staleness(const WorkerStatus& status) {
  config_error_.clear();
  try {
    validate(state_.config, "parameters");
  } catch (const ConfigError& e) {
    config_error_ = e.what();
  }
  stale_reason_.clear();
  if (!config_error_.empty())
    stale_reason_ = "the parameters are invalid: " + config_error_;
  else if (status.busy || status.submitted != status.finished)
    stale_reason_ = "a run is pending";
  else if (!status.error.empty())
    stale_reason_ = "the last run failed: " + status.error;
  else if (snapshot_ && config_to_json(snapshot_->config, -1) != config_to_json(state_.config, -1))
    stale_reason_ = "the parameters changed since this run";
}

void Studio::layout_windows(UiContext& ui, float W, float H) {
  LayoutState& layout = state_.layout;
  const float left = std::clamp(layout.left_width, ViewLimits::min_left_width,
                                std::max(ViewLimits::min_left_width, kMaxLeftShare * W));
  place(0, 0, left, H);
  if (ImGui::Begin("Pagor Studio", nullptr, kPanelFlags)) {
    ImGui::PushItemWidth(-std::min(130.0f, left * 0.42f));  // room for the labels
    // Each panel in its own ID scope: equal labels in two panels ("source") are two widgets.
    const auto section = [](const char* label, bool open, auto&& draw) {
      ImGui::PushID(label);
      if (ui::header(label, open)) draw();
      ImGui::PopID();
    };
    section("Data", true, [&] { data_panel(ui); });
    section("Parameters", true, [&] { parameters_panel(ui); });
    section("View", true, [&] { view_panel(ui); });
    section("History", false, [&] { history_panel(ui); });
    section("Session", false, [&] { session_panel(ui); });
    ImGui::PopItemWidth();
  }
  ImGui::End();

  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0.0f);
  place(left, 0, kSplitter, H);
  if (ImGui::Begin("##vsplit", nullptr, kBarFlags)) {
    // Stored only when dragged: a window shrunk for a moment shows a narrower panel, and the
    // user's width comes back when it grows again.
    const ImVec2 d = ui::splitter("##left_splitter", ImVec2(kSplitter, H), true);
    if (d.x != 0.0f)
      layout.left_width =
          std::clamp(left + d.x, ViewLimits::min_left_width,
                     std::min(ViewLimits::max_left_width,
                              std::max(ViewLimits::min_left_width, kMaxLeftShare * W)));
  }
  ImGui::End();
  const float x = left + kSplitter, w = std::max(1.0f, W - x);
  const float scene_h = std::floor(std::clamp(H * layout.scene_share, std::min(kMinPane, H * 0.5f),
                                              std::max(H * 0.5f, H - kMinPane - kSplitter)));
  if (state_.main_view == MainView::benchmark) {
    ImGui::PopStyleVar(2);
    place(x, 0, w, H);
    if (ImGui::Begin("Benchmark", nullptr, kPanelFlags)) benchmark_view(ui);
    ImGui::End();
    place(0, H, W, kStatusHeight);
    if (ImGui::Begin("##status", nullptr, kBarFlags)) status_bar(ui);
    ImGui::End();
    return;
  }
  place(x, scene_h, w, kSplitter);
  if (ImGui::Begin("##hsplit", nullptr, kBarFlags)) {
    const ImVec2 d = ui::splitter("##scene_splitter", ImVec2(w, kSplitter), false);
    if (d.y != 0)
      layout.scene_share =
          std::clamp((scene_h + d.y) / H, ViewLimits::min_scene_share, ViewLimits::max_scene_share);
  }
  ImGui::End();

  place(x, 0, w, scene_h);
  const int level = snapshot_ ? shown_level(state_.view, snapshot_->selected,
                                            static_cast<int>(snapshot_->levels.size()))
                              : -1;
  std::string title = "3D view";
  if (snapshot_)
    title +=
        " | " + snapshot_->description + (level >= 0 ? " | level " + std::to_string(level) : "");
  title += "###scene";
  if (ImGui::Begin(title.c_str(), nullptr,
                   kPanelFlags | ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse))
    scene_window(ui);
  ImGui::End();
  ImGui::PopStyleVar(2);

  place(x, scene_h + kSplitter, w, H - scene_h - kSplitter);
  const bool diagnosis = state_.view.diagnosis.panel;
  if (ImGui::Begin(diagnosis ? "Diagnosis" : "Pyramid", nullptr, kPanelFlags)) {
    bottom_panel_switch(ui);
    diagnosis ? diagnosis_panel(ui) : pyramid_panel(ui);
  }
  ImGui::End();

  place(0, H, W, kStatusHeight);
  if (ImGui::Begin("##status", nullptr, kBarFlags)) status_bar(ui);
  ImGui::End();
}

void Studio::help_overlay(float W, float H) {
  ImGui::SetNextWindowPos(ImVec2(W * 0.5f, H * 0.5f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowBgAlpha(0.94f);
  if (ImGui::Begin("Shortcuts (F1 or H to close)", nullptr,
                   ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                       ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoMove)) {
    if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) {
      for (const Shortcut& s : shortcuts()) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextColored(ImVec4(1.0f, 0.85f, 0.4f, 1.0f), "%s", s.keys);
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(s.action);
      }
      ImGui::EndTable();
    }
    if (ui::button("close##help", ImVec2(-1, 0))) state_.show_help = false;
  }
  ImGui::End();
}

void Studio::frame(int width, int height) {
  const auto t0 = std::chrono::steady_clock::now();
  state_.width = width;
  state_.height = height;
  snapshot_ = worker_.snapshot();
  runs_.observe(snapshot_);
  const WorkerStatus status = worker_.status();
  update_staleness(status);

  ui::registry().begin_frame();
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = ImVec2(static_cast<float>(width), static_cast<float>(height));
  ImGui::NewFrame();
  UiContext ui{state_,
               snapshot_.get(),
               status,
               [this] { submit_data(); },
               [this] { submit_config(); },
               scene_,
               frame_ms_,
               config_error_,
               stale_reason_,
               &runs_,
               &params_,
               [this] { undo(); },
               [this] { redo(); },
               [this] { save_session_now(); },
               [this] { load_session_now(); },
               &bench_,
               [this](const Plot& plot, const std::string& path) {
                 plot_exports_.push_back({plot, path});
               }};
  handle_shortcuts(ui);
  const float W = static_cast<float>(width), H = static_cast<float>(height) - kStatusHeight;
  layout_windows(ui, W, H);
  if (state_.show_help) help_overlay(W, H);
  // One undo step per finished edit (a slider drag is one step), valid configurations only.
  if (!ImGui::IsAnyItemActive() && config_error_.empty()) params_.commit(state_.config);

  ImGui::Render();
  for (const auto& d : ui::registry().duplicates()) {
    // Reported once per ID; in a debug build a duplicate is a programming error.
    static std::vector<ImGuiID> reported;
    if (std::find(reported.begin(), reported.end(), d.id) != reported.end()) continue;
    reported.push_back(d.id);
    std::fprintf(stderr, "pagor-studio: %s\n", d.describe().c_str());
    state_.message = d.describe();
    state_.message_is_error = true;
    assert(!"duplicate ImGui ID");
  }
  write_plot_exports(width, height);  // drawn over by this frame before it is shown
  gl_.BindFramebuffer(GL_FRAMEBUFFER, 0);
  gl_.Viewport(0, 0, width, height);
  gl_.ClearColor(0.08f, 0.08f, 0.09f, 1.0f);
  gl_.Clear(GL_COLOR_BUFFER_BIT);
  imgui_renderer_.render(ImGui::GetDrawData(), width, height);
  gl_.Finish();
  if (state_.want_screenshot) {
    state_.want_screenshot = false;
    std::string error;
    const bool ok = screenshot(state_.screenshot_path, width, height, error);
    state_.message = ok ? "wrote " + state_.screenshot_path : error;
    state_.message_is_error = !ok;
  }
  frame_ms_ =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

bool Studio::screenshot(const std::string& path, int width, int height, std::string& error) const {
  try {
    write_framebuffer_png(gl_, path, width, height);
  } catch (const InputError& e) {
    error = e.what();
    return false;
  }
  return true;
}

}  // namespace pagor::studio
