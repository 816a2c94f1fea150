#pragma once
/// \file acceptance.hpp
/// Whether the selected pose should be trusted: the verdict a loop-closure user acts on. After
/// verification has picked the lowest-D candidate, three measures are taken:
/// - overlap: the fraction of verification source points above the ground layer that lie within
///   `inlier_distance` of a target point under the selected pose. True overlaps leave a
///   substantial part of the structure aligned; any level pose aligns the ground of two scans that
///   share nothing, so the ground is left out (all points count when it would leave too few);
/// - inliers: how many correspondences of the selected clique agree with the pose (GNC inliers);
/// - margin: how much better the selected D is than the best *distinct* candidate (one that
///   differs from the selection by more than the success criterion), as a fraction of the largest
///   possible D (mu times the number of source points); 1 when there is no distinct candidate.
/// The pose is accepted when every measure reaches its threshold; a pose resting on the minimal
/// number of inliers for its model must reach the higher `minimal_support_overlap`.

#include <string>
#include <vector>

#include "pagor/config.hpp"
#include "pagor/pose/gnc.hpp"
#include "pagor/verify/verification.hpp"

namespace pagor {

/// The verdict and the measures behind it.
struct Acceptance {
  bool accepted = false;  ///< trust the selected pose
  double overlap = 0.0;   ///< fraction of source points within inlier_distance, in [0, 1]
  int inliers = 0;        ///< GNC inliers of the selected candidate
  double margin = 0.0;    ///< D margin to the best distinct candidate, fraction of mu * points
  std::string reason;     ///< which measure failed, e.g. "overlap 0.08 < 0.25"; empty if accepted
};

/// Judges the selection of `verification` among `candidates`. No selection: not accepted.
Acceptance judge_selection(const Verifier& verifier, const std::vector<PoseEstimate>& candidates,
                           const VerificationResult& verification,
                           const VerificationParams& verification_params,
                           const EvaluationParams& distinct, const AcceptanceParams& params,
                           PoseModel model);

}  // namespace pagor
