#pragma once
/// \file ambiguity.hpp
/// The search behind acceptance's ambiguity test (acceptance.hpp): distinct poses that explain the
/// clouds about as well as the selected one where the scene repeats itself. Internal to the core.
///
/// An alternative is scored against the selected pose by the structure points (those acceptance
/// counts) on which they disagree: ratio = (points only it aligns + 10) / (points only the selected
/// pose aligns + 10), a point aligned within the inlier distance r and not aligned beyond 2 r,
/// among the points both put where the target looked. About 1: nothing tells the two apart. Under
/// 1: the selected pose has evidence the alternative lacks (a car in a corridor of pillars). Over
/// 1: the alternative is the better pose. Alternatives:
/// - the other levels' candidates that are a different answer;
/// - the selected pose, and the same turned 180 degrees about the vertical through the centre of
///   what it aligns, each moved along the target structure's two horizontal axes (a scan's
///   principal axes; a plan's the directions its walls run along) by the shifts where the clouds'
///   occupancy agrees best (peaks of the cross-correlation of two voxel grids, which is where a
///   repetition period shows); also tried moved across its axis, by up to twice the distinct
///   translation, to where the occupancy agrees best (against a plan every peak, a scan the two
///   best); the two best of them then locally to the best E.
/// Every alternative is scored by E on the same points; the one with the highest E is returned.

#include <string>
#include <vector>

#include "pagor/types.hpp"
#include "pagor/verify/acceptance.hpp"
#include "pagor/verify/evaluation.hpp"
#include "pagor/verify/verification.hpp"

namespace pagor {

/// What the search needs: the clouds, the points counted, the selection and what is distinct.
struct AmbiguityInput {
  const Verifier* verifier = nullptr;
  const std::vector<char>* counts = nullptr;         ///< per downsampled source point: counted
  const std::vector<char>* target_counts = nullptr;  ///< per downsampled target point: structure
  /// per downsampled source point: furniture (what stands lower than the walls; only against a
  /// floor plan): a pose that puts it on the target's structure is contradicted by it; null: none
  const std::vector<char>* furniture = nullptr;
  /// the target shows all there is (a floor plan): every point is where it looked; otherwise only
  /// the horizontal cells that hold target points (a scan sees its surroundings up to a range)
  bool target_complete = false;
  Transform T_selected = Transform::Identity();
  /// the selected pose's distances (Verifier::distances) searched with a bound of at least
  /// 2 inlier_distance;
  /// null: searched here
  const std::vector<float>* selected_distances = nullptr;
  /// D's truncation [m]: the correlation's grid is mu / 2 (at least inlier_distance / 2)
  double mu = 1.0;
  double inlier_distance = 0.5;  ///< a point counts as aligned within this [m]
  EvaluationParams distinct;     ///< a pose within this of the selected one is the same answer
  double search_range = 40.0;    ///< furthest shift searched along an axis [m]
  int threads = 1;               ///< threads for the searches of the points (same result)
};

/// The best distinct alternative among `candidates` (the other levels', described by `names`) and
/// the repetitions of the selected pose, with its ratio (above). Empty description when
/// there is no distinct alternative.
AcceptanceAlternative find_best_alternative(const AmbiguityInput& in,
                                            const std::vector<Transform>& candidates,
                                            const std::vector<std::string>& names);

}  // namespace pagor
