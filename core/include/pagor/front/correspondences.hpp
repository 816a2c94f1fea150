#pragma once
/// \file correspondences.hpp
/// Putative correspondences between source and target landmarks of the same class:
/// all-to-all for cluster classes, mutual nearest FPFH descriptors for keypoint classes.

#include <string>
#include <vector>

#include "pagor/front/landmarks.hpp"
#include "pagor/params.hpp"
#include "pagor/types.hpp"

namespace pagor {

/// The correspondences of a pair of clouds.
struct CorrespondenceSet {
  std::vector<Correspondence> items;   ///< kept correspondences, best score first within a class
  std::size_t candidates = 0;          ///< how many there were before the cap
  bool capped = false;                 ///< whether the cap removed some
  std::vector<std::size_t> per_class;  ///< kept landmark correspondences per configured class
  std::size_t matches = 0;             ///< of `items`, a matcher's (origin matcher, class_index -1)
  std::vector<std::string> warnings;
  double time_ms = 0.0;  ///< wall time [ms]
};

/// Correspondences counted by origin (CorrespondenceOrigin).
struct OriginCounts {
  std::size_t landmark = 0;  ///< the front end's
  std::size_t matcher = 0;   ///< a matcher's
};

/// How many of `items` come from each origin.
OriginCounts count_by_origin(const std::vector<Correspondence>& items);
/// How many of the correspondences `indices` names (a clique, a pose's inliers) come from each
/// origin; an index outside `items` is not counted.
OriginCounts count_by_origin(const std::vector<Correspondence>& items,
                             const std::vector<int>& indices);

/// Name of the class a correspondence is shown and counted under: its landmarks' class in
/// `source` (the landmark set it was made from), "matcher" for a matcher's correspondence, "?" for
/// a class index `source` does not have.
std::string correspondence_class_name(const Correspondence& c, const LandmarkSet& source);

/// The correspondences of a matcher, tagged CorrespondenceOrigin::matcher with class_index -1
/// (their `score` is the matcher's weight), after `landmark_correspondences` when given (fused: the
/// matcher's source and target ids are moved past the landmarks' `source_ids` and `target_ids`,
/// so that no two correspondences share an id by accident). A matcher's id below 0 becomes its
/// position in `matches`.
CorrespondenceSet with_matches(std::vector<Correspondence> matches,
                               CorrespondenceSet landmark_correspondences = {}, int source_ids = 0,
                               int target_ids = 0);

/// Matches two landmark sets made with the same class list. Cluster classes: every source
/// landmark with every target landmark of the class, scored by how alike their extents are.
/// Keypoint classes: descriptor nearest neighbours (mutual when configured), scored by descriptor
/// distance. When the total exceeds `params.max_correspondences`, the best-scored are kept and
/// `capped` is set. Items are ordered by class, and within a class by decreasing score. `threads`
/// > 1 splits the descriptor search (the same correspondences).
CorrespondenceSet match_landmarks(const LandmarkSet& source, const LandmarkSet& target,
                                  const CorrespondenceParams& params = {}, int threads = 1);

}  // namespace pagor
