#pragma once
/// \file config.hpp
/// Every parameter of every stage, in one document. Defaults are those of the paper's outdoor
/// (KITTI) experiments. `pagor config --print-default` prints them as JSON.

#include <cstdint>
#include <string>
#include <vector>

#include "pagor/front/label_scheme.hpp"

namespace pagor {

/// How a class becomes landmarks.
enum class LandmarkMethod { cluster, fpfh };

/// Landmark extraction for one semantic class.
struct ClassParams {
  std::string name;                                 ///< class name in the label scheme
  LandmarkMethod method = LandmarkMethod::cluster;  ///< clusters, or FPFH keypoints
  double voxel_size = 0.2;         ///< downsampling voxel before clustering or FPFH [m]; 0 = none
  double cluster_tolerance = 0.5;  ///< cluster: max gap between points of one cluster [m]
  int min_points = 10;             ///< cluster: smallest cluster kept [voxels]
  int max_points = 5000;           ///< cluster: largest cluster kept [voxels]
  double normal_radius = 1.0;      ///< fpfh: radius of the normal estimate [m]
  double feature_radius = 2.5;     ///< fpfh: radius of the FPFH descriptor [m]
  /// fpfh: budget of keypoints. Normals and descriptors see every voxel; descriptors are computed
  /// at no more than this many voxels, spread evenly (one per cell of a coarser grid).
  int max_keypoints = 1500;
};

/// Class-agnostic landmarks for class-poor scenes and for clouds without labels: FPFH keypoints on
/// all non-ground structure, as one extra class `structure`.
enum class FallbackMode {
  automatic,  ///< when either cloud has no labels or is class-poor (`class_poor_below`)
  always,     ///< always add the class-agnostic landmarks
  never,      ///< never (an unlabelled cloud is then an error)
};
struct FallbackParams {
  FallbackMode mode = FallbackMode::automatic;  ///< when to add class-agnostic landmarks
  /// automatic: a cloud with fewer cluster landmarks (cars, trunks, poles, ...) than this is
  /// class-poor. Measured on semreg-dev, where every scene has 0-11.
  int class_poor_below = 15;
  /// Classes that count as ground and are left out (ignored when the scheme lacks them). Without
  /// labels, points within `ground_height` of the lowest dense height layer are left out instead.
  std::vector<std::string> ground_classes{"road", "parking", "sidewalk", "other-ground", "terrain"};
  double ground_height = 0.4;  ///< unlabelled: thickness of the removed ground layer [m]
  /// FPFH on a 0.8 m grid, radii 1.6 / 4.0 m, descriptors at 1000 keypoints: 9/10 of semreg-dev
  /// at voxels 0.4, 0.6 and 0.8 m alike with this budget (bench/README.md).
  ClassParams keypoints{"structure", LandmarkMethod::fpfh, 0.8, 0.5, 10, 5000, 1.6, 4.0, 1000};
};

/// Landmark extraction, one entry per class.
struct LandmarkParams {
  /// Defaults: car, trunk, pole, traffic-sign (clusters); building (fpfh).
  std::vector<ClassParams> classes;
  /// Estimate each cloud's point spacing s and keep every class's parameters physical on it:
  /// voxels never finer than s, cluster tolerances at least `tolerance_spacings` * s, and
  /// minimum/maximum cluster sizes (counted in voxels of the configured size) rescaled to the
  /// coarser voxel, so a downsampled cloud gives the landmarks of the full-resolution one.
  bool adapt_to_spacing = true;
  double tolerance_spacings = 2.5;  ///< least cluster tolerance, in point spacings
  int min_cluster_voxels = 3;       ///< rescaled minimum sizes never drop below this [voxels]
  FallbackParams fallback;          ///< class-agnostic landmarks
};

/// Correspondence generation.
struct CorrespondenceParams {
  int max_correspondences = 1500;  ///< cap on the total; the most promising are kept; 0 = no cap
  bool fpfh_mutual = true;         ///< fpfh classes: keep only mutual nearest descriptors
  int fpfh_max_per_class = 300;    ///< fpfh classes: at most this many matches (best first)
  double shape_scale = 0.5;        ///< ranking of cluster pairs: extents differing by this much [m]
                                   ///< score e^-1
};

/// Translation-and-rotation-invariant measurement between two correspondences.
enum class TrimKind {
  difference,  ///< | |p_i - p_j| - |q_i - q_j| |  [m], indoor
  ratio,       ///< max(a/b, b/a) - 1 with a, b the two lengths [unitless], outdoor
};
/// Edge weights of the consistency graph.
enum class AffinityKind {
  binary,    ///< 1 for every consistent pair
  gaussian,  ///< exp(-c^2 / (2 sigma^2)) with sigma = sigma_ratio * epsilon of the level
};

/// The pyramid of consistency graphs.
struct GraphParams {
  TrimKind trim = TrimKind::ratio;  ///< TRIM kind
  std::vector<double> thresholds{0.02, 0.04, 0.08,
                                 0.16};          ///< epsilon_1 < ... < epsilon_k [TRIM unit]
  AffinityKind affinity = AffinityKind::binary;  ///< edge weights
  double sigma_ratio = 0.5;  ///< gaussian: sigma as a fraction of the level's epsilon
  double min_length = 0.5;   ///< pairs of landmarks closer than this are never consistent [m]
};

/// Which densest-clique solver.
enum class CliqueSolver {
  cascaded,     ///< CLIPPER relaxation, each level warm-started from the previous one (Alg. 1)
  independent,  ///< CLIPPER relaxation, each level from the same initial vector
  exact,        ///< exact maximum clique (branch and bound; ~10 ms on the KITTI pairs)
};

/// The densest-clique solver (CLIPPER relaxation).
struct CliqueParams {
  CliqueSolver solver = CliqueSolver::cascaded;  ///< solver
  /// Relaxation on the k-core that can hold a clique at least as large as a greedy one (with
  /// k = greedy size - 1), and never return less than the greedy clique. Off: the plain relaxation
  /// on every vertex.
  bool prune = true;
  double tol_u = 1e-8;              ///< inner loop stops when |u_new - u| < tol_u
  double tol_F = 1e-9;              ///< inner loop stops when the objective changes less
  int max_inner_iterations = 200;   ///< gradient steps for one penalty d
  int max_outer_iterations = 1000;  ///< penalty increases
  double beta = 0.25;               ///< backtracking step reduction, in (0, 1)
  int max_line_search = 99;         ///< backtracking steps per gradient step
  double eps = 1e-9;                ///< numerical zero
  double support_tol = 1e-6;        ///< entries below this fraction of the largest count as zero
  std::uint64_t seed = 42;          ///< seed of the initial vector
  double warm_start_mix = 0.05;     ///< cascaded: weight of the random start added to a warm start
  /// cascaded: a warm-started level begins with this fraction of the previous level's final
  /// penalty d (1: continue where the previous level stopped; 0: from d = 0).
  double warm_start_penalty = 1.0;
  long exact_max_nodes = 20000000;  ///< exact: branch-and-bound node budget
};

/// The pose model.
enum class PoseModel {
  se3,       ///< rotation and translation in 3D (outdoor)
  se2,       ///< yaw and planar translation (planar robots, scan vs floor plan)
  four_dof,  ///< yaw and 3-D translation, roll and pitch held level (ground vehicles, as Quatro)
};

/// GNC with a truncated least-squares cost.
struct GncParams {
  PoseModel model = PoseModel::se3;  ///< SE(3) or SE(2)
  double noise_bound = 1.0;          ///< TLS truncation: residuals beyond are outliers [m]
  double mu_factor = 1.4;            ///< GNC continuation factor, > 1
  int max_iterations = 100;          ///< GNC iterations
  double cost_tolerance = 1e-6;      ///< stop when the TLS cost changes less [m^2]
};

/// How a candidate pose is scored on the dense clouds.
enum class ScoreKind {
  truncated,  ///< D = sum min(d, mu) (default, "distrust and verify")
  trimmed,    ///< D = sum of d over d < mu (ablation)
  nearest,    ///< D = sum d (ablation)
};

/// Geometric verification on the metric clouds.
struct VerificationParams {
  double voxel_size = 0.5;                 ///< downsampling of both clouds [m]
  double mu = 1.0;                         ///< truncation distance [m]
  ScoreKind score = ScoreKind::truncated;  ///< scoring
};

/// Whether the selected pose is trusted (see acceptance.hpp).
struct AcceptanceParams {
  double inlier_distance = 0.5;   ///< a verification point counts as aligned within this [m]
  double ground_thickness = 0.4;  ///< points this far above the ground layer are structure [m]
  /// least fraction of structure points aligned, in [0, 1]; calibrated on the shared data with
  /// refinement on: true pairs 0.27-0.61, scans that share nothing 0.03-0.20
  double min_overlap = 0.24;
  int min_inliers = 2;  ///< least GNC inliers of the selected candidate
  /// least overlap when the pose rests on the minimal number of inliers (2 for 4-DoF and SE(2),
  /// 3 for SE(3)): such a pose has no redundant support, so the clouds must say more
  double minimal_support_overlap = 0.3;
  /// least D margin to a distinct candidate, fraction of mu * points; calibrated on the shared
  /// data: true pairs 0.18-1 (1: no distinct candidate), scans that share nothing 0.02-0.05
  double min_margin = 0.1;
};

/// Optional fine alignment of the selected pose on the metric clouds (see refinement.hpp).
struct RefinementParams {
  bool enabled = true;      ///< refine the selected pose (kept only when it lowers D)
  int max_iterations = 20;  ///< ICP iterations at most
  int max_points = 1000;    ///< source points used, spread evenly over the verification's cloud
  /// pairing distance of the first iteration [m]; it shrinks linearly to `min_distance` over the
  /// first half of the iterations
  double max_distance = 1.0;
  double min_distance = 0.3;     ///< pairing distance of the later iterations [m]
  double robust_scale = 0.2;     ///< Cauchy scale of the point-to-plane residuals [m]
  double normal_radius = 1.0;    ///< neighbourhood of the target normals [m]
  double max_translation = 2.0;  ///< a refinement moving the pose farther is rejected [m]
  double max_rotation = 5.0;     ///< or turning it more [deg]
  /// refine roll and pitch too when the pose model holds them level (4-DoF): two scans of a
  /// ground vehicle are level only to a few degrees, and the dense clouds (the ground above all)
  /// constrain roll and pitch well. SE(2) poses stay planar.
  bool free_roll_pitch = true;
};

/// Success criterion against ground truth.
struct EvaluationParams {
  double max_translation_error = 2.0;  ///< [m]
  double max_rotation_error = 5.0;     ///< [deg]
};

/// The column detector for indoor scans (column_detector.hpp): 2-D clusters of the projected scan
/// whose extent and circle fit match a column.
struct ColumnDetectorParams {
  double cluster_tolerance = 0.15;  ///< max gap between points of one cluster [m]
  double min_radius = 0.2;          ///< smallest fitted radius accepted [m]
  double max_radius = 0.45;         ///< largest fitted radius accepted [m]
  double max_rms = 0.03;            ///< largest RMS distance of the points to the fitted circle [m]
  int min_points = 6;               ///< least points of a cluster (cells of the floor grid)
  double min_arc_deg = 60.0;        ///< least angle the points cover around the centre [deg]
};

/// Indoor re-localization against a floor plan (floor_plan.hpp, floor_projection.hpp). Applies
/// when a pair's target is a floor plan (`.json` or `.svg`): the plan is sampled into points and
/// the scan is projected to the floor plane with its columns found.
struct IndoorParams {
  double plan_spacing = 0.05;  ///< sampling of plan walls and column outlines [m]
  double height_min = -0.3;    ///< scan points lower than this (scan frame, z up) are left out [m]
  double height_max = 1.9;     ///< scan points higher than this are left out [m]
  double floor_voxel = 0.05;   ///< 2-D grid of the projected scan [m]
  /// Find columns with the detector; false: take them from the scan's labels (`indoor` ids,
  /// column 2), fitting a circle to each labelled cluster.
  bool detect_columns = true;
  ColumnDetectorParams columns;  ///< the detector
};

/// The whole configuration.
struct Config {
  LabelScheme label_scheme;  ///< default: semantickitti-train
  LandmarkParams landmarks;
  CorrespondenceParams correspondences;
  GraphParams graph;
  CliqueParams clique;
  GncParams gnc;
  VerificationParams verification;
  RefinementParams refinement;
  AcceptanceParams acceptance;
  EvaluationParams evaluation;
  IndoorParams indoor;  ///< scans against floor plans
};

/// The project's outdoor defaults: the paper's method with what measurement on the shared data
/// showed to be better (README, "Presets"): 4-DoF poses, point-spacing adaptation, traffic signs,
/// class-agnostic keypoints for class-poor or unlabelled pairs.
Config default_config();

/// A named configuration: `default` (default_config()) or `paper` (the published outdoor
/// configuration exactly: car, trunk, pole clusters and building FPFH at the configured voxel
/// sizes, ratio TRIM 0.02/0.04/0.08/0.16, SE(3), truncated D with mu = 1 m, no spacing
/// adaptation, no class-agnostic keypoints, no refinement) or `indoor` (a scan against a floor
/// plan, as the paper's car park: columns as landmarks, difference TRIM 0.05..0.25 m, SE(2),
/// success 1 m / 3 deg). Throws ConfigError listing the names.
Config preset_config(const std::string& name);

/// Names of the presets.
std::vector<std::string> preset_names();

/// Parses a JSON document. Keys that are absent keep the values of the preset named by the
/// top-level key `preset` (a string), else of `base_preset`. Unknown keys, wrong types and invalid
/// values throw ConfigError naming `origin` and the key path (e.g. `graph.thresholds[2]`).
Config parse_config(const std::string& json_text, const std::string& origin = "config",
                    const std::string& base_preset = "default");

/// Reads and parses a JSON file. Throws InputError (unreadable) or ConfigError.
Config load_config(const std::string& path, const std::string& base_preset = "default");

/// Serialises every parameter as JSON.
std::string config_to_json(const Config& config, int indent = 2);

/// One section (`label_scheme`, `landmarks`, `correspondences`, `graph`, `clique`, `gnc`,
/// `verification`, `acceptance`, `evaluation`, `indoor`) as compact JSON; two configs agree on a
/// section iff these are equal. The pipeline uses it to find what a change invalidates.
std::string section_json(const Config& config, const std::string& section);

/// Checks values (ranges, orders, class names). Throws ConfigError naming the key path.
void validate(const Config& config, const std::string& origin = "config");

/// Names of the enum values, as written in JSON.
const char* to_string(LandmarkMethod v);
const char* to_string(FallbackMode v);
const char* to_string(TrimKind v);
const char* to_string(AffinityKind v);
const char* to_string(CliqueSolver v);
const char* to_string(PoseModel v);
const char* to_string(ScoreKind v);

}  // namespace pagor
