#include "ui_driver.hpp"

#include <imgui_internal.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "pagor/errors.hpp"
#include "panels/panels.hpp"

namespace pagor::test {
namespace {

using studio::ui::WidgetKind;
using studio::ui::WidgetRecord;

std::string g_context = "(no action yet)";

std::string utf8(const std::u32string& text) {
  std::string out;
  for (char32_t c : text) {
    if (c < 0x80) {
      out += static_cast<char>(c);
    } else if (c < 0x800) {
      out += static_cast<char>(0xC0 | (c >> 6));
      out += static_cast<char>(0x80 | (c & 0x3F));
    } else {
      out += static_cast<char>(0xE0 | (c >> 12));
      out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (c & 0x3F));
    }
  }
  return out;
}

}  // namespace

ImVec2 centre(const WidgetRecord& w) {
  return ImVec2((w.min.x + w.max.x) * 0.5f, (w.min.y + w.max.y) * 0.5f);
}

ImVec2 frame_point(const WidgetRecord& w, float fraction) {
  return ImVec2(w.min.x + std::clamp(fraction, 0.0f, 1.0f) * std::max(1.0f, w.frame_w - 6) + 3,
                (w.min.y + w.max.y) * 0.5f);
}

void set_context(const std::string& what) {
  g_context = what;
}

}  // namespace pagor::test

// ImGui's IM_ASSERT is assert(); Debian's libimgui.a is compiled, so IM_ASSERT cannot be
// redefined. glibc's assert() calls __assert_fail; the test executable defines it, so that an
// assertion inside ImGui (or the studio) ends the test with the expression, the place and the
// action the driver was performing, instead of a bare abort.
extern "C" void __assert_fail(const char* assertion, const char* file, unsigned int line,
                              const char* function) noexcept {
  std::fprintf(stderr, "\nFAILED: assertion failed: %s\n  at %s:%u (%s)\n  while: %s\n", assertion,
               file, line, function ? function : "?", pagor::test::g_context.c_str());
  std::fflush(stderr);
  std::_Exit(86);
}

namespace pagor::test {

UiDriver::UiDriver(studio::AppState state, int width, int height) : width_(width), height_(height) {
  context_ = std::make_unique<studio::HeadlessContext>(width, height);
  std::string error;
  if (!gl_.load(studio::HeadlessContext::proc, error)) FAIL(error);
  imgui_ = ImGui::CreateContext();
  studio_ = std::make_unique<studio::Studio>(gl_, std::move(state));
  if (!studio_->init(error)) FAIL(error);
  studio_->submit_data();
  frame();
}

UiDriver::~UiDriver() {
  studio_.reset();
  ImGui::DestroyContext(imgui_);
  context_.reset();
}

void UiDriver::set_action(const std::string& a) {
  action_ = a;
  set_context(a + " (event " + std::to_string(events_) + ", frame " + std::to_string(frames_) +
              ")");
}

void UiDriver::frame() {
  ImGuiIO& io = ImGui::GetIO();
  io.DeltaTime = idle_ > 0 ? idle_ : 1.0f / 30.0f;  // two clicks are never a double click
  idle_ = 0;
  io.MousePos = mouse_;
  for (int b = 0; b < 5; ++b) io.MouseDown[b] = down_[b];
  io.MouseWheel = wheel_;
  wheel_ = 0;
  if (!studio_->input().pending()) {  // else the queue sets the key states
    io.KeyCtrl = ctrl_;
    io.KeyShift = shift_;
    std::fill(std::begin(io.KeysDown), std::end(io.KeysDown), false);
    for (int k : keys_down_) io.KeysDown[k] = true;
  }
  for (char32_t c : pending_chars_) io.AddInputCharacter(static_cast<unsigned int>(c));
  pending_chars_.clear();
  studio_->frame(width_, height_);
  ++frames_;
  max_widgets_ = std::max(max_widgets_, widgets().size());
  check_invariants();
}

void UiDriver::idle(float seconds) {
  idle_ = seconds;
  frame();
}

void UiDriver::frames(int n) {
  for (int i = 0; i < n; ++i) frame();
}

void UiDriver::settle(double timeout_s) {
  set_context("waiting for the worker after: " + action_);
  const auto t0 = std::chrono::steady_clock::now();
  for (;;) {
    const studio::WorkerStatus st = studio_->worker().status();
    if (!st.busy && st.submitted == st.finished) break;
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() > timeout_s)
      FAIL("the worker did not finish within " << timeout_s << " s after: " << action_ << " (still "
                                               << st.activity << ")");
    studio_->worker().wait_idle(0.05);
    frame();
  }
  frames(2);
}

void UiDriver::settle_bench() {
  set_context("waiting for the benchmark view after: " + action_);
  for (int i = 0; i < 6000 && !studio_->bench().wait_idle(0.05); ++i) frame();
  for (int i = 0; i < 6000 && studio_->bench().status().sweeping; ++i) frame();
  frames(3);
}

void UiDriver::open_and_run_bench() {
  REQUIRE(click_widget("benchmark view...", "Pagor Studio"));
  frames(2);
  REQUIRE(click_widget("open and run##bench", "Benchmark"));
}

void UiDriver::run_bench_and_sweep() {
  open_and_run_bench();
  settle_bench();
  REQUIRE(click_widget("run sweep##sweep", "Benchmark"));
  settle_bench();
}

void UiDriver::resize(int width, int height) {
  set_action("resize to " + std::to_string(width) + "x" + std::to_string(height));
  context_->resize(width, height);
  width_ = width;
  height_ = height;
  ++events_;
}

void UiDriver::move(ImVec2 p) {
  mouse_ = p;
  ++events_;
}
void UiDriver::button(int b, bool down) {
  down_[b] = down;
  ++events_;
}
void UiDriver::wheel(float steps) {
  wheel_ += steps;
  ++events_;
}
void UiDriver::key(int code, bool down) {
  keys_down_.erase(std::remove(keys_down_.begin(), keys_down_.end(), code), keys_down_.end());
  if (down) keys_down_.push_back(code);
  ++events_;
}
void UiDriver::chars(const std::u32string& text) {
  pending_chars_ += text;
  events_ += static_cast<int>(text.size());
}
void UiDriver::set_modifiers(bool ctrl, bool shift) {
  if (ctrl != ctrl_) ++events_;
  if (shift != shift_) ++events_;
  ctrl_ = ctrl;
  shift_ = shift;
}

void UiDriver::queue_key(int code, bool down) {
  studio_->input().key(code, down);
  ++events_;
}
void UiDriver::queue_tap(int code) {
  queue_key(code, true);
  queue_key(code, false);
}
void UiDriver::queue_chars(const std::u32string& text) {
  for (char32_t c : text) studio_->input().character(static_cast<unsigned int>(c));
  events_ += static_cast<int>(text.size());
}
int UiDriver::drain(int max_frames) {
  int n = 0;
  while (studio_->input().pending()) {
    if (n++ >= max_frames) FAIL("the input queue did not drain in " << max_frames << " frames");
    frame();
  }
  return n;
}

void UiDriver::click(ImVec2 p, int b) {
  move(p);
  frame();
  button(b, true);
  frame();
  button(b, false);
  frame();
}

void UiDriver::drag(ImVec2 from, ImVec2 to, int b, int steps) {
  move(from);
  frame();
  button(b, true);
  frame();
  for (int i = 1; i <= steps; ++i) {
    const float t = static_cast<float>(i) / steps;
    move(ImVec2(from.x + (to.x - from.x) * t, from.y + (to.y - from.y) * t));
    frame();
  }
  button(b, false);
  frame();
}

void UiDriver::press_key(int code, bool ctrl, bool shift) {
  set_modifiers(ctrl, shift);
  studio_->queue_key(code, ctrl, shift);  // as the window's GLFW key callback does
  key(code, true);
  frame();
  key(code, false);
  frame();
  set_modifiers(false, false);
}

void UiDriver::type(const std::u32string& text, bool enter, bool select_all) {
  if (select_all) press_key('A', true);
  chars(text);
  frame();
  if (enter) press_key(keys::Enter);
}

const std::vector<WidgetRecord>& UiDriver::widgets() const {
  return studio::ui::registry().items();
}

const WidgetRecord* UiDriver::find(const std::string& label, const std::string& window) const {
  for (const WidgetRecord& w : widgets())
    if (w.label == label && w.window.compare(0, window.size(), window) == 0) return &w;
  return nullptr;
}

const WidgetRecord* UiDriver::find_id(ImGuiID id) const {
  for (const WidgetRecord& w : widgets())
    if (w.id == id) return &w;
  return nullptr;
}

const WidgetRecord* UiDriver::find_param(const std::string& path) const {
  const std::string suffix = "###" + path;
  for (const WidgetRecord& w : widgets())
    if (w.label.size() >= suffix.size() &&
        w.label.compare(w.label.size() - suffix.size(), suffix.size(), suffix) == 0)
      return &w;
  return nullptr;
}

void UiDriver::open_all_nodes(const std::string& window) {
  std::set<ImGuiID> opened;
  for (bool more = true; more;) {
    more = false;
    std::vector<ImGuiID> nodes;
    for (const WidgetRecord& w : widgets())
      if (w.kind == WidgetKind::tree_node && w.window.rfind(window, 0) == 0 && !opened.count(w.id))
        nodes.push_back(w.id);
    for (ImGuiID id : nodes) {
      opened.insert(id);
      const std::size_t before = widgets().size();
      if (!click_id(id)) continue;
      idle();                           // the next click is not a double click
      if (widgets().size() < before) {  // it was open: closed now, open it again
        click_id(id);
        idle();
      }
      more = true;
    }
  }
}

std::vector<std::string> UiDriver::texts(const std::string& part, const std::string& window) const {
  std::vector<std::string> out;
  for (const WidgetRecord& w : widgets())
    if (w.kind == WidgetKind::text && w.window.rfind(window, 0) == 0 &&
        w.text.find(part) != std::string::npos)
      out.push_back(w.text);
  return out;
}

bool UiDriver::reveal(ImGuiID id) {
  for (int i = 0; i < 60; ++i) {
    const WidgetRecord* w = find_id(id);
    if (!w) return false;
    if (w->visible) return true;
    const ImVec2 c((w->clip_min.x + w->clip_max.x) * 0.5f, (w->clip_min.y + w->clip_max.y) * 0.5f);
    const float dir = centre(*w).y < c.y ? 1.0f : -1.0f;
    move(c);
    wheel(dir);
    frame();
  }
  return false;
}

bool UiDriver::click_widget(const std::string& label, const std::string& window) {
  const WidgetRecord* w = find(label, window);
  return w && click_id(w->id);
}

bool UiDriver::click_id(ImGuiID id) {
  if (!reveal(id)) return false;
  const WidgetRecord w = *find_id(id);
  set_action("click " + std::string(to_string(w.kind)) + " '" + w.label + "' in '" + w.window +
             "'");
  touch(w);
  const bool field = w.kind == WidgetKind::input_text || w.kind == WidgetKind::input_int;
  click(field ? frame_point(w, 0.05f) : centre(w));
  return true;
}

bool UiDriver::type_into_slider(ImGuiID id, const std::u32string& text) {
  if (!reveal(id)) return false;
  const WidgetRecord w = *find_id(id);
  set_action("ctrl+click slider '" + w.label + "', type '" + utf8(text) + "'");
  touch(w);
  set_modifiers(true, false);
  click(frame_point(w, 0.5f));
  set_modifiers(false, false);
  type(text);
  return true;
}

bool UiDriver::type_into(ImGuiID id, const std::u32string& text) {
  if (!reveal(id)) return false;
  const WidgetRecord w = *find_id(id);
  set_action("type '" + utf8(text) + "' into '" + w.label + "' in '" + w.window + "'");
  touch(w);
  click(frame_point(w, 0.05f));
  type(text);
  return true;
}

bool UiDriver::scene_rect(ImVec2& min, ImVec2& max) const {
  for (ImGuiWindow* w : GImGui->Windows)
    if (std::string(w->Name).find("###scene") != std::string::npos) {
      min = w->InnerRect.Min;
      max = w->InnerRect.Max;
      return max.x > min.x && max.y > min.y;
    }
  return false;
}

void UiDriver::check_invariants() {
  const auto fail = [this](const std::string& what) {
    FAIL(what << "\n  after: " << action_ << " (event " << events_ << ", frame " << frames_ << ")");
  };
  for (const auto& d : studio::ui::registry().duplicates()) fail(d.describe());
  const studio::AppState& s = studio_->state();
  using L = studio::ViewLimits;
  const auto in = [](float v, float lo, float hi) { return v >= lo && v <= hi; };
  if (!in(s.view.point_size, L::min_point_size, L::max_point_size))
    fail("point size out of range: " + std::to_string(s.view.point_size));
  if (!in(s.view.landmark_size, L::min_landmark_size, L::max_landmark_size))
    fail("landmark size out of range: " + std::to_string(s.view.landmark_size));
  if (!in(s.view.line_width, L::min_line_width, L::max_line_width))
    fail("line width out of range: " + std::to_string(s.view.line_width));
  if (!in(s.layout.left_width, L::min_left_width, L::max_left_width) ||
      !in(s.layout.scene_share, L::min_scene_share, L::max_scene_share))
    fail("layout out of range");
  const studio::Camera& c = s.camera;
  if (!c.target.allFinite() || !in(c.distance, 0.5f, 5000.0f) || !std::isfinite(c.yaw_deg) ||
      !in(c.pitch_deg, -89.9f, 89.9f))
    fail("camera out of range");
  if (s.data.source_frame < 0 || s.data.target_frame < 0 || s.data.source_frame > 999999 ||
      s.data.target_frame > 999999)
    fail("frame number out of range");
  if (s.pair_index < -1 || s.pair_index >= static_cast<int>(s.pairs.pairs.size()))
    fail("pair index out of range");
  if (!studio_->config_error().empty() && studio_->stale_reason().empty())
    fail("invalid parameters, but the results are not marked stale");
  if (!ImGui::IsAnyItemActive()) {
    // No edit in progress: the widgets must have left a valid configuration.
    try {
      validate(s.config, "parameters");
    } catch (const ConfigError& e) {
      fail(std::string("invalid configuration left by the widgets: ") + e.what());
    }
    const auto [lo, hi] = studio::epsilon_range(s.config.graph.trim);
    for (double e : s.config.graph.thresholds)
      if (!(e >= lo && e <= hi)) fail("epsilon outside its fixed range: " + std::to_string(e));
  }
}

}  // namespace pagor::test
