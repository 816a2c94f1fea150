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

void place(float x, float y, float w, float h) {
  ImGui::SetNextWindowPos(ImVec2(x, y));
  ImGui::SetNextWindowSize(ImVec2(std::max(w, 1.0f), std::max(h, 1.0f)));
}

}  // namespace

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
  const std::uint64_t request =
      worker_.submit(resolved_data(state_), state_.config, state_.inline_truth);
  // The camera frames this data when its result arrives (the result shown until then is of the
  // data before); if it fails, whatever stays shown.
  if (!state_.camera_fitted) fit_request_ = request;
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
  // A session reopens its set in the view it was saved in (the pair view of an opened row, say).
  const MainView view = state_.main_view;
  try {
    BenchPanelState panel = bench_panel_state(state_);
    open_benchmark(panel, bench_);
    state_.main_view = view;
  } catch (const std::exception& e) {  // a file the studio cannot use: say so, keep running
    state_.bench.open = false;
    notify(Message::error(e.what()));
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
      notify(Message::info("wrote " + e.path + " (" + std::to_string(w) + "x" + std::to_string(h) +
                           " px)"));
    } catch (const Error& ex) {
      notify(Message::error(ex.what()));
    }
  }
}

void Studio::undo() {
  if (auto c = params_.undo()) {
    state_.config = std::move(*c);
    notify(Message::info("undo (" + std::to_string(params_.undo_steps()) + " more)"));
    submit_config();
  }
}

void Studio::redo() {
  if (auto c = params_.redo()) {
    state_.config = std::move(*c);
    notify(Message::info("redo (" + std::to_string(params_.redo_steps()) + " more)"));
    submit_config();
  }
}

void Studio::save_session_now() {
  try {
    save_session(state_, state_.session_path);
    notify(Message::info("saved " + state_.session_path));
  } catch (const std::exception& e) {
    notify(Message::error(e.what()));
  }
}

void Studio::load_session_now() {
  try {
    load_session(state_.session_path, state_);
    notify(Message::info("loaded " + state_.session_path));
    params_.reset(state_.config);
    if (state_.have_data) submit_data();
    if (state_.bench.open) open_benchmark_now();
  } catch (const std::exception& e) {
    notify(Message::error(e.what()));
  }
}

void Studio::save_screenshot() {
  state_.want_screenshot = true;
}

void Studio::export_plot(const Plot& plot, const std::string& path) {
  plot_exports_.push_back({plot, path});
}

void Studio::notify(Message message) {
  state_.message = std::move(message);
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

void Studio::left_panel(float left, float H) {
  place(0, 0, left, H);
  if (ImGui::Begin("Pagor Studio", nullptr, kPanelFlags)) {
    ImGui::PushItemWidth(-std::min(130.0f, left * 0.42f));  // room for the labels
    // Each panel in its own ID scope: equal labels in two panels ("source") are two widgets.
    const auto section = [](const char* label, bool open, auto&& draw) {
      ImGui::PushID(label);
      if (ui::header(label, open)) draw();
      ImGui::PopID();
    };
    AppState& s = state_;
    section("Data", true, [&] { data_panel(s, *this); });
    section("Parameters", true,
            [&] { parameters_panel(s.config, s.preset, s.search.parameters, params_, config_error_,
                             *this); });
    section("View", true, [&] {
      view_panel(s.view, camera_control(), s.show_help, snapshot_ && snapshot_->plan);
      camera_views_panel(s.camera_views, camera_control(), *this);
    });
    section("History", false, [&] { history_panel(params_, runs_, *this); });
    section("Session", false, [&] {
      session_panel(SessionFiles{s.session_path, s.screenshot_path, s.export_path}, *this);
    });
    ImGui::PopItemWidth();
  }
  ImGui::End();
}

std::string Studio::scene_title() const {
  const int level = snapshot_ ? shown_level(state_.view, snapshot_->selected,
                                            static_cast<int>(snapshot_->levels.size()))
                              : -1;
  std::string title = "3D view";
  if (snapshot_)
    title +=
        " | " + snapshot_->description + (level >= 0 ? " | level " + std::to_string(level) : "");
  return title + "###scene";
}

void Studio::pair_view(float x, float w, float H) {
  LayoutState& layout = state_.layout;
  const float scene_h = std::floor(std::clamp(H * layout.scene_share, std::min(kMinPane, H * 0.5f),
                                              std::max(H * 0.5f, H - kMinPane - kSplitter)));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0.0f);
  place(x, scene_h, w, kSplitter);
  if (ImGui::Begin("##hsplit", nullptr, kBarFlags)) {
    const ImVec2 d = ui::splitter("##scene_splitter", ImVec2(w, kSplitter), false);
    if (d.y != 0)
      layout.scene_share =
          std::clamp((scene_h + d.y) / H, ViewLimits::min_scene_share, ViewLimits::max_scene_share);
  }
  ImGui::End();

  place(x, 0, w, scene_h);
  // With a result the 3D view's picture covers the window: no background under it.
  if (ImGui::Begin(scene_title().c_str(), nullptr,
                   kPanelFlags | ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse |
                       (snapshot_ && (snapshot_->target || !snapshot_->correspondences.empty())
                            ? ImGuiWindowFlags_NoBackground
                            : 0)))
    scene_window(scene_, snapshot_.get(), state_.view, camera_control(), state_.picks);
  ImGui::End();
  ImGui::PopStyleVar(2);

  place(x, scene_h + kSplitter, w, H - scene_h - kSplitter);
  ViewState& view = state_.view;
  const bool diagnosis = view.diagnosis.panel;
  if (ImGui::Begin(diagnosis ? "Diagnosis" : "Pyramid", nullptr, kPanelFlags)) {
    bottom_panel_switch(view.diagnosis);
    const Exports exports{state_.export_path, *this};
    if (diagnosis)
      diagnosis_panel(snapshot_.get(), stale_reason_, view, exports);
    else
      pyramid_panel(snapshot_.get(), runs_.changes(), stale_reason_, view, exports);
  }
  ImGui::End();
}

void Studio::layout_windows(const WorkerStatus& status, float W, float H) {
  LayoutState& layout = state_.layout;
  const float left = std::clamp(layout.left_width, ViewLimits::min_left_width,
                                std::max(ViewLimits::min_left_width, kMaxLeftShare * W));
  left_panel(left, H);

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
  ImGui::PopStyleVar(2);
  const float x = left + kSplitter, w = std::max(1.0f, W - x);
  if (state_.main_view == MainView::benchmark) {
    place(x, 0, w, H);
    if (ImGui::Begin("Benchmark", nullptr, kPanelFlags))
      benchmark_view(bench_panel_state(state_), bench_, *this);
    ImGui::End();
  } else {
    pair_view(x, w, H);
  }
  place(0, H, W, kStatusHeight);
  if (ImGui::Begin("##status", nullptr, kBarFlags))
    status_bar(status, snapshot_.get(), state_.message, frame_ms_);
  ImGui::End();
}

void Studio::report_duplicate_ids() {
  for (const auto& d : ui::registry().duplicates()) {
    // Reported once per ID; in a debug build a duplicate is a programming error.
    static std::vector<ImGuiID> reported;
    if (std::find(reported.begin(), reported.end(), d.id) != reported.end()) continue;
    reported.push_back(d.id);
    std::fprintf(stderr, "pagor-studio: %s\n", d.describe().c_str());
    notify(Message::error(d.describe()));
    assert(!"duplicate ImGui ID");
  }
}

CameraControl Studio::camera_control() {
  return {state_.camera, state_.camera_fitted, fit_request_};
}

void Studio::frame(int width, int height) {
  const auto t0 = std::chrono::steady_clock::now();
  state_.width = width;
  state_.height = height;
  // The status before the snapshot: a request it counts as finished is in the snapshot if it
  // succeeded.
  const WorkerStatus status = worker_.status();
  const auto previous = snapshot_;
  snapshot_ = worker_.snapshot();
  // A new result, a run ended (a failure too) or the benchmark done: ImGui fits new tables and
  // texts over a few frames, so these are drawn without waiting for input.
  const bool bench_was_busy = bench_was_busy_;
  bench_was_busy_ = bench_busy();
  if (snapshot_ != previous || status.finished != finished_seen_ ||
      (bench_was_busy && !bench_was_busy_))
    settle_frames_ = kSettleFrames;
  else if (settle_frames_ > 0)
    --settle_frames_;
  finished_seen_ = status.finished;
  // A slider held by the mouse (the previous frame's active item) re-runs at every step.
  runs_.observe(snapshot_, ImGui::IsAnyItemActive() && ImGui::IsMouseDown(ImGuiMouseButton_Left));
  update_staleness(status);
  forget_unreadable(status);
  // The data the camera waits for failed (or was replaced by newer data): fit what is shown.
  if (fit_request_ && status.finished >= fit_request_ &&
      (!snapshot_ || snapshot_->request < fit_request_))
    fit_request_ = 0;

  ui::registry().begin_frame();
  ImGuiIO& io = ImGui::GetIO();
  input_.feed(io);
  for (const InputQueue::Press& p : input_.presses()) queue_key(p.key, p.ctrl, p.shift);
  io.DisplaySize = ImVec2(static_cast<float>(width), static_cast<float>(height));
  ImGui::NewFrame();
  handle_shortcuts();
  const float W = static_cast<float>(width), H = static_cast<float>(height) - kStatusHeight;
  layout_windows(status, W, H);
  if (state_.show_help) help_overlay(W, H);
  file_dialog(state_.dialog, *this);
  // One undo step per finished edit (a slider drag is one step), valid configurations only.
  if (!ImGui::IsAnyItemActive() && config_error_.empty()) params_.commit(state_.config);

  ImGui::Render();
  report_duplicate_ids();
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
    notify(screenshot(state_.screenshot_path, width, height, error)
               ? Message::info("wrote " + state_.screenshot_path)
               : Message::error(error));
  }
  frame_ms_ =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

bool Studio::bench_busy() const {
  const BenchStatus b = bench_.status();
  return b.busy || b.sweeping;
}

bool Studio::wants_frame() const {
  const WorkerStatus status = worker_.status();
  return status.busy || status.submitted != status.finished || worker_.snapshot() != snapshot_ ||
         bench_busy() || !plot_exports_.empty() || state_.want_screenshot || !keys_.empty() ||
         input_.pending() || settle_frames_ > 0;
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
