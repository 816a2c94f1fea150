#include "pagor/verify/acceptance.hpp"

#include <cmath>
#include <cstdio>

#include "pagor/front/landmarks.hpp"
#include "pagor/verify/evaluation.hpp"

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
                           const EvaluationParams& distinct, const AcceptanceParams& params,
                           PoseModel model) {
  Acceptance a;
  if (verification.selected < 0) {
    a.reason = "no valid candidate";
    return a;
  }
  const std::size_t sel = static_cast<std::size_t>(verification.selected);
  const Transform& T = candidates[sel].T_target_source;
  const std::vector<Eigen::Vector3f>& points = verifier.source_points();
  // The distances the selection's D summed serve when their bound reaches the inlier distance
  // (points beyond it are not aligned either way).
  const bool reuse = verification.selected_distances.size() == points.size() &&
                     verification.distance_bound >= params.inlier_distance;
  std::vector<float> searched;
  if (!reuse) searched = verifier.distances(T, static_cast<float>(params.inlier_distance));
  const std::vector<float>& d = reuse ? verification.selected_distances : searched;
  const float ground = ground_layer_top(points, static_cast<float>(params.ground_thickness));
  std::size_t structure = 0, close = 0, close_all = 0;
  for (std::size_t i = 0; i < d.size(); ++i) {
    const bool aligned = d[i] <= params.inlier_distance;
    close_all += aligned;
    if (points[i].z() > ground) ++structure, close += aligned;
  }
  // A scene that is all ground (or not a ground vehicle's) is judged on all its points.
  const bool use_all = structure < std::max<std::size_t>(10, d.size() / 10);
  a.overlap = d.empty() ? 0.0
              : use_all ? static_cast<double>(close_all) / static_cast<double>(d.size())
                        : static_cast<double>(close) / static_cast<double>(structure);
  a.inliers = static_cast<int>(candidates[sel].inliers.size());

  // Margin to the best candidate that is a different answer, not the same pose found twice.
  const double full = verification_params.mu * static_cast<double>(d.size());
  double best_other = HUGE_VAL;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (i == sel || !candidates[i].valid) continue;
    if (pose_error(candidates[i].T_target_source, T, distinct).success) continue;
    best_other = std::min(best_other, verification.scores[i]);
  }
  a.margin =
      std::isfinite(best_other) && full > 0 ? (best_other - verification.scores[sel]) / full : 1.0;

  if (a.overlap < params.min_overlap)
    a.reason = below("overlap", a.overlap, params.min_overlap);
  else if (a.inliers < params.min_inliers)
    a.reason = below("inliers", a.inliers, params.min_inliers);
  else if (a.margin < params.min_margin)
    a.reason = below("D margin", a.margin, params.min_margin);
  else if (a.inliers <= minimal_sample_size(model) && a.overlap < params.minimal_support_overlap)
    a.reason = below("overlap with minimal support", a.overlap, params.minimal_support_overlap);
  a.accepted = a.reason.empty();
  return a;
}

}  // namespace pagor
