#pragma once
/// \file config.hpp
/// Every parameter of every stage, in one document. The stages' parameter structs, each with
/// its table of fields (util/fields.hpp), are in params.hpp; this header gathers them.
/// `Config::sections` is the one list of the document's sections: the reader, the writer, the
/// checks, the reference (`pagor config --describe`), the studio's editor and the pipeline's
/// staleness all follow it.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "pagor/front/label_scheme.hpp"
#include "pagor/params.hpp"
#include "pagor/util/fields.hpp"

namespace pagor {

/// The whole configuration.
struct Config {
  LabelScheme label_scheme;  ///< default: auto (detected per cloud)
  LandmarkParams landmarks;
  CorrespondenceParams correspondences;
  GraphParams graph;
  CliqueParams clique;
  GncParams gnc;
  VerificationParams verification;
  RefinementParams refinement;
  AcceptanceParams acceptance;
  EvaluationParams evaluation;
  IndoorParams indoor;  ///< scans against floor plans

  /// The sections in document order: `v(&Config::member, FieldInfo{key, doc})` for each.
  template <class V>
  static void sections(V&& v) {
    v(&Config::label_scheme,
      {"label_scheme",
       "The numbering of the labels: a built-in scheme's name or {name, classes}."});
    v(&Config::landmarks, {"landmarks", "Landmark extraction, per class."});
    v(&Config::correspondences, {"correspondences", "Putative correspondences."});
    v(&Config::graph, {"graph", "The pyramid of consistency graphs."});
    v(&Config::clique, {"clique", "The densest clique of each level."});
    v(&Config::gnc, {"gnc", "The pose of each level's clique: GNC with a TLS cost."});
    v(&Config::verification, {"verification", "Scoring the candidates on the dense clouds."});
    v(&Config::refinement, {"refinement", "ICP refinement of the selected pose."});
    v(&Config::acceptance, {"acceptance", "The verdict: whether to trust the selected pose."});
    v(&Config::evaluation, {"evaluation", "The success criterion against ground truth."});
    v(&Config::indoor, {"indoor", "Scans against floor plans."});
  }
};

/// The project's outdoor defaults: the paper's method with what measurement on the shared data
/// showed to be better (README, "Presets"): poses in 4-DoF where the data is level and in SE(3)
/// otherwise (`gnc.model = auto`), point-spacing adaptation, traffic signs,
/// class-agnostic keypoints for class-poor or unlabelled pairs.
Config default_config();

/// A named configuration: `default` (default_config()) or `paper` (the published outdoor
/// configuration exactly: car, trunk, pole clusters and building FPFH at the configured voxel
/// sizes, ratio TRIM 0.02/0.04/0.08/0.16, SE(3), truncated D with mu = 1 m, no spacing
/// adaptation, no class-agnostic keypoints, no refinement) or `indoor` (a scan against a floor
/// plan, as the paper's car park: columns as landmarks, difference TRIM 0.05..0.25 m, SE(2),
/// success 1 m / 3 deg). Throws ConfigError listing the names.
Config preset_config(const std::string& name);

/// Names of the presets.
std::vector<std::string> preset_names();

/// Parses a JSON document. Keys that are absent keep the values of the preset named by the
/// top-level key `preset` (a string), else of `base_preset`. Unknown keys, wrong types and invalid
/// values throw ConfigError naming `origin` and the key path (e.g. `graph.thresholds[2]`).
Config parse_config(const std::string& json_text, const std::string& origin = "config",
                    const std::string& base_preset = "default");

/// Reads and parses a JSON file. Throws InputError (unreadable) or ConfigError.
Config load_config(const std::string& path, const std::string& base_preset = "default");

/// Serialises every parameter as JSON.
std::string config_to_json(const Config& config, int indent = 2);

/// One section (a key of Config::sections) as compact JSON; two configs agree on a section iff
/// these are equal. Throws ConfigError for an unknown section.
std::string section_json(const Config& config, const std::string& section);

/// Checks values: each field against its range, the tables' cross-field rules, class names against
/// the label scheme. Throws ConfigError naming the key path and the allowed range.
void validate(const Config& config, const std::string& origin = "config");

/// What kind of value a parameter holds.
enum class FieldKind {
  number,   ///< a real number (FieldInfo::range, unit)
  integer,  ///< a whole number (FieldInfo::range)
  flag,     ///< true or false
  choice,   ///< one of `ConfigField::choices`
  text,     ///< a string (a class name)
  numbers,  ///< a list of numbers, each in FieldInfo::range (the thresholds)
  other,    ///< a list of names, or the label scheme: edited as JSON
};

/// One parameter of a configuration, addressed by its key path: "verification.mu",
/// "landmarks.classes[2].voxel_size" (a list of tables gives a path per element).
struct ConfigField {
  std::string path;
  FieldInfo info;
  FieldKind kind = FieldKind::number;
  std::vector<std::string> choices;  ///< choice: the names, in table order
};

/// Every parameter of `config`, in document order, generated from the tables (so a new field
/// appears here, and in the studio's editor, by being listed once in its table, params.hpp).
std::vector<ConfigField> config_fields(const Config& config);

/// The value at `path` as compact JSON. Throws ConfigError for a path that names no parameter.
std::string field_json(const Config& config, const std::string& path);
/// Sets the value at `path` from JSON text (checked like the document; the whole configuration is
/// validated). Throws ConfigError naming the path; `config` is unchanged then.
void set_field_json(Config& config, const std::string& path, const std::string& json_text);
/// Sets several values at once, each (key path, JSON text), and validates the result once (so a
/// pair of values that is only valid together, such as min_points and max_points, can be set).
/// Throws ConfigError naming the path; `config` is unchanged then.
void set_fields_json(Config& config,
                     const std::vector<std::pair<std::string, std::string>>& values);
/// A number, integer or flag parameter's value as a double (flags 0/1); nullopt for other kinds
/// or an unknown path.
std::optional<double> field_number(const Config& config, const std::string& path);
/// Sets a number, integer or flag parameter (integers rounded; flags: non-zero is true) and
/// validates. Throws ConfigError naming the path and the allowed range; `config` is unchanged.
void set_field_number(Config& config, const std::string& path, double value);

/// The reference of every parameter, generated from the tables: one Markdown table per section
/// with key path, default, allowed values, unit and documentation.
std::string config_reference_markdown();

}  // namespace pagor
