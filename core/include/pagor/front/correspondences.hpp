#pragma once
/// \file correspondences.hpp
/// Putative correspondences between source and target landmarks of the same class:
/// all-to-all for cluster classes, mutual nearest FPFH descriptors for keypoint classes.

#include <string>
#include <vector>

#include "pagor/front/landmarks.hpp"
#include "pagor/types.hpp"

namespace pagor {

/// Correspondence generation.
struct CorrespondenceParams {
  int max_correspondences = 1500;  ///< cap on the total; the most promising are kept; 0 = no cap
  bool fpfh_mutual = true;         ///< fpfh classes: keep only mutual nearest descriptors
  int fpfh_max_per_class = 300;    ///< fpfh classes: at most this many matches (best first)
  /// fpfh classes: keep a match only when its descriptor distance is at most this fraction of the
  /// distance to the second nearest (Lowe's ratio test); 1: no test
  double fpfh_ratio = 1.0;
  double shape_scale = 0.5;  ///< ranking of cluster pairs: extents differing by this much [m]
                             ///< score e^-1

  template <class V>
  static void fields(V&& v) {
    v(&CorrespondenceParams::max_correspondences,
      {"max_correspondences",
       "Cap on the number of correspondences; the most promising are kept; 0: no cap.", "",
       Range::closed(1, 1e7), 0.0, true});
    v(&CorrespondenceParams::fpfh_mutual,
      {"fpfh_mutual", "FPFH classes: keep only mutual nearest descriptors."});
    v(&CorrespondenceParams::fpfh_max_per_class,
      {"fpfh_max_per_class", "FPFH classes: at most this many matches per class, best first.", "",
       Range::closed(1, 1e6)});
    v(&CorrespondenceParams::fpfh_ratio,
      {"fpfh_ratio",
       "FPFH classes: keep a match only when its descriptor distance is at most this fraction of "
       "the second nearest's (ratio test); 1: no test.",
       "", Range::above(0, 1)});
    v(&CorrespondenceParams::shape_scale,
      {"shape_scale",
       "Ranking of cluster pairs: extents differing by this much score e^-1 of alike ones.", "m",
       Range::above(0, 100)});
  }
};

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
