#pragma once
/// \file param_editor.hpp
/// Every parameter of the configuration, generated from its field table (config.hpp:
/// `config_fields`): a widget per kind (number, integer, flag, choice, text, list), on a log
/// scale where the field says so, clamped to its range (plus its "off" value), with its unit, its
/// documentation and range as tooltip, a mark when it differs from the reference configuration
/// (the preset) and a button that resets it. A field the tables gain appears here without code.
/// Landmark classes can be added (from the label scheme's classes) and removed.

#include <string>

#include "pagor/config.hpp"
#include "panels/studio_actions.hpp"

namespace pagor::studio {

/// The widget a number or integer field gets, and the range it spans.
struct NumberWidget {
  enum Kind { log_slider, slider, typed } kind = typed;
  double lo = 0, hi = 1;  ///< the span: the field's range, open ends nudged inside
  bool integer = false;
};

/// The widget of a number or integer field: a log slider where `info.log_scale`, a linear
/// slider over a range of at most 100 units, else a typed field.
NumberWidget number_widget(const ConfigField& field);

/// The label of a field: its key, its unit in brackets ("voxel_size [m]", a "trim" unit by the
/// TRIM kind: metres for a difference, none for a ratio).
std::string field_label(const ConfigField& field, TrimKind trim);

/// The tooltip of a field: its documentation, its range with unit, its "off" value, its key path.
std::string field_tooltip(const ConfigField& field, TrimKind trim);

/// Whether a field matches a search: every word of `query` (case-insensitive) is in its key path
/// or its documentation. An empty query matches every field.
bool field_matches(const ConfigField& field, const std::string& query);

/// The generated sections of every parameter but the label scheme and the pyramid's TRIM and
/// thresholds (the Parameters panel draws those above). Edits go through set_field_number /
/// set_field_json, so the configuration stays valid (a refused value is reported by notify()).
/// With a non-empty `search`, the fields that match it (field_matches), in one list, instead of
/// the sections. True when something changed.
bool parameter_sections(Config& config, const Config& reference, const std::string& search,
                        StudioActions& actions);

}  // namespace pagor::studio
