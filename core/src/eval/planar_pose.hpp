// The generators' poses in the ground plane (internal to pagor_eval).
#pragma once

#include <Eigen/Geometry>

#include "pagor/types.hpp"

namespace pagor {

/// A turn by `yaw` [rad] about the vertical, then a move to (x, y) [m].
inline Transform planar_pose(double x, double y, double yaw) {
  Transform T = Transform::Identity();
  T.block<3, 3>(0, 0) = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  T(0, 3) = x;
  T(1, 3) = y;
  return T;
}

}  // namespace pagor
