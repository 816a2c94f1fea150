#include "pagor/verify/acceptance.hpp"

#include <cmath>
#include <cstdio>

#include "pagor/front/ground.hpp"
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
  const auto bound = static_cast<float>(params.inlier_distance);
  std::vector<float> searched;
  if (!reuse) searched = verifier.distances(T, bound);
  const std::vector<float>& d = reuse ? verification.selected_distances : searched;
  // The ground follows the terrain (ground.hpp): on a sloped street a height layer would leave the
  // uphill road as structure, which a pose sliding along the street aligns.
  GroundParams ground_params;
  ground_params.thickness = params.ground_thickness;
  const std::vector<char> ground = ground_points(points, ground_params);
  std::size_t structure = 0;
  for (char g : ground) structure += !g;
  // A flat cloud (a floor projection: everything within the ground layer) is judged on all its
  // points. A scan with little structure is still judged on it: judged on all its points, a street
  // that is mostly road was "aligned" by any pose that lays road on road.
  const bool use_all = structure < std::max<std::size_t>(10, d.size() / 100);
  std::vector<char> counts(ground.size(), 1);  // the points the overlap counts
  if (!use_all)
    for (std::size_t i = 0; i < ground.size(); ++i) counts[i] = !ground[i];
  const auto overlap_of = [&](const std::vector<float>& dist) {
    std::size_t close = 0, counted = 0;
    for (std::size_t i = 0; i < dist.size(); ++i) {
      if (!counts[i]) continue;
      ++counted;
      close += dist[i] <= params.inlier_distance;
    }
    return counted ? static_cast<double>(close) / static_cast<double>(counted) : 0.0;
  };
  a.overlap = overlap_of(d);
  // The same pose moved by the success criterion's translation along each horizontal axis: a true
  // alignment loses most of its overlap, one that aligns only what slides along itself (a facade,
  // a hedge, the road) or what matches anything (vegetation) keeps it.
  double shifted = 0.0;
  for (const Eigen::Vector2d& step : {Eigen::Vector2d(1, 0), Eigen::Vector2d(-1, 0),
                                      Eigen::Vector2d(0, 1), Eigen::Vector2d(0, -1)}) {
    Transform moved = T;
    moved.block<2, 1>(0, 3) += distinct.max_translation_error * step;
    // Only the points overlap_of counts are searched (on KITTI, skipping the ground halved this).
    shifted = std::max(shifted, overlap_of(verifier.distances(moved, bound, counts)));
  }
  a.sharpness = a.overlap > 0 ? 1.0 - shifted / a.overlap : 0.0;
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
  else if (a.sharpness < params.min_sharpness)
    a.reason = below("sharpness", a.sharpness, params.min_sharpness);
  else if (a.margin < params.min_margin)
    a.reason = below("D margin", a.margin, params.min_margin);
  else if (a.inliers <= minimal_sample_size(model) && a.overlap < params.minimal_support_overlap)
    a.reason = below("overlap with minimal support", a.overlap, params.minimal_support_overlap);
  a.accepted = a.reason.empty();
  return a;
}

}  // namespace pagor
