#include "widgets/widgets.hpp"

#include "widgets/widget_record.hpp"

#include "widgets/number_format.hpp"

#include <imgui_internal.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <unordered_map>

namespace pagor::studio::ui {

WidgetRecord& record_last(WidgetKind kind, const char* label, ImGuiID id, float frame_w) {
  WidgetRecord& r =
      registry().add(kind, label, id, ImGui::GetItemRectMin(), ImGui::GetItemRectMax());
  r.frame_w = frame_w >= 0 ? frame_w : r.max.x - r.min.x;
  return r;
}

namespace {

void maybe_tip(const char* tip) {
  if (tip) tooltip(tip);
}

// Records the last item as a number widget over [lo, hi] (what the driven tests read), with its
// tooltip.
void record_ranged(WidgetKind kind, const char* label, ImGuiID id, float frame_w, double lo,
                   double hi, const char* tip) {
  WidgetRecord& rec = record_last(kind, label, id, frame_w);
  rec.lo = static_cast<float>(lo);
  rec.hi = static_cast<float>(hi);
  maybe_tip(tip);
}

// A number typed into a widget's text field is applied when the field is left (Enter, Tab, a
// click elsewhere), not at every keystroke: typing "0.35" must not apply 0, 0.3 and 0.35 in turn
// (three runs, and a comparison with a run of a value nobody meant). While the field is active
// ImGui edits its own text and parses it into the copy handed to it each frame; that value waits
// here. Escape restores the text it started from, so the copy comes back unchanged.
template <class T>
class TypedValues {
 public:
  /// The value to hand to the widget this frame: the one being typed, else `v`.
  T start(ImGuiID id, T v) {
    const auto it = held_.find(id);
    if (it == held_.end()) return v;
    // Not drawn last frame (its panel closed while typing): the edit is gone with the field.
    if (it->second.frame < ImGui::GetFrameCount() - 1) {
      held_.erase(it);
      return v;
    }
    return it->second.value;
  }
  /// After the widget: while `typing`, holds `value` and returns false; else true (apply it).
  bool finish(ImGuiID id, bool typing, T value) {
    if (typing) {
      held_[id] = Held{value, ImGui::GetFrameCount()};
      return false;
    }
    held_.erase(id);
    return true;
  }

 private:
  struct Held {
    T value;
    int frame;
  };
  std::unordered_map<ImGuiID, Held> held_;
};

template <class T>
TypedValues<T>& typed_values() {
  static TypedValues<T> values;
  return values;
}

// Whether the text field of the number widget `id` is being typed into: a slider's Ctrl+click
// field, or an input field (whose text field has the widget's own ID).
bool slider_typing(ImGuiID id) {
  return ImGui::TempInputIsActive(id);
}
bool field_typing(ImGuiID id) {
  return ImGui::GetActiveID() == id;
}

}  // namespace

const char* to_string(WidgetKind kind) {
  static constexpr const char* kNames[] = {"button",     "checkbox",  "radio",    "slider",
                                           "input_text", "input_int", "combo",    "selectable",
                                           "tree_node",  "header",    "splitter", "text"};
  static_assert(std::size(kNames) == static_cast<std::size_t>(WidgetKind::text) + 1,
                "a name for every WidgetKind");
  const auto i = static_cast<std::size_t>(kind);
  return i < std::size(kNames) ? kNames[i] : "?";
}

std::string DuplicateId::describe() const {
  return "duplicate ImGui ID in window '" + window + "': '" + first + "' and '" + second +
         "' (give one a unique label, a ## suffix or a PushID scope)";
}

WidgetRegistry& registry() {
  static WidgetRegistry r;
  return r;
}

void WidgetRegistry::begin_frame() {
  last_.swap(items_);
  items_.clear();
  duplicates_.clear();
}

WidgetRecord& WidgetRegistry::add(WidgetKind kind, const char* label, ImGuiID id, ImVec2 min,
                                  ImVec2 max, ImGuiWindow* window) {
  if (!window) window = ImGui::GetCurrentWindow();
  for (const WidgetRecord& r : items_)
    if (r.id == id && kind != WidgetKind::text && r.kind != WidgetKind::text) {
      DuplicateId d{id, window->Name, r.label, label};
      duplicates_.push_back(d);
      const bool known = std::any_of(all_duplicates_.begin(), all_duplicates_.end(),
                                     [&](const DuplicateId& o) { return o.id == id; });
      if (!known) all_duplicates_.push_back(d);
      break;
    }
  WidgetRecord r;
  r.id = id;
  r.label = label;
  r.window = window->Name;
  r.kind = kind;
  r.min = min;
  r.max = max;
  r.clip_min = window->ClipRect.Min;
  r.clip_max = window->ClipRect.Max;
  // Visible when the centre is inside the window's clip rectangle and the item is not tiny.
  const ImVec2 c((min.x + max.x) * 0.5f, (min.y + max.y) * 0.5f);
  r.visible = c.x > r.clip_min.x && c.x < r.clip_max.x && c.y > r.clip_min.y &&
              c.y < r.clip_max.y && max.x - min.x >= 2 && max.y - min.y >= 2;
  r.enabled = (GImGui->CurrentItemFlags & ImGuiItemFlags_Disabled) == 0;
  items_.push_back(std::move(r));
  return items_.back();
}

namespace {

void show_tooltip(const char* tip) {
  // A disabled item explains itself too: why it is disabled is what the user asks then.
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
    // Opaque and legible also over a disabled item or a dimmed (stale) panel.
    ImGui::PushStyleVar(ImGuiStyleVar_Alpha, 1.0f);
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 28.0f);
    ImGui::TextUnformatted(tip);
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
    ImGui::PopStyleVar();
  }
}

}  // namespace

void tooltip(const char* tip) {
  registry().mark_last_explained();
  show_tooltip(tip);
}

void hover_tooltip(const std::string& tip) {
  show_tooltip(tip.c_str());
}

bool button(const char* label, ImVec2 size, const char* tip) {
  const ImGuiID id = ImGui::GetID(label);
  const bool r = ImGui::Button(label, size);
  record_last(WidgetKind::button, label, id);
  maybe_tip(tip);
  return r;
}

bool small_button(const char* label, const char* tip) {
  const ImGuiID id = ImGui::GetID(label);
  const bool r = ImGui::SmallButton(label);
  record_last(WidgetKind::button, label, id);
  maybe_tip(tip);
  return r;
}

bool arrow_button(const char* label, ImGuiDir dir, const char* tip) {
  const ImGuiID id = ImGui::GetID(label);
  const bool r = ImGui::ArrowButton(label, dir);
  record_last(WidgetKind::button, label, id);
  maybe_tip(tip);
  return r;
}

bool checkbox(const char* label, bool* v, const char* tip) {
  const ImGuiID id = ImGui::GetID(label);
  const bool r = ImGui::Checkbox(label, v);
  record_last(WidgetKind::checkbox, label, id);
  maybe_tip(tip);
  return r;
}

bool radio(const char* label, int* v, int value, const char* tip) {
  const ImGuiID id = ImGui::GetID(label);
  const bool r = ImGui::RadioButton(label, v, value);
  record_last(WidgetKind::radio, label, id);
  maybe_tip(tip);
  return r;
}

bool slider_float(const char* label, float* v, float lo, float hi, const char* fmt, bool log,
                  const char* tip) {
  const ImGuiID id = ImGui::GetID(label);
  const ImGuiSliderFlags flags =
      ImGuiSliderFlags_AlwaysClamp | (log ? ImGuiSliderFlags_Logarithmic : 0);
  const float frame_w = ImGui::CalcItemWidth();
  // A drag applies at once; a typed value when its field is left.
  float value = typed_values<float>().start(id, *v);
  ImGui::SliderFloat(label, &value, lo, hi, fmt, flags);
  bool r = false;
  if (typed_values<float>().finish(id, slider_typing(id), value)) {
    if (!(value >= lo && value <= hi))  // NaN typed, or a value past the range
      value = std::isnan(value) ? lo : std::clamp(value, lo, hi);
    r = value != *v;
    *v = value;
  }
  record_ranged(WidgetKind::slider, label, id, frame_w, lo, hi, tip);
  return r;
}

bool slider_int(const char* label, int* v, int lo, int hi, bool log, const char* tip) {
  const ImGuiID id = ImGui::GetID(label);
  const ImGuiSliderFlags flags =
      ImGuiSliderFlags_AlwaysClamp | (log ? ImGuiSliderFlags_Logarithmic : 0);
  const float frame_w = ImGui::CalcItemWidth();
  int value = typed_values<int>().start(id, *v);
  ImGui::SliderInt(label, &value, lo, hi, "%d", flags);
  bool r = false;
  if (typed_values<int>().finish(id, slider_typing(id), value)) {
    value = std::clamp(value, lo, hi);
    r = value != *v;
    *v = value;
  }
  record_ranged(WidgetKind::slider, label, id, frame_w, lo, hi, tip);
  return r;
}

bool slider_double(const char* label, double* v, double lo, double hi, const char* fmt, bool log,
                   const char* tip) {
  float f = static_cast<float>(std::clamp(*v, lo, hi));
  const bool changed =
      slider_float(label, &f, static_cast<float>(lo), static_cast<float>(hi), fmt, log, tip);
  if (changed) *v = std::clamp(shortest(f), lo, hi);
  return changed;
}

bool input_text(const char* label, std::string* text, const char* tip) {
  const ImGuiID id = ImGui::GetID(label);
  const float frame_w = ImGui::CalcItemWidth();
  const bool r = ImGui::InputText(label, text);
  record_last(WidgetKind::input_text, label, id, frame_w);
  maybe_tip(tip);
  return r;
}

bool input_int(const char* label, int* v, int lo, int hi, int step, bool on_enter,
               const char* tip) {
  const ImGuiID id = ImGui::GetID(label);
  const float frame_w = ImGui::CalcItemWidth();
  // With `on_enter` ImGui parses the text on Enter only (a click elsewhere drops the edit);
  // without, a typed value waits until the field is left. The +/- buttons apply at once.
  int value = on_enter ? *v : typed_values<int>().start(id, *v);
  const bool r = ImGui::InputInt(label, &value, step, step * 10,
                                 on_enter ? ImGuiInputTextFlags_EnterReturnsTrue : 0);
  const bool apply = on_enter || typed_values<int>().finish(id, field_typing(id), value);
  // Written back only when the user edited it: a value loaded from a file is not changed silently.
  bool changed = false;
  if (apply && (r || value != *v)) {
    const int clamped = std::clamp(value, lo, hi);
    changed = clamped != *v;
    *v = clamped;
  }
  record_ranged(WidgetKind::input_int, label, id, frame_w, lo, hi, tip);
  return changed;
}

bool begin_combo(const char* label, const char* preview, const char* tip) {
  const ImGuiID id = ImGui::GetID(label);
  const ImVec2 at = ImGui::GetCursorScreenPos();
  const ImVec2 to(at.x + ImGui::CalcItemWidth(), at.y + ImGui::GetFrameHeight());
  ImGuiWindow* window = ImGui::GetCurrentWindow();
  const bool open = ImGui::BeginCombo(label, preview);
  // While open, the popup is the current window: record against the combo's own window.
  WidgetRecord& rec = registry().add(WidgetKind::combo, label, id, at, to, window);
  rec.frame_w = to.x - at.x;
  rec.text = preview ? preview : "";
  if (!open)
    maybe_tip(tip);
  else if (tip)
    registry().mark_last_explained();
  return open;
}

void end_combo() {
  ImGui::EndCombo();
}

bool selectable(const char* label, bool selected, ImGuiSelectableFlags flags, ImVec2 size) {
  const ImGuiID id = ImGui::GetID(label);
  const bool r = ImGui::Selectable(label, selected, flags, size);
  record_last(WidgetKind::selectable, label, id);
  return r;
}

bool tree_node(const char* label, const char* text) {
  const ImGuiID id = ImGui::GetID(label);
  const bool open = ImGui::TreeNode(label, "%s", text);
  record_last(WidgetKind::tree_node, label, id);
  return open;
}

void tree_pop() {
  ImGui::TreePop();
}

bool header(const char* label, bool default_open) {
  const ImGuiID id = ImGui::GetID(label);
  const bool open =
      ImGui::CollapsingHeader(label, default_open ? ImGuiTreeNodeFlags_DefaultOpen : 0);
  record_last(WidgetKind::header, label, id);
  return open;
}

ImVec2 splitter(const char* label, ImVec2 size, bool vertical) {
  const ImGuiID id = ImGui::GetID(label);
  ImGui::InvisibleButton(label, size);
  record_last(WidgetKind::splitter, label, id);
  const bool active = ImGui::IsItemActive();
  if (active || ImGui::IsItemHovered())
    ImGui::SetMouseCursor(vertical ? ImGuiMouseCursor_ResizeEW : ImGuiMouseCursor_ResizeNS);
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->AddRectFilled(ImGui::GetItemRectMin(), ImGui::GetItemRectMax(),
                    active ? IM_COL32(110, 140, 200, 255) : IM_COL32(55, 60, 70, 255));
  return active ? ImGui::GetIO().MouseDelta : ImVec2(0, 0);
}

std::string format(const char* fmt, ...) {
  va_list args;
  va_start(args, fmt);
  char buf[1024];
  std::vsnprintf(buf, sizeof(buf), fmt, args);
  va_end(args);
  return buf;
}

bool figure(const std::string& text, ImVec4 color, bool wrap) {
  if (wrap) ImGui::PushTextWrapPos(0.0f);
  if (color.w > 0) ImGui::PushStyleColor(ImGuiCol_Text, color);
  ImGui::TextUnformatted(text.c_str());
  if (color.w > 0) ImGui::PopStyleColor();
  if (wrap) ImGui::PopTextWrapPos();
  WidgetRecord& r = record_last(WidgetKind::text, "##figure", 0);
  r.text = text;
  return ImGui::IsItemHovered();
}

bool figure_dim(const std::string& text) {
  return figure(text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
}

bool input_double(const char* label, double* v, double lo, double hi, const char* fmt,
                  const char* tip) {
  const ImGuiID id = ImGui::GetID(label);
  const float frame_w = ImGui::CalcItemWidth();
  double value = typed_values<double>().start(id, *v);
  ImGui::InputDouble(label, &value, 0.0, 0.0, fmt);
  bool changed = false;
  if (typed_values<double>().finish(id, field_typing(id), value) && value != *v &&
      !(std::isnan(value) && std::isnan(*v))) {
    const double clamped = std::isnan(value) ? lo : std::clamp(value, lo, hi);
    changed = clamped != *v;
    *v = clamped;
  }
  record_ranged(WidgetKind::input_int, label, id, frame_w, lo, hi, tip);
  return changed;
}

bool input_int64(const char* label, long long* v, long long lo, long long hi, const char* tip) {
  const ImGuiID id = ImGui::GetID(label);
  const float frame_w = ImGui::CalcItemWidth();
  long long value = typed_values<long long>().start(id, *v);
  ImGui::InputScalar(label, ImGuiDataType_S64, &value, nullptr, nullptr, "%lld");
  bool changed = false;
  if (typed_values<long long>().finish(id, field_typing(id), value) && value != *v) {
    const long long clamped = std::clamp(value, lo, hi);
    changed = clamped != *v;
    *v = clamped;
  }
  record_ranged(WidgetKind::input_int, label, id, frame_w, lo, hi, tip);
  return changed;
}

bool input_text_apply(const char* label, std::string* text, const char* tip) {
  const ImGuiID id = ImGui::GetID(label);
  const float frame_w = ImGui::CalcItemWidth();
  // While the field is active ImGui edits its own copy; this one receives it on Enter or when the
  // field is left after an edit.
  std::string edited = *text;
  const bool enter = ImGui::InputText(label, &edited, ImGuiInputTextFlags_EnterReturnsTrue);
  const bool changed = (enter || ImGui::IsItemDeactivatedAfterEdit()) && edited != *text;
  if (changed) *text = edited;
  record_last(WidgetKind::input_text, label, id, frame_w);
  maybe_tip(tip);
  return changed;
}

}  // namespace pagor::studio::ui
