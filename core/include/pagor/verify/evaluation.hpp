#pragma once
/// \file evaluation.hpp
/// Errors of an estimated pose against ground truth, and the success criterion.

#include "pagor/params.hpp"
#include "pagor/types.hpp"

namespace pagor {

/// Errors of one pose.
struct PoseError {
  double translation = 0.0;   ///< |t_est - t_gt| [m]
  double rotation_deg = 0.0;  ///< angle of R_gt^T R_est [deg]
  bool success = false;       ///< both within the criterion
};

/// Yaw, pitch and roll of a rotation [deg]: Z-Y-X Euler angles (R = Rz(yaw) Ry(pitch) Rx(roll))
/// in the branch with |pitch| <= 90 deg.
Eigen::Vector3d yaw_pitch_roll_deg(const Eigen::Matrix3d& R);

/// Compares an estimate with the truth under `criterion` (default 2 m / 5 deg).
PoseError pose_error(const Transform& estimate, const Transform& truth,
                     const EvaluationParams& criterion = {});

}  // namespace pagor
