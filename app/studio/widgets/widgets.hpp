#pragma once
/// \file widgets.hpp
/// The studio's interactive widgets: thin wrappers over ImGui's that record every item drawn in a
/// frame (ID, label, window, kind, rectangle, tooltip) in a registry. The registry reports two
/// items of one frame that share an ImGui ID (ImGui 1.86 has no ID-conflict detection, and such a
/// pair aborts inside ImGui when clicked), and the driven-UI tests find every widget through it.
/// Panels call these, never ImGui's interactive widgets directly (a test checks the sources).

#include <imgui.h>

#include <string>
#include <vector>

struct ImGuiWindow;

namespace pagor::studio::ui {

enum class WidgetKind {
  button,
  checkbox,
  radio,
  slider,
  input_text,
  input_int,
  combo,
  selectable,
  tree_node,
  header,
  splitter,
  text  ///< not interactive: a line stating a figure (ui::figure), recorded so tests can read it
};
const char* to_string(WidgetKind kind);

/// One widget as drawn in one frame.
struct WidgetRecord {
  ImGuiID id = 0;
  std::string label;   ///< as passed to ImGui (with any ## suffix)
  std::string window;  ///< name of the ImGui window it is in
  WidgetKind kind = WidgetKind::button;
  ImVec2 min, max;            ///< screen rectangle [px]
  ImVec2 clip_min, clip_max;  ///< visible part of its window [px]
  bool visible = false;       ///< inside its window's visible part
  bool has_tooltip = false;   ///< a sentence explains it on hover
  /// text kind: the line as drawn; a path field: the part of the path it shows; a combo: its
  /// preview (the current choice)
  std::string text;
  bool enabled = true;   ///< false when drawn disabled
  bool warned = false;   ///< drawn as a warning (a path field naming no file)
  float lo = 0, hi = 0;  ///< slider / input range (0, 0 when none)
  float frame_w = 0;     ///< width of the frame (sliders, fields: without the label) [px]
};

/// Two widgets of one frame with the same ImGui ID.
struct DuplicateId {
  ImGuiID id = 0;
  std::string window, first, second;
  std::string describe() const;
};

/// Every widget of the current frame. One per process (the studio has one ImGui context).
class WidgetRegistry {
 public:
  /// Starts a frame: forgets the previous frame's widgets (kept as `last_frame()`).
  void begin_frame();
  /// Records the widget just drawn; `id` is the ID ImGui gave it, `window` the window it is in
  /// (default: the current one).
  WidgetRecord& add(WidgetKind kind, const char* label, ImGuiID id, ImVec2 min, ImVec2 max,
                    ImGuiWindow* window = nullptr);
  /// Marks the last widget as explained by a tooltip.
  void mark_last_explained() {
    if (!items_.empty()) items_.back().has_tooltip = true;
  }
  /// Widgets of the frame being built.
  const std::vector<WidgetRecord>& items() const { return items_; }
  /// Widgets of the last complete frame.
  const std::vector<WidgetRecord>& last_frame() const { return last_; }
  /// Duplicate IDs seen in the last complete frame (and so far in this one).
  const std::vector<DuplicateId>& duplicates() const { return duplicates_; }
  /// Every duplicate seen since the start (the studio prints each once).
  const std::vector<DuplicateId>& all_duplicates() const { return all_duplicates_; }

 private:
  std::vector<WidgetRecord> items_, last_;
  std::vector<DuplicateId> duplicates_, all_duplicates_;
};

WidgetRegistry& registry();

/// Shows `tip` as a tooltip while the last item is hovered and marks the last widget as explained.
void tooltip(const char* tip);
/// Shows `tip` while the last item (text, a table cell: no widget) is hovered, wrapped at 28 font
/// sizes as tooltip()'s are: a long line (an alternative's description) ran off the window.
void hover_tooltip(const std::string& tip);

// Wrappers: same meaning as ImGui's, plus registration. Ranges are always enforced (a value typed
// with Ctrl+click is clamped to [lo, hi]). A number typed into a slider's Ctrl+click field or a
// number field is applied once, when the field is left (Enter, Tab, a click elsewhere; Escape
// drops it), never at each keystroke; a slider dragged applies at once.
bool button(const char* label, ImVec2 size = ImVec2(0, 0), const char* tip = nullptr);
bool small_button(const char* label, const char* tip = nullptr);
bool arrow_button(const char* id, ImGuiDir dir, const char* tip = nullptr);
bool checkbox(const char* label, bool* v, const char* tip = nullptr);
bool radio(const char* label, int* v, int value, const char* tip = nullptr);
/// A radio button of an enum: selects `value` into `*v`.
template <class E>
bool radio(const char* label, E* v, E value, const char* tip = nullptr) {
  int i = static_cast<int>(*v);
  const bool r = radio(label, &i, static_cast<int>(value), tip);
  *v = static_cast<E>(i);
  return r;
}
bool slider_float(const char* label, float* v, float lo, float hi, const char* fmt,
                  bool log = false, const char* tip = nullptr);
bool slider_int(const char* label, int* v, int lo, int hi, bool log = false,
                const char* tip = nullptr);
/// A double edited through a float slider; the value written back is the float's shortest
/// decimal (0.3, not 0.30000001192092896).
bool slider_double(const char* label, double* v, double lo, double hi, const char* fmt,
                   bool log = false, const char* tip = nullptr);
bool input_text(const char* label, std::string* text, const char* tip = nullptr);
/// An integer field clamped to [lo, hi]; with `on_enter`, typing returns true only on Enter (the
/// +/- buttons at once).
bool input_int(const char* label, int* v, int lo, int hi, int step = 1, bool on_enter = false,
               const char* tip = nullptr);
bool begin_combo(const char* label, const char* preview, const char* tip = nullptr);
void end_combo();
bool selectable(const char* label, bool selected, ImGuiSelectableFlags flags = 0,
                ImVec2 size = ImVec2(0, 0));
bool tree_node(const char* id, const char* text);
void tree_pop();
bool header(const char* label, bool default_open);
/// A draggable bar of `size` at the cursor; returns the drag in pixels this frame (0 when idle).
ImVec2 splitter(const char* id, ImVec2 size, bool vertical);

/// printf into a std::string.
std::string format(const char* fmt, ...) IM_FMTARGS(1);

/// A line of text that states a figure (a verdict, an error, a rate, a margin): drawn like
/// ImGui::Text (in `color` unless its alpha is 0, wrapped at the window edge when `wrap`) and
/// recorded in the registry as a `text` item, so that the driven-UI tests read what the studio
/// says. Returns whether it is hovered.
bool figure(const std::string& text, ImVec4 color = ImVec4(0, 0, 0, 0), bool wrap = false);
/// The same, disabled-looking (grey).
bool figure_dim(const std::string& text);

/// A path field. While it is not being edited, a path too long for it shows its start and its end
/// (the file name) around "..."; editing shows and edits the whole path as input_text does.
/// `found` false (the caller looked: the path names nothing) draws it in the warning colour and
/// says so in the tooltip, so that a path spliced by a stray edit cannot pass for its old self.
bool input_path(const char* label, std::string* path, const char* tip = nullptr, bool found = true);
/// A number typed in a field, clamped to [lo, hi]; true when it changed (on Enter, or when the
/// field is left after an edit).
bool input_double(const char* label, double* v, double lo, double hi, const char* fmt = "%.6g",
                  const char* tip = nullptr);
/// A 64-bit integer typed in a field, clamped to [lo, hi]; true when it changed (as input_double).
bool input_int64(const char* label, long long* v, long long lo, long long hi,
                 const char* tip = nullptr);
/// A text field whose edit is applied when Enter is pressed or the field is left: `*text` changes
/// only then (returns true).
bool input_text_apply(const char* label, std::string* text, const char* tip = nullptr);

/// A combo over every value of an enum that `to_string` names (so values the core adds appear
/// without a change here). True when the value changed.
template <class E>
bool enum_combo(const char* label, E& value, const char* tip = nullptr) {
  bool changed = false;
  if (begin_combo(label, to_string(value), tip)) {
    for (int i = 0; i < 32; ++i) {
      const E o = static_cast<E>(i);
      const std::string name = to_string(o);
      if (name == "?") continue;
      if (selectable(name.c_str(), o == value)) {
        changed = o != value;
        value = o;
      }
    }
    end_combo();
  }
  return changed;
}

}  // namespace pagor::studio::ui
