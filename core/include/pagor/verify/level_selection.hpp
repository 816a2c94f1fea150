#pragma once
/// \file level_selection.hpp
/// Which level's candidate to select when there are no clouds to verify on (a matcher's
/// correspondences alone). Verification scores a candidate on the dense clouds; without them it
/// is scored the same way on the correspondences: S = sum_i min(|T p_i - q_i|, c) over *every*
/// correspondence i, not only the level's clique, with c the GNC noise bound. A clique of
/// spurious agreement (e.g. points matched to themselves near the sensor, a near-identity pose)
/// explains itself but few of the other correspondences; the true pose explains the true
/// correspondences of every level.

#include <vector>

#include "pagor/pose/gnc.hpp"
#include "pagor/types.hpp"
#include "pagor/verify/evaluation.hpp"
#include "pagor/verify/verification.hpp"

namespace pagor {

/// Selects among `candidates` (one per level) by S over `correspondences` with truncation
/// `bound` [m] (residuals in the x-y plane for SE(2) candidates): the lowest S wins; ties (to 1e-9
/// relative) go to more GNC inliers, then to the lower level. `scores` stay +infinity (there is no
/// D); `support` and `support_scores` hold each candidate's count of correspondences within
/// `bound` and its S (+infinity when invalid); `selected` is -1 when no candidate is valid.
VerificationResult select_without_clouds(const std::vector<PoseEstimate>& candidates,
                                         const std::vector<Correspondence>& correspondences,
                                         double bound);

/// The first valid candidate other than `level` among those `among` marks (one entry per
/// candidate, non-zero: eligible) whose pose is the same answer as candidate `level`'s: within
/// `distinct`'s translation and rotation (the acceptance's distinct_*); -1 when there is none or
/// candidate `level` is invalid.
int same_answer_as(const std::vector<PoseEstimate>& candidates, int level,
                   const std::vector<char>& among, const EvaluationParams& distinct);

}  // namespace pagor
