#pragma once
/// \file correspondence_file.hpp
/// Correspondences from any matcher, as text: one correspondence per line,
///   px py pz qx qy qz [weight [inlier]]
/// (source point, target point [m], an optional non-negative weight, an optional ground-truth
/// inlier flag 0 or 1), separated by blanks or commas. Numbers are decimal (`12.5`, `-3e2`): hex
/// (`0x10`), `inf` and `nan` are errors, as is a coordinate beyond kMaxMatchCoordinate. `#` starts
/// a comment; blank lines are skipped. Every line has the same number of columns (6, 7 or 8). This
/// is the input of `pagor register --correspondences` and the format the benchmark's association
/// problems are written in.

#include <cstdint>
#include <string>
#include <vector>

#include "pagor/types.hpp"
#include "pagor/util/work_budget.hpp"

namespace pagor {

/// Most correspondences a file may hold: as many as the consistency graph takes
/// (kMaxGraphCorrespondences, work_budget.hpp), since every one of them goes into it.
constexpr std::size_t kMaxFileCorrespondences = kMaxGraphCorrespondences;
/// Largest correspondences file: 1 KiB per correspondence the file may hold [bytes].
constexpr std::uint64_t kMaxCorrespondenceFileBytes = std::uint64_t{1024} * kMaxFileCorrespondences;

/// Largest coordinate a correspondence may have on an axis [m]: the farthest a georeferenced
/// frame lies from its origin (kMaxFrameOrigin of the cloud readers: geocentric and national
/// grids stay within it). A coordinate beyond it is corrupt (1e30), an error naming the line.
constexpr double kMaxMatchCoordinate = 1e7;

/// What a correspondences file holds.
struct CorrespondenceFile {
  /// One per data line, in file order. Each has its own source and target id (its position),
  /// origin `matcher`, class_index -1, and `score` = its weight (1 without a weight column).
  std::vector<Correspondence> items;
  std::vector<double> weights;  ///< per item; empty without a weight column
  std::vector<char> inlier;     ///< ground-truth flag per item; empty without a flag column
  std::vector<int> lines;       ///< 1-based line number of each item in the file
};

/// Parses the text of a correspondences file. Throws InputError naming `origin` and the line
/// (`origin:LINE: ...`; for a number also its 1-based column) for a malformed number (not
/// decimal, not finite, a coordinate beyond kMaxMatchCoordinate), a wrong column count, a negative
/// or non-finite weight or a flag other than 0/1, when there is no correspondence at all, and at
/// the first line beyond kMaxFileCorrespondences (the message names the budget).
CorrespondenceFile parse_correspondence_file(const std::string& text,
                                             const std::string& origin = "correspondences");

/// Reads and parses a file. Throws InputError (not a regular file, unreadable, larger than
/// kMaxCorrespondenceFileBytes, or as above).
CorrespondenceFile read_correspondence_file(const std::string& path);

/// Precision and recall of a set of correspondence indices against ground-truth flags.
struct InlierQuality {
  std::size_t selected = 0;      ///< indices given
  std::size_t true_inliers = 0;  ///< of those, flagged inliers
  std::size_t inliers = 0;       ///< flagged inliers in total
  double precision = 0.0;        ///< true_inliers / selected (0 when nothing is selected)
  double recall = 0.0;           ///< true_inliers / inliers (0 when there are no inliers)
};

/// Precision/recall of `indices` (into `inlier`). Indices out of range throw std::out_of_range.
InlierQuality inlier_quality(const std::vector<int>& indices, const std::vector<char>& inlier);

}  // namespace pagor
