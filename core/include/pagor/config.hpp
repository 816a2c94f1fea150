#pragma once
/// \file config.hpp
/// Every parameter of every stage, in one document. Defaults are those of the paper's outdoor
/// (KITTI) experiments. `pagor config --print-default` prints them as JSON.

#include <cstdint>
#include <string>
#include <vector>

#include "pagor/label_scheme.hpp"

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
};

/// Landmark extraction, one entry per class.
struct LandmarkParams {
  std::vector<ClassParams> classes;  ///< defaults: car, trunk, pole (clusters), building (fpfh)
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
  se3,  ///< rotation and translation in 3D (outdoor)
  se2,  ///< yaw and planar translation (planar robots, scan vs floor plan)
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

/// Success criterion against ground truth.
struct EvaluationParams {
  double max_translation_error = 2.0;  ///< [m]
  double max_rotation_error = 5.0;     ///< [deg]
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
  EvaluationParams evaluation;
};

/// The paper's outdoor defaults.
Config default_config();

/// Parses a JSON document. Keys that are absent keep their defaults. Unknown keys, wrong types
/// and invalid values throw ConfigError naming `origin` and the key path (e.g.
/// `graph.thresholds[2]`).
Config parse_config(const std::string& json_text, const std::string& origin = "config");

/// Reads and parses a JSON file. Throws InputError (unreadable) or ConfigError.
Config load_config(const std::string& path);

/// Serialises every parameter as JSON.
std::string config_to_json(const Config& config, int indent = 2);

/// One section (`label_scheme`, `landmarks`, `correspondences`, `graph`, `clique`, `gnc`,
/// `verification`, `evaluation`) as compact JSON; two configs agree on a section iff these are
/// equal. The pipeline uses it to find what a change invalidates.
std::string section_json(const Config& config, const std::string& section);

/// Checks values (ranges, orders, class names). Throws ConfigError naming the key path.
void validate(const Config& config, const std::string& origin = "config");

/// Names of the enum values, as written in JSON.
const char* to_string(LandmarkMethod v);
const char* to_string(TrimKind v);
const char* to_string(AffinityKind v);
const char* to_string(CliqueSolver v);
const char* to_string(PoseModel v);
const char* to_string(ScoreKind v);

}  // namespace pagor
