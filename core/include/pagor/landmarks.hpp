#pragma once
/// \file landmarks.hpp
/// Semantic landmarks: per configured class, Euclidean clusters of that class's points (their
/// centroids and covariances), or FPFH keypoints for classes marked `fpfh`.

#include <string>
#include <vector>

#include "pagor/config.hpp"
#include "pagor/types.hpp"

namespace pagor {

/// What extraction found for one configured class.
struct ClassSummary {
  std::string name;                                 ///< class name
  LandmarkMethod method = LandmarkMethod::cluster;  ///< how its landmarks were made
  std::size_t points = 0;                           ///< input points of this class
  std::size_t voxels = 0;                           ///< after voxel downsampling
  std::size_t landmarks = 0;                        ///< landmarks made
  double time_ms = 0.0;                             ///< wall time [ms]
};

/// The landmarks of one cloud.
struct LandmarkSet {
  std::vector<Landmark> landmarks;  ///< all classes, grouped by class in configured order
  /// FPFH descriptor (33 values) of each landmark; empty for cluster landmarks.
  std::vector<std::vector<float>> descriptors;
  std::vector<ClassSummary> classes;  ///< one per configured class, in configured order
  std::vector<std::string> warnings;  ///< e.g. a class with no points
  double time_ms = 0.0;               ///< total wall time [ms]
};

/// Extracts the landmarks of every configured class. Centroids and covariances are computed over
/// the voxel means of a cluster, so that the dense near side of an object does not dominate;
/// `point_indices` lists every input point covered. A class with no points gives a warning and no
/// landmarks. Throws InputError when the cloud has no labels.
LandmarkSet extract_landmarks(const PointCloud& cloud, const LabelScheme& scheme,
                              const LandmarkParams& params);

}  // namespace pagor
