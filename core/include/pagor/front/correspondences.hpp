#pragma once
/// \file correspondences.hpp
/// Putative correspondences between source and target landmarks of the same class:
/// all-to-all for cluster classes, mutual nearest FPFH descriptors for keypoint classes.

#include <string>
#include <vector>

#include "pagor/config.hpp"
#include "pagor/front/landmarks.hpp"
#include "pagor/types.hpp"

namespace pagor {

/// The correspondences of a pair of clouds.
struct CorrespondenceSet {
  std::vector<Correspondence> items;   ///< kept correspondences, best score first within a class
  std::size_t candidates = 0;          ///< how many there were before the cap
  bool capped = false;                 ///< whether the cap removed some
  std::vector<std::size_t> per_class;  ///< kept per configured class
  std::vector<std::string> warnings;
  double time_ms = 0.0;  ///< wall time [ms]
};

/// Matches two landmark sets made with the same class list. Cluster classes: every source
/// landmark with every target landmark of the class, scored by how alike their extents are.
/// Keypoint classes: descriptor nearest neighbours (mutual when configured), scored by descriptor
/// distance. When the total exceeds `params.max_correspondences`, the best-scored are kept and
/// `capped` is set. Items are ordered by class, and within a class by decreasing score.
CorrespondenceSet match_landmarks(const LandmarkSet& source, const LandmarkSet& target,
                                  const CorrespondenceParams& params = {});

}  // namespace pagor
