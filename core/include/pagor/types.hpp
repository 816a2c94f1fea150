#pragma once
/// \file types.hpp
/// Plain data types shared by the stages: point clouds, landmarks, correspondences.

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

namespace pagor {

/// A point cloud with optional per-point reflectance and semantic labels.
/// `intensities` and `labels` are either empty or as long as `points`.
/// A label keeps the SemanticKITTI layout: lower 16 bits class id, upper 16 bits instance id.
/// The points are in the cloud's own frame, whose origin lies at `origin` in the frame of its file:
/// a file coordinate is `point + origin`. The origin is zero but for clouds far from their file's
/// origin (georeferenced data: load_cloud, clouds.hpp), whose float32 points would otherwise lose
/// their precision and whose poses would be judged with a lever arm of kilometres.
struct PointCloud {
  std::vector<Eigen::Vector3f> points;  ///< coordinates in the cloud's frame [m]
  std::vector<float> intensities;       ///< reflectance, unitless (empty if absent)
  std::vector<std::uint32_t> labels;    ///< raw labels (empty if absent)
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  ///< the frame's origin in the file's [m]

  std::size_t size() const { return points.size(); }
  bool empty() const { return points.empty(); }
  bool has_labels() const { return !labels.empty(); }
  bool has_intensities() const { return !intensities.empty(); }
};

/// Semantic class id of a raw label (lower 16 bits).
inline std::uint32_t semantic_id(std::uint32_t raw_label) {
  return raw_label & 0xFFFFu;
}

/// How a landmark was made.
enum class LandmarkKind : std::uint8_t {
  cluster,   ///< centroid of a Euclidean cluster of one class
  keypoint,  ///< a downsampled point of a class matched by FPFH descriptors
};

/// A semantic landmark: a cluster centroid or a FPFH keypoint of one configured class.
struct Landmark {
  int class_index = -1;                                  ///< index into the configured class list
  LandmarkKind kind = LandmarkKind::cluster;             ///< how it was made
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();    ///< position [m]
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();  ///< spread of its points [m^2]
  std::size_t point_count = 0;                           ///< points of the input cloud it covers
  std::vector<int> point_indices;  ///< those points' indices in the input cloud
};

/// Where a correspondence comes from.
enum class CorrespondenceOrigin : std::uint8_t {
  landmark,  ///< the front end's: two semantic landmarks of one class
  matcher,   ///< a matcher's (FPFH, FCGF, GeDi, ...), given to the pipeline (set_matches)
};

/// A putative association of a source point with a target point: two landmarks of the same class,
/// or a matcher's pair of keypoints.
struct Correspondence {
  /// configured class both landmarks belong to; -1 for a matcher's correspondence (no class)
  int class_index = -1;
  /// index into the source landmark list (a matcher's: its source keypoint's id); two
  /// correspondences sharing a source or a target id are never consistent
  int source = -1;
  int target = -1;                              ///< index into the target landmark list, likewise
  Eigen::Vector3d p = Eigen::Vector3d::Zero();  ///< source position [m]
  Eigen::Vector3d q = Eigen::Vector3d::Zero();  ///< target position [m]
  /// how promising: landmarks' in [0, 1], used only to rank when capping; a matcher's weight
  /// (non-negative) as given
  double score = 0.0;
  CorrespondenceOrigin origin = CorrespondenceOrigin::landmark;  ///< who made it
};

/// A rigid transform as a 4x4 homogeneous matrix.
using Transform = Eigen::Matrix4d;

}  // namespace pagor
