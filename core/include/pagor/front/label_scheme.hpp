#pragma once
/// \file label_scheme.hpp
/// Label schemes are configuration: a named map from class names to the raw label ids that
/// mean that class in a data set.

#include <cstdint>
#include <string>
#include <vector>

namespace pagor {

/// One semantic class and the raw ids (lower 16 bits of a label) that belong to it.
struct SemanticClass {
  std::string name;
  std::vector<std::uint32_t> ids;
};

/// A named label scheme.
struct LabelScheme {
  std::string name;
  std::vector<SemanticClass> classes;

  /// Index of a class by name, or -1.
  int find(const std::string& class_name) const;
  /// Ids of a class. Throws ConfigError naming the scheme and listing its classes.
  const std::vector<std::uint32_t>& ids_of(const std::string& class_name) const;
  /// Comma-separated class names, for messages.
  std::string class_list() const;
  /// `auto`: each cloud's numbering is detected from its labels (label_detection.hpp).
  bool automatic() const { return name == "auto"; }
  /// `none`: labels are not used; every cloud is read as unlabelled.
  bool ignores_labels() const { return name == "none"; }
};

/// The built-in schemes:
/// - `auto` (the default): each cloud's labels are read in the numbering detected from their
///   values (label_detection.hpp), or not at all when none fits. Names every class of the
///   numberings below, with no ids.
/// - `none`: labels are ignored (the class-agnostic front end alone). Names the same classes.
/// - `semantickitti`: raw SemanticKITTI ids (car 10, truck 18, building 50, vegetation 70,
///   trunk 71, pole 80, traffic-sign 81, ...). Moving-object ids (252-259) belong to no class.
/// - `semantickitti-train`: the 19-class training numbering starting at 0 (car 0, ..., pole 17,
///   traffic-sign 18), as output by segmentation networks and in the shared KITTI data.
/// - `semantickitti-learning`: SemanticKITTI's learning map, 0 unlabeled, 1 car, ..., 9 road,
///   13 building, 15 vegetation, 16 trunk, 18 pole, 19 traffic-sign (the training numbering + 1).
/// - `indoor`: a small scheme for scans against floor plans (wall 1, column 2, door 3, furniture
/// 4). Throws ConfigError listing the built-in names for an unknown one.
LabelScheme builtin_label_scheme(const std::string& name);

/// Names of the built-in schemes: `auto`, `none` and the numberings.
std::vector<std::string> builtin_label_scheme_names();

/// Names of the built-in numberings (the schemes with ids: all but `auto` and `none`).
std::vector<std::string> label_numbering_names();

}  // namespace pagor
