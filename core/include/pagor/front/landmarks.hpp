#pragma once
/// \file landmarks.hpp
/// Semantic landmarks: per configured class, Euclidean clusters of that class's points (their
/// centroids and covariances), or FPFH keypoints for classes marked `fpfh`.

#include <string>
#include <vector>

#include "pagor/front/ground.hpp"
#include "pagor/front/label_detection.hpp"
#include "pagor/front/label_scheme.hpp"
#include "pagor/types.hpp"
#include "pagor/util/fields.hpp"

namespace pagor {

/// How a class becomes landmarks.
enum class LandmarkMethod { cluster, fpfh };
inline constexpr EnumEntry<LandmarkMethod> kLandmarkMethods[] = {
    {LandmarkMethod::cluster, "cluster",
     "Euclidean clusters of the class; a landmark per centroid"},
    {LandmarkMethod::fpfh, "fpfh", "FPFH keypoints of the class, matched by their descriptors"},
};
inline const auto& enum_entries(LandmarkMethod) {
  return kLandmarkMethods;
}

/// Landmark extraction for one semantic class.
struct ClassParams {
  // Each field's meaning, unit and valid range: fields() below (docs/config.md).
  std::string name;
  LandmarkMethod method = LandmarkMethod::cluster;
  double voxel_size = 0.2;
  double cluster_tolerance = 0.5;
  int min_points = 10;
  int max_points = 5000;
  double normal_radius = 1.0;
  double feature_radius = 2.5;
  int max_keypoints = 1500;

  template <class V>
  static void fields(V&& v) {
    v(&ClassParams::name, {"name", "Class name in the label scheme."});
    v(&ClassParams::method, {"method", "How the class becomes landmarks: clusters or FPFH."});
    v(&ClassParams::voxel_size,
      {"voxel_size", "Downsampling voxel before clustering or FPFH; 0: none.", "m",
       Range::closed(1e-3, 50), 0.0, true});
    v(&ClassParams::cluster_tolerance,
      {"cluster_tolerance", "Clusters: the largest gap between points of one cluster.", "m",
       Range::above(0, 50)});
    v(&ClassParams::min_points,
      {"min_points", "Clusters: the smallest cluster kept, in voxels.", "", Range::closed(1, 1e7)});
    v(&ClassParams::max_points,
      {"max_points", "Clusters: the largest cluster kept, in voxels.", "", Range::closed(1, 1e8)});
    v(&ClassParams::normal_radius,
      {"normal_radius", "FPFH: radius of the normal estimate.", "m", Range::above(0, 50)});
    v(&ClassParams::feature_radius,
      {"feature_radius", "FPFH: radius of the descriptor; larger than normal_radius.", "m",
       Range::above(0, 100)});
    v(&ClassParams::max_keypoints,
      {"max_keypoints",
       "FPFH: descriptors are computed at no more than this many voxels, spread evenly (normals "
       "and descriptors still see every voxel).",
       "", Range::closed(1, 1e6)});
  }
  template <class C>
  static void check(const ClassParams& p, C& c) {
    c.require(p.max_points >= p.min_points, "max_points", "must be >= min_points");
    c.require(p.feature_radius > p.normal_radius, "feature_radius",
              "must be larger than normal_radius [m]");
  }
};

/// When class-agnostic landmarks (FPFH keypoints on all non-ground structure, one extra class
/// `structure`) are added: for class-poor scenes and clouds without labels.
enum class FallbackMode { automatic, always, never };
inline constexpr EnumEntry<FallbackMode> kFallbackModes[] = {
    {FallbackMode::automatic, "automatic",
     "when either cloud has no labels or is class-poor (class_poor_below)"},
    {FallbackMode::always, "always", "always add the class-agnostic landmarks"},
    {FallbackMode::never, "never", "never (an unlabelled cloud is then an error)"},
};
inline const auto& enum_entries(FallbackMode) {
  return kFallbackModes;
}

/// The class-agnostic keypoints' defaults: FPFH on a 0.8 m grid, radii 1.6 / 4.0 m, descriptors
/// at 1000 keypoints (9/10 of semreg-dev at voxels 0.4, 0.6 and 0.8 m alike with this budget,
/// bench/README.md).
ClassParams default_structure_keypoints();

/// Class-agnostic landmarks for class-poor scenes and for clouds without labels.
struct FallbackParams {
  // Each field's meaning, unit and valid range: fields() below (docs/config.md).
  FallbackMode mode = FallbackMode::automatic;
  // automatic: a cloud with fewer cluster landmarks (cars, trunks, poles, ...) than this is
  // class-poor. Measured on semreg-dev, where every scene has 0-11.
  int class_poor_below = 15;
  /// Classes that count as ground and are left out (ignored when the scheme lacks them).
  std::vector<std::string> ground_classes{"road", "parking", "sidewalk", "other-ground", "terrain"};
  double ground_height = 0.4;
  double ground_cell = 2.0;
  double ground_slope = 0.3;
  ClassParams keypoints = default_structure_keypoints();
  // A cloud whose labels are not used: descriptors at no more than this many keypoints (they are
  // all the evidence there is). Measured on semreg-dev without labels: 9/10 at 1500 and 2000,
  // 9/10 with one right pose rejected at 1000; with labels, 1500 loses a pair (08).
  int unlabelled_keypoints = 1500;
  // A pair of which a cloud's labels are not used: the keypoints are matched one way (each source
  // keypoint's nearest target descriptor), at most this many; 0: as with labels (mutual nearest,
  // correspondences.fpfh_max_per_class). Without labels, mutual matching keeps 3-34 true of
  // 50-110 matches on semreg-dev, one way 18-123 of 650-1300, which the pyramid sorts out.
  int unlabelled_matches = 1500;

  template <class V>
  static void fields(V&& v) {
    v(&FallbackParams::mode, {"mode", "When to add the class-agnostic landmarks."});
    v(&FallbackParams::class_poor_below,
      {"class_poor_below",
       "automatic: a cloud with fewer cluster landmarks (cars, trunks, poles, ...) than this is "
       "class-poor.",
       "", Range::closed(0, 1e6)});
    v(&FallbackParams::ground_classes,
      {"ground_classes",
       "Classes that count as ground and are left out (ignored when the scheme lacks them)."});
    v(&FallbackParams::ground_height,
      {"ground_height",
       "Clouds without labels: points this far above the ground surface are not ground.", "m",
       Range::closed(0, 10)});
    v(&FallbackParams::ground_cell,
      {"ground_cell",
       "Clouds without labels: the horizontal grid of the ground surface, which follows each "
       "cell's lowest points.",
       "m", Range::closed(0.1, 100)});
    v(&FallbackParams::ground_slope,
      {"ground_slope",
       "Clouds without labels: the steepest rise of the ground surface between cells; steeper is "
       "an object (wall, car, bush).",
       "m/m", Range::closed(0, 10)});
    v(&FallbackParams::keypoints, {"keypoints", "The class-agnostic FPFH class `structure`."});
    v(&FallbackParams::unlabelled_keypoints,
      {"unlabelled_keypoints",
       "A cloud whose labels are not used: descriptors at no more than this many keypoints.", "",
       Range::closed(1, 1e6)});
    v(&FallbackParams::unlabelled_matches,
      {"unlabelled_matches",
       "A pair with a cloud whose labels are not used: keypoints matched one way (each source "
       "keypoint's nearest descriptor), at most this many; 0: mutual, as with labels.",
       "", Range::closed(1, 1e6), 0.0});
  }
  template <class C>
  static void check(const FallbackParams& p, C& c) {
    c.require(p.keypoints.voxel_size > 0, "keypoints.voxel_size", "must be > 0 [m]");
  }
};

/// Landmark extraction, one entry per class.
struct LandmarkParams {
  // Each field's meaning, unit and valid range: fields() below (docs/config.md).
  std::vector<ClassParams> classes;
  bool adapt_to_spacing = true;
  double tolerance_spacings = 2.5;
  int min_cluster_voxels = 3;
  FallbackParams fallback;

  template <class V>
  static void fields(V&& v) {
    v(&LandmarkParams::classes, {"classes", "One entry per landmark class."});
    v(&LandmarkParams::adapt_to_spacing,
      {"adapt_to_spacing",
       "Keep each class's parameters physical on the cloud's point spacing: voxels never finer "
       "than the data, cluster tolerances at least tolerance_spacings spacings, cluster sizes "
       "rescaled."});
    v(&LandmarkParams::tolerance_spacings,
      {"tolerance_spacings", "The least cluster tolerance, in point spacings.", "",
       Range::above(0, 100)});
    v(&LandmarkParams::min_cluster_voxels,
      {"min_cluster_voxels", "Rescaled minimum cluster sizes never drop below this [voxels].", "",
       Range::closed(1, 1e6)});
    v(&LandmarkParams::fallback, {"fallback", "Class-agnostic landmarks."});
  }
  template <class C>
  static void check(const LandmarkParams& p, C& c) {
    c.require(!p.classes.empty(), "classes", "needs at least one class");
  }
};

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
