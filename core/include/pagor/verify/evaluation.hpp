#pragma once
/// \file evaluation.hpp
/// Errors of an estimated pose against ground truth, and the success criterion.

#include "pagor/types.hpp"
#include "pagor/util/fields.hpp"

namespace pagor {

/// Success criterion against ground truth.
struct EvaluationParams {
  // Each field's meaning, unit and valid range: fields() below (docs/config.md).
  double max_translation_error = 2.0;
  double max_rotation_error = 5.0;

  template <class V>
  static void fields(V&& v) {
    v(&EvaluationParams::max_translation_error,
      {"max_translation_error", "A pose within this translation error of the truth is right.", "m",
       Range::above(0, 1e6)});
    v(&EvaluationParams::max_rotation_error,
      {"max_rotation_error", "A pose within this rotation error of the truth is right.", "deg",
       Range::above(0, 180)});
  }
};

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
