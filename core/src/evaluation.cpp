#include "pagor/evaluation.hpp"

#include "pagor/gnc.hpp"

namespace pagor {

PoseError pose_error(const Transform& estimate, const Transform& truth,
                     const EvaluationParams& criterion) {
  PoseError e;
  e.translation = (estimate.block<3, 1>(0, 3) - truth.block<3, 1>(0, 3)).norm();
  e.rotation_deg =
      rotation_angle_deg(truth.block<3, 3>(0, 0).transpose() * estimate.block<3, 3>(0, 0));
  e.success = e.translation < criterion.max_translation_error &&
              e.rotation_deg < criterion.max_rotation_error;
  return e;
}

}  // namespace pagor
