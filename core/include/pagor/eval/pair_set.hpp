#pragma once
/// \file pair_set.hpp
/// Sets of registration pairs for benchmarks: a KITTI pairs file, or a generic manifest that
/// names any two clouds with optional label files and an optional ground-truth transform.
///
/// Manifest format: one pair per line, `SOURCE TARGET [key=value ...]`, paths relative to the
/// manifest's directory, `#` starts a comment. Keys:
/// - `gt=FILE`: the 4x4 ground truth `T_target_source` (row-major, whitespace-separated);
/// - `source_labels=FILE`, `target_labels=FILE`: SemanticKITTI `.label` files for the clouds;
/// - `scheme=NAME`: the numbering of this pair's labels, a built-in label scheme (`auto`, `none`:
///   read the clouds without their labels, `semantickitti`, ...), in place of the configuration's;
/// - `name=TEXT`: the pair's name in tables (default: the line number);
/// - `overlap=no`: a known negative, two scans that share nothing (no `gt` then).
/// A path or value with blanks is written in double quotes (`"my scan.pcd"`, `name="pair 3"`;
/// inside them `\"` and `\\` stand for `"` and `\`). Every pair needs its own name, and a line
/// naming the same files as another (however spelled: `./a.pcd`, `a.pcd`, a symbolic link) with
/// the same role is refused.
/// A TARGET that is a floor plan (`.json` or `.svg`, floor_plan.hpp) makes the pair an indoor
/// pair: the scan is registered against the plan (dataset.hpp).

#include <optional>
#include <string>
#include <vector>

#include "pagor/eval/dataset.hpp"
#include "pagor/types.hpp"

namespace pagor {

/// One pair of a set.
struct PairEntry {
  std::string name;       ///< shown in tables, e.g. "03" or "0 -> 20"
  PairSource source;      ///< where its clouds (and ground truth) come from
  bool negative = false;  ///< a known non-overlapping pair: registration should be rejected
  std::string origin;     ///< "manifest.txt:7", for messages
};

/// A named list of pairs.
struct PairSet {
  std::string origin;            ///< the file it was read from
  std::vector<PairEntry> pairs;  ///< in file order
};

/// Reads a generic manifest (format above). Every named file must exist. Throws InputError
/// naming the manifest and line (a missing file, an unknown key, a negative with `gt`).
PairSet read_pair_manifest(const std::string& path);

/// The pairs of a KITTI pairs file (`source target` frame numbers per line) in one sequence.
/// Opens the sequence first, so a broken poses.txt or calib.txt, or a frame without a pose, fails
/// before any pair runs. Throws InputError naming the file (and line).
PairSet kitti_pair_set(const std::string& kitti_root, const std::string& sequence,
                       const std::string& pairs_file);

/// A fingerprint of what a pair's result depends on besides the configuration and the tool: its
/// name, whether it is a known negative, and the content of every file it reads (clouds, labels,
/// ground truth, a floor plan; for a KITTI pair its two scans and label files, poses.txt and
/// calib.txt), however the files are named or wherever they are. Throws InputError naming a file
/// that cannot be read.
std::string pair_fingerprint(const PairEntry& entry);

/// Reads a 4x4 rigid transform (16 numbers, row-major; a 3x4 matrix of 12 numbers is accepted
/// too). Throws InputError naming the file and line when it is not 12/16 finite numbers, the
/// last row is not (0 0 0 1), or the rotation is not orthonormal with determinant +1.
Transform read_transform_file(const std::string& path);

/// The text of a transform file: four rows of four numbers, each printed so that
/// read_transform_file reads back the same double (%.17g).
std::string transform_file_text(const Transform& T);

/// Throws InputError (prefixed by `where`) when `T` is not a rigid transform: rotation
/// orthonormal within 1e-3 and det +1, last row (0 0 0 1), all entries finite.
void check_rigid(const Transform& T, const std::string& where);

}  // namespace pagor
