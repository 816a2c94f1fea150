#pragma once
/// \file gnc.hpp
/// Pose from correspondences by graduated non-convexity (GNC) with a truncated least-squares (TLS)
/// cost: min_T sum_i min(|T p_i - q_i|^2, c^2), solved as a sequence of weighted least-squares
/// problems whose weights go from the convex surrogate (mu -> 0) to the TLS cost (mu -> inf).

#include <string>
#include <vector>

#include "pagor/params.hpp"
#include "pagor/types.hpp"

namespace pagor {

/// The fewest correspondences that fix a pose of the model: 3 in SE(3), 2 in SE(2) and 4-DoF (and
/// with `automatic`, whose 4-DoF fit needs 2).
inline int minimal_sample_size(PoseModel model) {
  return model == PoseModel::se3 ? 3 : 2;
}

/// A candidate pose.
struct PoseEstimate {
  bool valid = false;  ///< false: too few or degenerate correspondences
  Transform T_target_source = Transform::Identity();  ///< maps source points into the target frame
  std::vector<int> inliers;  ///< indices (into the input lists) with residual <= noise bound
  int iterations = 0;        ///< GNC iterations run
  /// the model the pose was fitted in: the configured one, or for `automatic` the one kept
  /// (se3 or four_dof)
  PoseModel model = PoseModel::se3;
  std::string failure;   ///< why it is invalid
  double time_ms = 0.0;  ///< wall time [ms]
};

/// Weighted least-squares rigid transform (Horn/Umeyama without scale) mapping `src` onto `dst`.
/// In SE(2) only x, y and yaw are estimated (z translation 0); in 4-DoF yaw and x, y, z (roll and
/// pitch held level). Returns false when the weighted points are degenerate (fewer than 3
/// non-collinear in SE(3); fewer than 2 distinct in the x-y plane for SE(2) and 4-DoF).
bool weighted_rigid_transform(const std::vector<Eigen::Vector3d>& src,
                              const std::vector<Eigen::Vector3d>& dst,
                              const std::vector<double>& weights, PoseModel model, Transform& T);

/// GNC-TLS. `src` and `dst` have the same length. In SE(2), residuals are measured in the x-y
/// plane (in 4-DoF in 3-D). Fewer than 3 correspondences (2 in SE(2) and 4-DoF), or a degenerate
/// set, gives an invalid estimate. With `PoseModel::automatic` both SE(3) and 4-DoF are fitted and
/// the 4-DoF pose is kept when it has at least as many inliers as the SE(3) one (or SE(3) has no
/// valid pose); the estimate's `model` says which.
PoseEstimate estimate_pose_gnc(const std::vector<Eigen::Vector3d>& src,
                               const std::vector<Eigen::Vector3d>& dst,
                               const GncParams& params = {});

/// estimate_pose_gnc on the correspondences `members` indexes (a level's clique): the estimate's
/// inliers are indices into `correspondences`.
PoseEstimate estimate_pose_gnc(const std::vector<Correspondence>& correspondences,
                               const std::vector<int>& members, const GncParams& params = {});

/// The squared residual of correspondence (p, q) under T, as GNC measures it: |T p - q|^2, in the
/// x-y plane alone in SE(2) [m^2].
double squared_residual(const Transform& T, const Eigen::Vector3d& p, const Eigen::Vector3d& q,
                        PoseModel model);

/// Rotation angle of a rotation matrix [deg].
double rotation_angle_deg(const Eigen::Matrix3d& R);

}  // namespace pagor
