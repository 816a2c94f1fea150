#pragma once
/// \file dataset.hpp
/// Where the clouds of a registration come from: two files, a KITTI sequence pair, or the
/// generated synthetic scene. Shared by the CLI and the studio so both open data the same way.

#include <cstdint>
#include <optional>
#include <string>

#include "pagor/config.hpp"
#include "pagor/indoor/column_detector.hpp"
#include "pagor/indoor/floor_plan.hpp"
#include "pagor/io/clouds.hpp"
#include "pagor/types.hpp"

namespace pagor {

/// Description of a registration pair's data.
struct PairSource {
  enum class Kind { files, kitti, synthetic };
  Kind kind = Kind::synthetic;
  // files
  std::string source, source_labels;  ///< source cloud and optional `.label` file
  std::string target, target_labels;  ///< target cloud and optional `.label` file
  std::string ground_truth;  ///< optional 4x4 `T_target_source` file; replaces any other truth
  /// Optional matcher's correspondences file (correspondence_file.hpp) for the studio; not read by
  /// load_pair (the pipeline takes them through set_matches).
  std::string correspondences;
  /// The numbering of both clouds' labels, a built-in scheme's name (`none`: read them without
  /// labels); empty: the configuration's `label_scheme`.
  std::string label_scheme;
  // kitti
  std::string kitti_root;       ///< directory holding `sequences/`
  std::string sequence = "00";  ///< sequence name
  int source_frame = 0, target_frame = 0;
  // synthetic
  std::uint64_t synthetic_seed = 7;  ///< seed of the generated scene
};

/// A loaded pair.
struct LoadedPair {
  LoadedCloud source, target;
  std::string source_name, target_name;  ///< file paths or descriptions, for messages
  /// Ground truth when known, between the clouds' own frames (to_cloud_frames, clouds.hpp).
  std::optional<Transform> T_target_source_gt;
  /// Indoor pair: the floor plan the target was sampled from (its vector geometry, for drawing).
  std::optional<FloorPlan> plan;
  /// Indoor pair: the columns found in the scan, in the scan frame (floor_projection.hpp).
  std::vector<DetectedColumn> scan_columns;
};

/// Loads a pair. A file pair whose target is a floor plan (`.json` or `.svg`, floor_plan.hpp) is
/// an indoor pair: the plan is sampled into points and the scan projected to the floor with its
/// columns found, both by `indoor` (floor_projection.hpp). Throws InputError naming the file.
/// `threads` > 1 loads the two clouds at once (the same pair; of two errors, the source's).
LoadedPair load_pair(const PairSource& src, const IndoorParams& indoor = {}, int threads = 1);

/// The label scheme a pair's own description sets (PairSource::label_scheme), if any.
std::optional<LabelScheme> pair_label_scheme(const PairSource& src);

/// A one-line description, e.g. "KITTI 00: 20 -> 30".
std::string describe(const PairSource& src);

}  // namespace pagor
