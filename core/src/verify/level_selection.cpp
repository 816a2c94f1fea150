#include "pagor/verify/level_selection.hpp"

#include <cmath>

namespace pagor {

VerificationResult select_without_clouds(const std::vector<PoseEstimate>& candidates) {
  VerificationResult r;
  r.scores.assign(candidates.size(), HUGE_VAL);
  for (std::size_t l = 0; l < candidates.size(); ++l) {
    if (!candidates[l].valid) continue;
    if (r.selected < 0 || candidates[l].inliers.size() >
                              candidates[static_cast<std::size_t>(r.selected)].inliers.size())
      r.selected = static_cast<int>(l);
  }
  return r;
}

}  // namespace pagor
