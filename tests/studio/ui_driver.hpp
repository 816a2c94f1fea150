#pragma once
// Drives the real studio headless: an OSMesa context, the Studio, and mouse / keyboard input fed
// through ImGui's IO between frames (ImGui 1.86: MousePos, MouseDown, KeysDown, characters).
// After every frame it checks the invariants the UI promises (no duplicate IDs, values inside
// their ranges, a valid configuration whenever no edit is in progress) and fails the test with
// the last action when one breaks.

#include <imgui.h>

#include <functional>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "render/gl.hpp"
#include "render/headless.hpp"
#include "state/app_state.hpp"
#include "studio.hpp"
#include "widgets/widgets.hpp"

namespace pagor::test {

// Key codes the studio reads (GLFW's numbering).
namespace keys {
constexpr int Enter = 257, Escape = 256, Backspace = 259, Tab = 258, Left = 263, Right = 262,
              F1 = 290, Home = 268, End = 269, LeftShift = 340, LeftCtrl = 341;
}

/// The action being performed, printed when an assertion aborts the process.
void set_context(const std::string& what);
/// The centre of a widget's box.
ImVec2 centre(const studio::ui::WidgetRecord& w);
/// Where to click to focus a field or grab a slider: inside its frame (at `fraction` of its
/// width), not on its label.
ImVec2 frame_point(const studio::ui::WidgetRecord& w, float fraction);

class UiDriver {
 public:
  /// Opens `state` (its data is submitted) in a window of width x height.
  explicit UiDriver(studio::AppState state, int width = 1024, int height = 768);
  ~UiDriver();
  UiDriver(const UiDriver&) = delete;
  UiDriver& operator=(const UiDriver&) = delete;

  studio::Studio& studio() { return *studio_; }
  studio::AppState& state() { return studio_->state(); }

  // ---- frames ----
  void frame();
  void frames(int n);
  /// One frame after `seconds` of idle time (ImGui's clock moves on: a click after it is not a
  /// double click).
  void idle(float seconds = 0.35f);
  /// Frames until the worker has nothing pending (fails after `timeout_s`).
  void settle(double timeout_s = 240);
  /// Frames until the benchmark view's worker is idle and its sweep, if any, has ended.
  void settle_bench();
  /// From the main window: opens the benchmark view and starts its set (not waiting for it).
  void open_and_run_bench();
  /// From the main window: opens the benchmark view, runs its set, then its sweep, each settled.
  void run_bench_and_sweep();
  void resize(int width, int height);
  int width() const { return width_; }
  int height() const { return height_; }

  // ---- raw input (each counts as one event) ----
  void move(ImVec2 p);
  void button(int b, bool down);
  void wheel(float steps);
  void key(int code, bool down);
  void chars(const std::u32string& text);
  void set_modifiers(bool ctrl, bool shift);

  // ---- the window's keyboard path: the studio's input queue, as GLFW's callbacks fill it ----
  /// Queues a key press or release without drawing a frame (keys faster than frames).
  void queue_key(int code, bool down);
  /// Queues a key's press and release.
  void queue_tap(int code);
  /// Queues typed characters without drawing a frame.
  void queue_chars(const std::u32string& text);
  /// Draws frames until the queue is empty; returns how many (fails beyond `max_frames`).
  int drain(int max_frames = 200);

  // ---- gestures (events plus the frames they need) ----
  void click(ImVec2 p, int b = 0);
  void drag(ImVec2 from, ImVec2 to, int b = 0, int steps = 3);
  void press_key(int code, bool ctrl = false, bool shift = false);
  void type(const std::u32string& text, bool enter = true, bool select_all = true);

  // ---- widgets ----
  /// Widgets of the last frame.
  const std::vector<studio::ui::WidgetRecord>& widgets() const;
  /// The widget of the last frame with this label (and window prefix); null when absent.
  const studio::ui::WidgetRecord* find(const std::string& label,
                                       const std::string& window = "") const;
  const studio::ui::WidgetRecord* find_id(ImGuiID id) const;
  /// The parameter editor's widget of the configuration key path `path` (its label ends with
  /// "###path"); null when absent (its section closed).
  const studio::ui::WidgetRecord* find_param(const std::string& path) const;
  /// Opens every tree node and header of the window (prefix) until no new one appears.
  void open_all_nodes(const std::string& window = "Pagor Studio");
  /// The text lines (ui::figure) of the last frame that contain `part`, in the window (prefix).
  std::vector<std::string> texts(const std::string& part, const std::string& window = "") const;
  /// Scrolls the widget's window until the widget is visible; false when it cannot be.
  bool reveal(ImGuiID id);
  /// Clicks the centre of a widget (after revealing it). False when it is not there.
  bool click_widget(const std::string& label, const std::string& window = "");
  bool click_id(ImGuiID id);
  /// Ctrl+click on a slider, then types `text` and Enter.
  bool type_into_slider(ImGuiID id, const std::u32string& text);
  /// Clicks a text or integer field, selects all, types `text`, presses Enter.
  bool type_into(ImGuiID id, const std::u32string& text);
  /// The screen rectangle of the 3D view.
  bool scene_rect(ImVec2& min, ImVec2& max) const;

  int events() const { return events_; }
  int frame_count() const { return frames_; }
  /// Distinct widgets acted on (by window and label).
  const std::set<std::string>& touched() const { return touched_; }
  void touch(const studio::ui::WidgetRecord& w) { touched_.insert(w.window + "/" + w.label); }
  /// Most widgets seen in one frame.
  std::size_t max_widgets() const { return max_widgets_; }
  /// Last action, for failure messages.
  const std::string& action() const { return action_; }
  void set_action(const std::string& a);

 private:
  void check_invariants();

  std::unique_ptr<studio::HeadlessContext> context_;
  studio::Gl gl_;
  ImGuiContext* imgui_ = nullptr;
  std::unique_ptr<studio::Studio> studio_;
  int width_, height_;
  ImVec2 mouse_{-1, -1};
  bool down_[5] = {false, false, false, false, false};
  bool ctrl_ = false, shift_ = false;
  float wheel_ = 0;
  float idle_ = 0;  // the next frame's time step when set [s]
  std::vector<int> keys_down_;
  std::u32string pending_chars_;
  int events_ = 0, frames_ = 0;
  std::size_t max_widgets_ = 0;
  std::set<std::string> touched_;
  std::string action_ = "start";
};

/// Acts on every widget the studio shows, in the windows given, repeatedly until no new widget
/// appears: clicks buttons, boxes, radios, headers, tree nodes and rows; drags every slider across
/// its range and types out-of-range and non-numeric values into it; types valid and invalid text
/// into fields; opens every combo and picks each choice; drags the splitters. `keep` runs after
/// each action (e.g. to go back to the data mode under test); `window` limits the walk to the
/// windows whose name starts with it. Returns the widgets acted on.
int exercise_every_widget(UiDriver& d, const std::function<void()>& keep, int max_actions = 600,
                          const std::string& window = "",
                          const std::function<bool(const studio::ui::WidgetRecord&)>& skip = {});

/// Skips the parameter editor's generated sections (walked in full in one mode only: they are
/// the same in every mode, and a walk through them takes minutes).
bool skip_parameter_sections(const studio::ui::WidgetRecord& w);

}  // namespace pagor::test
