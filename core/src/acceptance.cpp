#include "pagor/acceptance.hpp"

#include <cmath>
#include <cstdio>

#include "pagor/evaluation.hpp"

namespace pagor {
namespace {

std::string below(const char* what, double value, double threshold) {
  char buf[96];
  std::snprintf(buf, sizeof(buf), "%s %.3g < %.3g", what, value, threshold);
  return buf;
}

}  // namespace

Acceptance judge_selection(const Verifier& verifier, const std::vector<PoseEstimate>& candidates,
                           const VerificationResult& verification,
                           const VerificationParams& verification_params,
                           const EvaluationParams& distinct, const AcceptanceParams& params) {
  Acceptance a;
  if (verification.selected < 0) {
    a.reason = "no valid candidate";
    return a;
  }
  const std::size_t sel = static_cast<std::size_t>(verification.selected);
  const Transform& T = candidates[sel].T_target_source;
  const std::vector<float> d = verifier.distances(T);
  std::size_t close = 0;
  for (float x : d) close += x <= params.inlier_distance;
  a.overlap = d.empty() ? 0.0 : static_cast<double>(close) / static_cast<double>(d.size());
  a.inliers = static_cast<int>(candidates[sel].inliers.size());

  // Margin to the best candidate that is a different answer, not the same pose found twice.
  const double full = verification_params.mu * static_cast<double>(d.size());
  double best_other = HUGE_VAL;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (i == sel || !candidates[i].valid) continue;
    if (pose_error(candidates[i].T_target_source, T, distinct).success) continue;
    best_other = std::min(best_other, verification.scores[i]);
  }
  a.margin = std::isfinite(best_other) && full > 0
                 ? (best_other - verification.scores[sel]) / full
                 : 1.0;

  if (a.overlap < params.min_overlap)
    a.reason = below("overlap", a.overlap, params.min_overlap);
  else if (a.inliers < params.min_inliers)
    a.reason = below("inliers", a.inliers, params.min_inliers);
  else if (a.margin < params.min_margin)
    a.reason = below("D margin", a.margin, params.min_margin);
  a.accepted = a.reason.empty();
  return a;
}

}  // namespace pagor
