#pragma once
// Internal to landmark extraction: Euclidean clusters, surface normals and FPFH descriptors of a
// voxelised point set, with neighbours from a RadiusGrid. They compute what PCL's
// EuclideanClusterExtraction, NormalEstimation and FPFHEstimation compute (tests/
// point_features_test.cpp compares them), with the grid in place of FLANN's kd-tree and each
// pair's FPFH features computed once for both of its points.

#include <Eigen/Core>
#include <array>
#include <vector>

namespace pagor::detail {

/// Connected components of "closer than `tolerance`" [m] with `min_size` to `max_size` points,
/// largest first (ties: by smallest member), each as sorted point indices.
std::vector<std::vector<int>> euclidean_clusters(const std::vector<Eigen::Vector3f>& points,
                                                 double tolerance, int min_size, int max_size);

/// Unit normal per point from the covariance of its neighbours closer than `radius` [m], turned
/// towards the origin; NaN where fewer than 3 neighbours.
std::vector<Eigen::Vector3f> estimate_normals(const std::vector<Eigen::Vector3f>& points,
                                              double radius);

/// An angle in the same one of FPFH's 11 angle bins as std::atan2(y, x) [rad]: a polynomial
/// where the angle is clear of a bin edge, atan2 itself near an edge, with NaN or at (0, 0).
float binnable_atan2(float y, float x);

/// FPFH descriptor (11 + 11 + 11 bins) at each point `keypoints[k]`, over neighbours closer than
/// `radius` [m]; NaN normals are handled as PCL does.
using Fpfh = std::array<float, 33>;
std::vector<Fpfh> compute_fpfh(const std::vector<Eigen::Vector3f>& points,
                               const std::vector<Eigen::Vector3f>& normals,
                               const std::vector<int>& keypoints, double radius);

}  // namespace pagor::detail
