#pragma once
/// \file gravity.hpp
/// Whether a scan is gravity-aligned: a ground vehicle's (or a tripod's) LiDAR sees its ground as
/// its dominant plane, level in the sensor frame. The pose model
/// `automatic` (gnc.hpp) keeps 4-DoF poses for a pair whose two scans both look level, and fits
/// SE(3) otherwise (a handheld or aerial scan, or one rotated on purpose).

#include "pagor/types.hpp"

namespace pagor {

/// The ground plane of a scan.
struct GroundPlane {
  bool found = false;  ///< a dense, flat layer was found
  /// angle between the plane's normal and the sensor's z axis [deg] (90 when not found)
  double tilt_deg = 90.0;
  double share = 0.0;  ///< fraction of the (sampled) points within 0.15 m of the plane
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< unit normal, z >= 0
};

/// The ground of a scan: its dominant plane, in any orientation (RANSAC with a fixed seed over at
/// most 20000 points, evenly spread; planes within 0.15 m scored on 2000 of them), refitted by
/// principal axes on the points within 0.15 m. A plane holding less than 5 % of the points is no
/// ground (found false). A vehicle's or a tripod's scan is dominated by its ground.
GroundPlane ground_plane(const PointCloud& cloud);

/// Whether two scans are gravity-aligned with each other: both grounds found, each tilted at most
/// `tolerance_deg` and their normals at most `tolerance_deg` apart, so that the rotation between
/// the scans is a yaw to within about that angle.
bool gravity_aligned(const GroundPlane& source, const GroundPlane& target, double tolerance_deg);

}  // namespace pagor
