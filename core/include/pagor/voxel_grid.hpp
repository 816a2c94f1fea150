#pragma once
/// \file voxel_grid.hpp
/// Voxel downsampling that remembers which voxel every input point fell into.

#include <Eigen/Core>
#include <vector>

namespace pagor {

/// Result of voxel downsampling.
struct VoxelDownsample {
  std::vector<Eigen::Vector3f>
      points;                 ///< one point per occupied voxel: the mean of its points [m]
  std::vector<int> counts;    ///< input points per voxel
  std::vector<int> voxel_of;  ///< per input point (or per subset entry): its voxel index
};

/// Downsamples `points` (or only `points[subset[i]]` when `subset` is given) on a grid of
/// `voxel_size` [m]. Voxels come out in order of first appearance, so the result is deterministic.
/// A voxel size <= 0 keeps every point as its own voxel. The grid starts at the corner of the
/// points' bounding box, so moving all points by an offset moves the voxel means by it.
/// Throws InputError when the cloud spans more than 2^52 voxels per axis or has a non-finite
/// coordinate.
VoxelDownsample voxel_downsample(const std::vector<Eigen::Vector3f>& points, double voxel_size,
                                 const std::vector<int>* subset = nullptr);

}  // namespace pagor
