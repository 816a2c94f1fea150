#include "panels/param_editor.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cctype>
#include <optional>
#include <sstream>
#include <nlohmann/json.hpp>

#include "pagor/errors.hpp"
#include "pagor/graph/trim.hpp"
#include "widgets/widgets.hpp"

namespace pagor::studio {
namespace {

using json = nlohmann::json;

const ImVec4 kModified(1.0f, 0.78f, 0.3f, 1.0f);
// A linear slider spans at most this many units; a wider range is typed (a click on a slider
// over (0, 1000] m would set a noise bound of hundreds of metres).
constexpr double kSliderSpan = 100.0;
const char* const kReset = "\xe2\x86\xba";  // an anticlockwise arrow

// "landmarks.classes[2].voxel_size" -> the JSON pointer "/landmarks/classes/2/voxel_size".
json::json_pointer pointer_of(const std::string& path) {
  std::string p = "/";
  for (char c : path) p += c == '.' || c == '[' ? '/' : c == ']' ? '\0' : c;
  p.erase(std::remove(p.begin(), p.end(), '\0'), p.end());
  return json::json_pointer(p);
}

std::string last_key(const std::string& path) {
  const auto dot = path.find_last_of('.');
  return dot == std::string::npos ? path : path.substr(dot + 1);
}

// The path of the same parameter in `reference`: a class entry is matched by its name.
std::string reference_path(const std::string& path, const Config& config, const Config& reference) {
  const std::string prefix = "landmarks.classes[";
  if (path.rfind(prefix, 0) != 0) return path;
  const auto close = path.find(']');
  const std::size_t i = std::stoul(path.substr(prefix.size(), close - prefix.size()));
  if (i >= config.landmarks.classes.size()) return {};
  const std::string& name = config.landmarks.classes[i].name;
  for (std::size_t j = 0; j < reference.landmarks.classes.size(); ++j)
    if (reference.landmarks.classes[j].name == name)
      return prefix + std::to_string(j) + path.substr(close);
  return {};
}

// What the editor draws from: both configurations as JSON, read by pointer.
struct Values {
  const Config& config;
  const Config& reference;
  json now, ref;
  const json* at(const json& j, const std::string& path) const {
    const auto p = pointer_of(path);
    return !path.empty() && j.contains(p) ? &j.at(p) : nullptr;
  }
  const json* current(const std::string& path) const { return at(now, path); }
  const json* preset(const std::string& path) const {
    return at(ref, reference_path(path, config, reference));
  }
};

// Sets one value; a refusal (a cross-field rule) is said, and the configuration kept.
bool set_json(Config& c, const std::string& path, const std::string& value,
              StudioActions& actions) {
  try {
    set_field_json(c, path, value);
    return true;
  } catch (const ConfigError& e) {
    actions.notify(Message::error(e.what()));
    return false;
  }
}

bool number_field(Config& c, const ConfigField& f, const Values& v, const std::string& label,
                  const std::string& tip, StudioActions& actions) {
  const json* now = v.current(f.path);
  if (!now || !now->is_number()) return false;
  double value = now->get<double>();
  const bool off = !std::isnan(f.info.off) && value == f.info.off;
  const NumberWidget w = number_widget(f);
  bool changed = false;
  double edited = off ? w.lo : value;
  ImGui::BeginDisabled(off);
  if (w.kind == NumberWidget::log_slider || w.kind == NumberWidget::slider)
    changed = ui::slider_double(label.c_str(), &edited, w.lo, w.hi, w.integer ? "%.0f" : "%.4g",
                                w.kind == NumberWidget::log_slider, tip.c_str());
  else if (w.integer) {
    long long i = static_cast<long long>(std::llround(edited));
    changed = ui::input_int64(label.c_str(), &i, static_cast<long long>(std::ceil(w.lo)),
                              static_cast<long long>(std::floor(w.hi)), tip.c_str());
    edited = static_cast<double>(i);
  } else {
    changed = ui::input_double(label.c_str(), &edited, w.lo, w.hi, "%.6g", tip.c_str());
  }
  ImGui::EndDisabled();
  if (!std::isnan(f.info.off)) {  // the value that switches the field off, outside its range
    ImGui::SameLine();
    bool is_off = off;
    if (ui::checkbox(
            "off", &is_off,
            ("Switch it off: " + number_text(f.info.off) + " (" + f.info.doc + ")").c_str())) {
      const json* p = v.preset(f.path);
      const double on =
          p && p->is_number() && p->get<double>() != f.info.off ? p->get<double>() : w.lo;
      edited = is_off ? f.info.off : on;
      changed = true;
    }
  }
  if (!changed || edited == value) return false;
  if (w.integer) edited = std::round(edited);
  try {
    set_field_number(c, f.path, edited);
    return true;
  } catch (const ConfigError& e) {
    actions.notify(Message::error(e.what()));
    return false;
  }
}

bool choice_field(Config& c, const ConfigField& f, const Values& v, const std::string& label,
                  const std::string& tip, StudioActions& actions) {
  const json* now = v.current(f.path);
  const std::string name = now && now->is_string() ? now->get<std::string>() : "?";
  bool changed = false;
  if (ui::begin_combo(label.c_str(), name.c_str(), tip.c_str())) {
    for (const std::string& choice : f.choices)
      if (ui::selectable(choice.c_str(), choice == name) && choice != name)
        changed = set_json(c, f.path, json(choice).dump(), actions);
    ui::end_combo();
  }
  return changed;
}

// A class name: one of the label scheme's classes no other entry uses.
bool class_name_field(Config& c, const ConfigField& f, const std::string& name,
                      const std::string& label, const std::string& tip, StudioActions& actions) {
  // The choice is applied after the listing: setting it replaces the configuration, classes and
  // all, which the loop walks.
  std::optional<std::string> chosen;
  if (ui::begin_combo(label.c_str(), name.c_str(), tip.c_str())) {
    for (const SemanticClass& k : c.label_scheme.classes) {
      const bool used = std::any_of(c.landmarks.classes.begin(), c.landmarks.classes.end(),
                                    [&](const ClassParams& p) { return p.name == k.name; });
      if ((!used || k.name == name) && ui::selectable(k.name.c_str(), k.name == name) &&
          k.name != name)
        chosen = k.name;
    }
    ui::end_combo();
  }
  return chosen && set_json(c, f.path, json(*chosen).dump(), actions);
}

// Text and lists edited as JSON (applied on Enter).
bool json_field(Config& c, const ConfigField& f, const Values& v, const std::string& label,
                const std::string& tip, StudioActions& actions) {
  const json* now = v.current(f.path);
  if (!now) return false;
  const bool text = now->is_string();
  std::string shown = text ? now->get<std::string>() : now->dump();
  if (!ui::input_text_apply(label.c_str(), &shown, tip.c_str())) return false;
  if (text) return set_json(c, f.path, json(shown).dump(), actions);
  if (!json::accept(shown)) {
    actions.notify(Message::error(f.path + ": not JSON: " + shown));
    return false;
  }
  return set_json(c, f.path, shown, actions);
}

// One field's row: mark, widget, reset. `whole_path`: labelled by its whole key path (a search's
// flat list, where "voxel_size" of two classes would otherwise look the same).
bool field_row(Config& c, const ConfigField& f, const Values& v, StudioActions& actions,
               bool whole_path = false) {
  const json* now = v.current(f.path);
  const json* preset = v.preset(f.path);
  const bool modified = now && preset && *now != *preset;
  std::string shown = field_label(f, c.graph.trim);
  if (whole_path) shown = f.path + shown.substr(last_key(f.path).size());  // the unit kept
  const std::string label = (modified ? "* " : "") + shown + "###" + f.path;
  const std::string tip =
      field_tooltip(f, c.graph.trim) +
      (preset ? "\npreset: " + preset->dump() : std::string("\n(not in the preset)"));
  ImGui::PushID(f.path.c_str());
  if (modified) ImGui::PushStyleColor(ImGuiCol_Text, kModified);
  const float reset_w = ImGui::GetFrameHeight() + 4;
  ImGui::PushItemWidth(ImGui::CalcItemWidth() - reset_w -
                       (std::isnan(f.info.off) ? 0.0f : ImGui::GetFrameHeight() + 40));
  bool changed = false;
  switch (f.kind) {
    case FieldKind::number:
    case FieldKind::integer:
      changed = number_field(c, f, v, label, tip, actions);
      break;
    case FieldKind::flag: {
      bool b = now && now->is_boolean() && now->get<bool>();
      if (ui::checkbox(label.c_str(), &b, tip.c_str()))
        changed = set_json(c, f.path, b ? "true" : "false", actions);
      break;
    }
    case FieldKind::choice:
      changed = choice_field(c, f, v, label, tip, actions);
      break;
    case FieldKind::text:
      changed =
          f.path.rfind("landmarks.classes[", 0) == 0 && last_key(f.path) == "name"
              ? class_name_field(c, f, now ? now->get<std::string>() : "", label, tip, actions)
              : json_field(c, f, v, label, tip, actions);
      break;
    case FieldKind::numbers:
    case FieldKind::other:
      changed = json_field(c, f, v, label, tip, actions);
      break;
  }
  ImGui::PopItemWidth();
  if (modified) ImGui::PopStyleColor();
  ImGui::SameLine(0, 4);
  ImGui::BeginDisabled(!modified);
  if (ui::small_button(kReset, "Back to the preset's value.") && preset)
    changed |= set_json(c, f.path, preset->dump(), actions);
  ImGui::EndDisabled();
  ImGui::PopID();
  return changed;
}

}  // namespace

NumberWidget number_widget(const ConfigField& f) {
  NumberWidget w;
  w.integer = f.kind == FieldKind::integer;
  const Range& r = f.info.range;
  double lo = std::isfinite(r.min) ? r.min : -1e12, hi = std::isfinite(r.max) ? r.max : 1e12;
  if (f.info.log_scale && lo <= 0) lo = hi * 1e-12;  // a log scale needs a positive start
  if (r.min_open && lo == r.min) lo += w.integer ? 1.0 : std::max(1e-9, (hi - lo) * 1e-6);
  if (r.max_open) hi -= w.integer ? 1.0 : std::max(1e-9, (hi - lo) * 1e-6);
  w.lo = lo;
  w.hi = hi;
  w.kind = f.info.log_scale ? NumberWidget::log_slider
           : (std::isfinite(r.min) && std::isfinite(r.max) && hi - lo <= kSliderSpan)
               ? NumberWidget::slider
               : NumberWidget::typed;
  return w;
}

std::string field_label(const ConfigField& f, TrimKind trim) {
  const std::string unit = f.info.unit;
  const std::string shown = unit == "trim" ? trim_unit(trim) : unit;
  return last_key(f.path) + (shown.empty() ? "" : " [" + shown + "]");
}

std::string field_tooltip(const ConfigField& f, TrimKind trim) {
  std::string t = f.info.doc;
  if (f.kind == FieldKind::number || f.kind == FieldKind::integer || f.kind == FieldKind::numbers) {
    const std::string unit = std::string(f.info.unit) == "trim" ? trim_unit(trim) : f.info.unit;
    t += "\nrange " + f.info.range.text() + (unit.empty() ? "" : " " + unit);
    if (!std::isnan(f.info.off)) t += ", or " + number_text(f.info.off) + " (off)";
    if (f.info.log_scale) t += "; log scale";
  }
  if (f.kind == FieldKind::choice) {
    t += "\none of:";
    for (const std::string& c : f.choices) t += " " + c;
  }
  return t + "\nkey: " + f.path;
}

namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string section_of(const std::string& path) {
  return path.substr(0, path.find_first_of(".["));
}

// The class entries: one tree node each with its fields and a remove button, then "add".
bool class_entries(Config& c, const std::vector<ConfigField>& fields, const Values& v,
                   StudioActions& actions, bool& moved) {
  bool changed = false;
  for (std::size_t i = 0; i < c.landmarks.classes.size(); ++i) {
    const std::string prefix = "landmarks.classes[" + std::to_string(i) + "].";
    const ClassParams& p = c.landmarks.classes[i];
    ImGui::PushID(static_cast<int>(i));
    const std::string text = "class " + p.name + " (" + to_string(p.method) + ")";
    const bool open = ui::tree_node("##class", text.c_str());
    ImGui::SameLine();
    ImGui::BeginDisabled(c.landmarks.classes.size() <= 1);
    const bool remove = ui::small_button("remove", "Stop making landmarks of this class.");
    ImGui::EndDisabled();
    if (open) {
      for (const ConfigField& f : fields)
        if (f.path.rfind(prefix, 0) == 0) changed |= field_row(c, f, v, actions);
      ui::tree_pop();
    }
    ImGui::PopID();
    if (remove) {
      Config next = c;
      next.landmarks.classes.erase(next.landmarks.classes.begin() + static_cast<std::ptrdiff_t>(i));
      try {
        validate(next, "parameters");
        c = std::move(next);
        moved = true;  // the paths below moved
        return true;
      } catch (const ConfigError& e) {
        actions.notify(Message::error(e.what()));
      }
    }
  }
  if (ui::begin_combo("add class", "a class of the label scheme...",
                      "Make landmarks of one more class of the label scheme (clusters; its "
                      "parameters start from the preset's entry of that name, if any).")) {
    for (const SemanticClass& k : c.label_scheme.classes) {
      const bool used = std::any_of(c.landmarks.classes.begin(), c.landmarks.classes.end(),
                                    [&](const ClassParams& p) { return p.name == k.name; });
      if (used || !ui::selectable(k.name.c_str(), false)) continue;
      ClassParams added;
      for (const ClassParams& r : v.reference.landmarks.classes)
        if (r.name == k.name) added = r;
      added.name = k.name;
      c.landmarks.classes.push_back(added);
      changed = moved = true;
    }
    ui::end_combo();
  }
  return changed;
}

}  // namespace

bool field_matches(const ConfigField& f, const std::string& query) {
  const std::string text = lower(f.path + " " + f.info.doc);
  std::istringstream words(lower(query));
  for (std::string w; words >> w;)
    if (text.find(w) == std::string::npos) return false;
  return true;
}

bool parameter_sections(Config& config, const Config& reference, const std::string& search,
                        StudioActions& actions) {
  const std::vector<ConfigField> fields = config_fields(config);
  const Values v{config, reference, json::parse(config_to_json(config, -1)),
                 json::parse(config_to_json(reference, -1))};
  bool changed = false, moved = false;  // moved: a class was added or removed
  if (search.find_first_not_of(" \t") != std::string::npos) {
    // One list of the fields that match, whatever their section (the pyramid's TRIM and
    // thresholds are drawn above).
    std::size_t shown = 0, total = 0;
    for (const ConfigField& f : fields) {
      if (f.path == "graph.trim" || f.path == "graph.thresholds" ||
          section_of(f.path) == "label_scheme")
        continue;
      ++total;
      if (!field_matches(f, search)) continue;
      ++shown;
      changed |= field_row(config, f, v, actions, true);
      if (changed) break;  // the configuration changed under the list: the rest next frame
    }
    ui::figure(ui::format("%zu of %zu parameters match \"%s\"", shown, total, search.c_str()),
               ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled), true);
    return changed;
  }
  Config::sections([&](auto, const FieldInfo& section) {
    const std::string key = section.key;
    if (moved || key == "label_scheme") return;  // the paths moved: drawn again next frame
    ImGui::PushID(section.key);
    const bool open = ui::tree_node("##section", (key + ": " + section.doc).c_str());
    if (open) {
      if (key == "landmarks") changed |= class_entries(config, fields, v, actions, moved);
      for (const ConfigField& f : fields) {
        if (moved) break;
        if (section_of(f.path) != key || f.path.rfind("landmarks.classes[", 0) == 0) continue;
        if (f.path == "graph.trim" || f.path == "graph.thresholds") continue;  // drawn above
        changed |= field_row(config, f, v, actions);
      }
      ui::tree_pop();
    }
    ImGui::PopID();
  });
  return changed;
}

}  // namespace pagor::studio
