#pragma once
/// \file landmarks.hpp
/// Semantic landmarks: per configured class, Euclidean clusters of that class's points (their
/// centroids and covariances), or FPFH keypoints for classes marked `fpfh`.

#include <string>
#include <vector>

#include "pagor/front/ground.hpp"
#include "pagor/front/label_detection.hpp"
#include "pagor/front/label_scheme.hpp"
#include "pagor/params.hpp"
#include "pagor/types.hpp"

namespace pagor {

/// What extraction found for one configured class.
struct ClassSummary {
  std::string name;                                 ///< class name
  LandmarkMethod method = LandmarkMethod::cluster;  ///< how its landmarks were made
  std::size_t points = 0;                           ///< input points of this class
  std::size_t voxels = 0;                           ///< after voxel downsampling
  std::size_t landmarks = 0;                        ///< landmarks made
  double spacing = 0.0;            ///< estimated spacing of this class's points [m]
  double voxel_size = 0.0;         ///< voxel used, after spacing adaptation [m]
  double cluster_tolerance = 0.0;  ///< cluster: tolerance used [m]
  int min_points = 0;              ///< cluster: minimum size used [voxels of `voxel_size`]
  /// fpfh: match one way (each source keypoint's nearest target descriptor), at most this many,
  /// instead of mutual nearest; 0: as correspondences.fpfh_mutual says. Set on the class-agnostic
  /// keypoints of a cloud whose labels are not used (FallbackParams::unlabelled_matches).
  int one_way_matches = 0;
  double time_ms = 0.0;  ///< wall time [ms]
};

/// The landmarks of one cloud.
struct LandmarkSet {
  std::vector<Landmark> landmarks;  ///< all classes, grouped by class in configured order
  /// FPFH descriptor (33 values) of each landmark; empty for cluster landmarks.
  std::vector<std::vector<float>> descriptors;
  std::vector<ClassSummary> classes;  ///< one per configured class, in configured order
  LabelReading labels;  ///< the scheme the labels were read with (`auto` resolved), and why
  std::vector<std::string> warnings;  ///< e.g. a class with no points
  double time_ms = 0.0;               ///< total wall time [ms]
};

/// Typical distance between neighbouring points [m]: the median nearest-neighbour distance of an
/// even sample of queries (0 for fewer than two points). Large clouds are thinned to an even
/// subsample of about 16k points first and the distance scaled back by the square root of the
/// thinning factor (surfaces). Clouds voxelised at v give about v.
/// With `subset`, only the points `points[subset[i]]` count.
double estimate_spacing(const std::vector<Eigen::Vector3f>& points,
                        const std::vector<int>* subset = nullptr);

/// A class's parameters as used on a cloud of point spacing `spacing` [m] (see
/// LandmarkParams::adapt_to_spacing); unchanged when adaptation is off or the data is finer.
ClassParams params_for_spacing(const ClassParams& p, double spacing, const LandmarkParams& all);

/// Extracts the landmarks of every configured class. The labels are read as `read_labels` says
/// (`auto`: in the numbering detected for this cloud; kept in `labels`), and a warning says when
/// they do not fit a configured scheme. Centroids and covariances are computed over the voxel
/// means of a cluster, so that the dense near side of an object does not dominate;
/// `point_indices` lists every input point covered. A class with no points gives a warning and no
/// landmarks. A cloud whose labels are absent or not used gives no semantic landmarks and a
/// warning (see the fallback).
LandmarkSet extract_landmarks(const PointCloud& cloud, const LabelScheme& scheme,
                              const LandmarkParams& params);

/// Number of cluster landmarks (the semantic objects) in a set.
std::size_t cluster_landmark_count(const LandmarkSet& set);

/// Height [m] of the top of the ground layer: the upper edge of the most populated 0.2 m height
/// bin among the lower half of the points, plus `thickness` [m]. Assumes z up (ground vehicles).
float ground_layer_top(const std::vector<Eigen::Vector3f>& points, float thickness);

/// Whether a pair needs the class-agnostic landmarks (LandmarkParams::fallback): in `automatic`
/// mode when either cloud's labels are absent or not used (`s.labels`, `t.labels`) or either set
/// is class-poor.
bool needs_fallback(const PointCloud& source, const PointCloud& target, const LandmarkSet& s,
                    const LandmarkSet& t, const FallbackParams& params);

/// Appends the class-agnostic `structure` keypoints of `cloud` to `set` as one more class (index
/// = the number of classes in `set`): FPFH keypoints over every point except the ground (by the
/// ground classes of the scheme the labels were read with, `set.labels`, else by height). `scheme`
/// is the configured one, used only when `set` has no reading (not made by extract_landmarks).
void add_fallback_landmarks(const PointCloud& cloud, const LabelScheme& scheme,
                            const LandmarkParams& params, LandmarkSet& set);

}  // namespace pagor
