#include "pagor/verify/level_selection.hpp"

#include <algorithm>
#include <cmath>

namespace pagor {

VerificationResult select_without_clouds(const std::vector<PoseEstimate>& candidates,
                                         const std::vector<Correspondence>& correspondences,
                                         double bound) {
  VerificationResult r;
  r.scores.assign(candidates.size(), HUGE_VAL);
  r.support.assign(candidates.size(), 0);
  r.support_scores.assign(candidates.size(), HUGE_VAL);
  for (std::size_t l = 0; l < candidates.size(); ++l) {
    const PoseEstimate& e = candidates[l];
    if (!e.valid) continue;
    double S = 0;
    int within = 0;
    for (const Correspondence& c : correspondences) {
      const double residual = std::sqrt(squared_residual(e.T_target_source, c.p, c.q, e.model));
      S += std::min(residual, bound);
      within += residual <= bound;
    }
    r.support_scores[l] = S;
    r.support[l] = within;
    if (r.selected < 0) {
      r.selected = static_cast<int>(l);
      continue;
    }
    const auto best = static_cast<std::size_t>(r.selected);
    const double b = r.support_scores[best];
    const bool tie = std::abs(S - b) <= 1e-9 * std::max(1.0, std::abs(b));
    if ((!tie && S < b) || (tie && e.inliers.size() > candidates[best].inliers.size()))
      r.selected = static_cast<int>(l);
  }
  return r;
}

int same_answer_as(const std::vector<PoseEstimate>& candidates, int level,
                   const std::vector<char>& among, const EvaluationParams& distinct) {
  const PoseEstimate& e = candidates[static_cast<std::size_t>(level)];
  if (!e.valid) return -1;
  for (std::size_t k = 0; k < candidates.size(); ++k)
    if (static_cast<int>(k) != level && k < among.size() && among[k] && candidates[k].valid &&
        pose_error(e.T_target_source, candidates[k].T_target_source, distinct).success)
      return static_cast<int>(k);
  return -1;
}

}  // namespace pagor
