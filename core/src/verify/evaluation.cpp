#include "pagor/verify/evaluation.hpp"

#include <algorithm>
#include <cmath>

#include "pagor/pose/gnc.hpp"

namespace pagor {

Eigen::Vector3d yaw_pitch_roll_deg(const Eigen::Matrix3d& R) {
  constexpr double kRadToDeg = 180.0 / 3.14159265358979323846;
  const double pitch = std::asin(std::clamp(-R(2, 0), -1.0, 1.0));
  const double yaw = std::atan2(R(1, 0), R(0, 0));
  const double roll = std::atan2(R(2, 1), R(2, 2));
  return Eigen::Vector3d(yaw, pitch, roll) * kRadToDeg;
}

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
