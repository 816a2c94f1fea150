#pragma once
/// \file level_selection.hpp
/// Which level's candidate to select when there are no clouds to verify on (a matcher's
/// correspondences alone): without a score D, the candidates are judged by their
/// correspondences only.

#include <vector>

#include "pagor/pose/gnc.hpp"
#include "pagor/verify/verification.hpp"

namespace pagor {

/// Selects among `candidates` (one per level) without clouds: the valid candidate with the most
/// GNC inliers, the lower level on a tie. Every score is +infinity (there is no D); `selected` is
/// -1 when no candidate is valid.
VerificationResult select_without_clouds(const std::vector<PoseEstimate>& candidates);

}  // namespace pagor
