// The Parameters panel: every parameter of the configuration, section by section, as the
// config's own structs hold them; a change re-runs the pipeline (cached stages are reused).

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "pagor/errors.hpp"
#include "panels/panels.hpp"
#include "panels/param_editor.hpp"
#include "widgets/number_format.hpp"
#include "widgets/widgets.hpp"

namespace pagor::studio {
namespace {

constexpr std::size_t kMaxLevels = 32;
const ImVec4 kRed(1.0f, 0.4f, 0.4f, 1.0f);

void section(const char* title) {
  ImGui::Spacing();
  ImGui::Separator();
  ImGui::TextDisabled("%s", title);
}

// Keeps the levels strictly increasing inside the fixed range: sorts, clamps and drops equal
// neighbours (saying so). True when something had to change.
bool normalise_levels(GraphParams& g, StudioActions& actions) {
  auto& th = g.thresholds;
  const auto [lo, hi] = epsilon_range(g.trim);
  const std::vector<double> before = th;
  for (double& e : th) e = std::clamp(e, lo, hi);
  if (th != before)
    actions.notify(Message::info("\xce\xb5 clamped into [" + std::to_string(lo) + ", " +
                                 std::to_string(hi) + "], the range of TRIM '" + to_string(g.trim) +
                                 "'"));
  std::sort(th.begin(), th.end());
  th.erase(std::unique(th.begin(), th.end()), th.end());
  if (th.size() < before.size())
    actions.notify(Message::info("two levels had the same \xce\xb5; kept one"));
  return th != before;
}

// The built-in label schemes that name every configured landmark class (others would make the
// configuration invalid). Returns whether the scheme changed.
bool label_scheme_combo(Config& c) {
  bool changed = false;
  if (ui::begin_combo(
          "labels", c.label_scheme.name.c_str(),
          "Numbering of the clouds' labels: auto (detected per cloud), none (labels not used), "
          "raw SemanticKITTI ids, the 0-based training numbering, or the learning map that "
          "segmentation networks output.")) {
    for (const std::string& name : builtin_label_scheme_names()) {
      const LabelScheme scheme = builtin_label_scheme(name);
      const bool fits = std::all_of(c.landmarks.classes.begin(), c.landmarks.classes.end(),
                                    [&](const ClassParams& p) { return scheme.find(p.name) >= 0; });
      if (!fits) continue;
      if (ui::selectable(name.c_str(), name == c.label_scheme.name) &&
          name != c.label_scheme.name) {
        c.label_scheme = scheme;
        changed = true;
      }
    }
    ui::end_combo();
  }
  return changed;
}

// One row per level: its epsilon slider, insert and delete, drawn for the TRIM kind `trim` (the
// one at the start of the frame). True when a level changed.
bool level_rows(GraphParams& g, TrimKind trim, StudioActions& actions) {
  bool changed = false;
  const bool ratio = trim == TrimKind::ratio;
  const auto [lo, hi] = epsilon_range(trim);
  for (std::size_t l = 0; l < g.thresholds.size(); ++l) {
    ImGui::PushID(static_cast<int>(l));
    const std::string label = "\xce\xb5" + std::to_string(l) + (ratio ? "" : " [m]");
    ImGui::PushItemWidth(ImGui::CalcItemWidth() - 2 * (ImGui::GetFrameHeight() + 4));
    changed |= ui::slider_double(label.c_str(), &g.thresholds[l], lo, hi, "%.4g", true,
                                 "Consistency threshold of this pyramid level: two "
                                 "correspondences agree when their TRIM value is below it. The "
                                 "scale is fixed and logarithmic; levels are kept sorted.");
    const bool released = ImGui::IsItemDeactivatedAfterEdit();
    ImGui::PopItemWidth();
    ImGui::SameLine();
    const bool can_insert =
        g.thresholds.size() < kMaxLevels && (l == 0 ? g.thresholds[0] > lo : true);
    ImGui::BeginDisabled(!can_insert);
    if (ui::small_button("+", "Inserts a level below this one (between it and the one before).")) {
      const double v = l == 0 ? std::max(lo, g.thresholds[0] * 0.5)
                              : std::sqrt(g.thresholds[l - 1] * g.thresholds[l]);
      g.thresholds.insert(g.thresholds.begin() + static_cast<std::ptrdiff_t>(l),
                          shortest(static_cast<float>(v)));
      changed = true;
    }
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(g.thresholds.size() <= 1);
    if (ui::small_button("x", "Deletes this level.")) {
      g.thresholds.erase(g.thresholds.begin() + static_cast<std::ptrdiff_t>(l));
      changed = true;
    }
    ImGui::EndDisabled();
    ImGui::PopID();
    if (released && normalise_levels(g, actions)) changed = true;
    if (l >= g.thresholds.size()) break;
  }
  return changed;
}

// The label scheme, the TRIM and the pyramid's levels.
bool graph_section(Config& c, StudioActions& actions) {
  GraphParams& g = c.graph;
  const TrimKind trim = g.trim;
  const auto [lo, hi] = epsilon_range(trim);
  bool changed = label_scheme_combo(c);
  ImGui::TextDisabled("%zu levels, \xce\xb5 in [%g, %g]%s", g.thresholds.size(), lo, hi,
                      trim == TrimKind::ratio ? "" : " m");
  ImGui::SameLine();
  ImGui::BeginDisabled(g.thresholds.size() >= kMaxLevels || g.thresholds.back() >= hi);
  if (ui::small_button("+ level at end", "Appends a level with twice the largest \xce\xb5.")) {
    g.thresholds.push_back(std::min(hi, shortest(static_cast<float>(g.thresholds.back() * 2))));
    changed = true;
  }
  ImGui::EndDisabled();
  if (ui::enum_combo("TRIM", g.trim,
                     "How two correspondences are compared: 'ratio' of their lengths (outdoor, "
                     "unitless) or 'difference' of lengths in metres (indoor).")) {
    normalise_levels(g, actions);
    changed = true;
  }
  changed |= level_rows(g, trim, actions);
  if (!ImGui::IsAnyItemActive() && normalise_levels(g, actions)) changed = true;
  return changed;
}

// The presets: choosing one starts from it; the label scheme stays when it names the preset's
// classes (it belongs to the data).
bool preset_combo(Config& c, std::string& preset) {
  bool changed = false;
  if (ui::begin_combo("preset", preset.c_str(),
                      "The configuration the parameters start from: 'default' (the project's), "
                      "'paper' (the published one) or 'indoor' (a scan against a floor plan). "
                      "Parameters that differ from it are marked * and can be reset.")) {
    for (const std::string& name : preset_names())
      if (ui::selectable(name.c_str(), name == preset) && name != preset) {
        Config next = preset_config(name);
        Config kept = next;
        kept.label_scheme = c.label_scheme;
        try {
          validate(kept, "parameters");
          next = kept;
        } catch (const ConfigError&) {  // the scheme lacks the preset's classes: the preset's
        }
        c = next;
        preset = name;
        changed = true;
      }
    ui::end_combo();
  }
  return changed;
}

}  // namespace

std::pair<double, double> epsilon_range(TrimKind trim) {
  return trim == TrimKind::ratio ? std::pair{0.001, 1.0} : std::pair{0.01, 10.0};
}

void undo_redo_buttons(const ParamHistory& params, StudioActions& actions, const char* id) {
  const std::string suffix = id[0] ? std::string("##") + id : std::string();
  ImGui::BeginDisabled(!params.can_undo());
  if (ui::button(("undo" + suffix).c_str(), ImVec2(0, 0),
                 "Undo the last parameter change (Ctrl+Z)."))
    actions.undo();
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(!params.can_redo());
  if (ui::button(("redo" + suffix).c_str(), ImVec2(0, 0), "Redo (Ctrl+Y).")) actions.redo();
  ImGui::EndDisabled();
}

void parameters_panel(Config& config, std::string& preset, std::string& search,
                      const ParamHistory& params, const std::string& config_error,
                      StudioActions& actions) {
  if (!config_error.empty()) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(kRed, "invalid: %s", config_error.c_str());
    ImGui::PopTextWrapPos();
  }
  bool changed = preset_combo(config, preset);
  changed |= graph_section(config, actions);
  Config reference = preset_config(preset);
  reference.label_scheme = config.label_scheme;
  section("every parameter (* differs from the preset)");
  ui::input_text("find##parameters", &search,
                 "Only the parameters whose key or description holds every word typed here "
                 "(case-insensitive), in one list; empty: every section.");
  changed |= parameter_sections(config, reference, search, actions);
  undo_redo_buttons(params, actions, "");
  ImGui::SameLine();
  if (ui::button("defaults", ImVec2(0, 0),
                 "Every parameter back to the preset's values; the label scheme stays (it "
                 "belongs to the data).")) {
    try {
      validate(reference, "parameters");
      config = reference;
    } catch (const ConfigError&) {  // the scheme lacks the preset's classes
      config = preset_config(preset);
    }
    changed = true;
  }
  if (changed) actions.submit_config();
}

}  // namespace pagor::studio
