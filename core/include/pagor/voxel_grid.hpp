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
/// A voxel size <= 0 keeps every point as its own voxel. Voxels are cells of the global lattice
/// (multiples of `voxel_size`), keyed relative to the cloud's lowest cell, so a cloud far from the
/// origin (georeferenced) is binned as finely as one near it and far-apart points never merge.
/// Throws InputError when a lattice index would exceed 2^52 or a coordinate is not finite.
VoxelDownsample voxel_downsample(const std::vector<Eigen::Vector3f>& points, double voxel_size,
                                 const std::vector<int>* subset = nullptr);

}  // namespace pagor
