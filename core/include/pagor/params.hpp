#pragma once
/// \file params.hpp
/// Every stage's parameters, in pipeline order: what a user tunes. Each parameter struct lists
/// its fields once, in `fields()` (util/fields.hpp): key, meaning, unit, valid range, default;
/// `check()` holds the rules between fields. The reader, writer and checks of a configuration
/// (config.hpp), `pagor config --describe`, docs/config.md and the studio's editor all follow
/// those tables. The stages themselves (front/, graph/, pose/, verify/, indoor/) take these
/// structs; each section below names its stage's header.

#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "pagor/util/fields.hpp"

namespace pagor {

// -------------------- Landmarks (front/landmarks.hpp)

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

// -------------------- Correspondences (front/correspondences.hpp)

/// Correspondence generation.
struct CorrespondenceParams {
  // Each field's meaning, unit and valid range: fields() below (docs/config.md).
  int max_correspondences = 1500;
  bool fpfh_mutual = true;
  int fpfh_max_per_class = 300;
  double fpfh_ratio = 1.0;
  double shape_scale = 0.5;
  bool fuse_matches = false;

  template <class V>
  static void fields(V&& v) {
    v(&CorrespondenceParams::max_correspondences,
      {"max_correspondences",
       "Cap on the number of correspondences; the most promising are kept; 0: no cap.", "",
       Range::closed(1, 1e7), 0.0, true});
    v(&CorrespondenceParams::fpfh_mutual,
      {"fpfh_mutual", "FPFH classes: keep only mutual nearest descriptors."});
    v(&CorrespondenceParams::fpfh_max_per_class,
      {"fpfh_max_per_class", "FPFH classes: at most this many matches per class, best first.", "",
       Range::closed(1, 1e6)});
    v(&CorrespondenceParams::fpfh_ratio,
      {"fpfh_ratio",
       "FPFH classes: keep a match only when its descriptor distance is at most this fraction of "
       "the second nearest's (ratio test); 1: no test.",
       "", Range::above(0, 1)});
    v(&CorrespondenceParams::shape_scale,
      {"shape_scale",
       "Ranking of cluster pairs: extents differing by this much score e^-1 of alike ones.", "m",
       Range::above(0, 100)});
    v(&CorrespondenceParams::fuse_matches,
      {"fuse_matches",
       "With a matcher's correspondences and clouds: keep the landmark correspondences too, both "
       "in one pyramid (false: the matcher's replace them)."});
  }
};

// -------------------- The pyramid of consistency graphs (graph/pyramid_graph.hpp)

/// Translation-and-rotation-invariant measurement between two correspondences.
enum class TrimKind {
  difference,  ///< | |p_i - p_j| - |q_i - q_j| |  [m], indoor
  ratio,       ///< max(a/b, b/a) - 1 with a, b the two lengths [unitless], outdoor
};
inline constexpr EnumEntry<TrimKind> kTrimKinds[] = {
    {TrimKind::difference, "difference", "| |p_i - p_j| - |q_i - q_j| | in metres (indoor)"},
    {TrimKind::ratio, "ratio", "max(a/b, b/a) - 1 of the two lengths, unitless (outdoor)"},
};
inline const auto& enum_entries(TrimKind) {
  return kTrimKinds;
}

/// Edge weights of the consistency graph.
enum class AffinityKind {
  binary,    ///< 1 for every consistent pair
  gaussian,  ///< exp(-c^2 / (2 sigma^2)) with sigma = sigma_ratio * epsilon of the level
};
inline constexpr EnumEntry<AffinityKind> kAffinityKinds[] = {
    {AffinityKind::binary, "binary", "1 for every consistent pair"},
    {AffinityKind::gaussian, "gaussian",
     "exp(-c^2 / (2 sigma^2)) with sigma = sigma_ratio * the level's epsilon"},
};
inline const auto& enum_entries(AffinityKind) {
  return kAffinityKinds;
}

/// The pyramid of consistency graphs.
struct GraphParams {
  // Each field's meaning, unit and valid range: fields() below (docs/config.md).
  TrimKind trim = TrimKind::ratio;
  std::vector<double> thresholds{0.02, 0.04, 0.08,
                                 0.16};  ///< epsilon_1 < ... < epsilon_k [TRIM unit]
  AffinityKind affinity = AffinityKind::binary;
  double sigma_ratio = 0.5;
  double min_length = 0.5;

  /// Most levels a pyramid may have.
  static constexpr std::size_t kMaxLevels = 32;

  template <class V>
  static void fields(V&& v) {
    v(&GraphParams::trim, {"trim", "The consistency measure: length ratio or length difference."});
    v(&GraphParams::thresholds,
      {"thresholds",
       "The pyramid's epsilon_1 < ... < epsilon_k, one level each (1 to 32): metres for the "
       "difference TRIM, unitless for the ratio.",
       "trim", Range::above(0, 1000), std::numeric_limits<double>::quiet_NaN(), true});
    v(&GraphParams::affinity, {"affinity", "Edge weights: binary or Gaussian in the TRIM."});
    v(&GraphParams::sigma_ratio,
      {"sigma_ratio", "Gaussian: sigma as a fraction of epsilon.", "", Range::above(0, 100)});
    v(&GraphParams::min_length,
      {"min_length", "Pairs of landmarks closer than this are never consistent.", "m",
       Range::closed(0, 1000)});
  }
  template <class C>
  static void check(const GraphParams& p, C& c) {
    c.require(!p.thresholds.empty() && p.thresholds.size() <= kMaxLevels, "thresholds",
              "needs 1 to 32 levels");
    for (std::size_t i = 1; i < p.thresholds.size(); ++i)
      c.require(p.thresholds[i] > p.thresholds[i - 1], "thresholds[" + std::to_string(i) + "]",
                "thresholds must increase strictly");
  }
};

// -------------------- Each level's densest clique (graph/densest_clique.hpp)

/// Which densest-clique solver.
enum class CliqueSolver {
  cascaded,     ///< CLIPPER relaxation, each level warm-started from the previous one (Alg. 1)
  independent,  ///< CLIPPER relaxation, each level from the same initial vector
  exact,        ///< exact maximum clique (branch and bound)
};
inline constexpr EnumEntry<CliqueSolver> kCliqueSolvers[] = {
    {CliqueSolver::cascaded, "cascaded",
     "CLIPPER relaxation, each level warm-started from the previous one (Alg. 1)"},
    {CliqueSolver::independent, "independent",
     "CLIPPER relaxation, each level from the same initial vector"},
    {CliqueSolver::exact, "exact", "exact maximum clique by branch and bound"},
};
inline const auto& enum_entries(CliqueSolver) {
  return kCliqueSolvers;
}

/// The densest-clique solver (CLIPPER relaxation) and the exact search.
struct CliqueParams {
  // Each field's meaning, unit and valid range: fields() below (docs/config.md).
  CliqueSolver solver = CliqueSolver::cascaded;
  bool prune = true;
  bool prove_first = true;
  long prove_first_min_edges = 3000;
  double tol_u = 1e-8;
  double tol_F = 1e-9;
  int max_inner_iterations = 200;
  int max_outer_iterations = 1000;
  double beta = 0.25;
  int max_line_search = 99;
  double eps = 1e-9;
  double support_tol = 1e-6;
  std::uint64_t seed = 42;
  double warm_start_mix = 0.05;
  double warm_start_penalty = 1.0;
  long exact_max_nodes = 20000000;
  double exact_time_budget_ms = 1000.0;
  int greedy_starts = 4;
  int max_swaps = 64;
  double pair_time_budget_ms = 10000.0;
  bool cascade_fallback = true;
  long cascade_check_nodes = 200000;
  double max_step = 1e6;
  bool settle_selected = true;
  long probe_nodes = 20000;

  template <class V>
  static void fields(V&& v) {
    v(&CliqueParams::solver, {"solver", "The densest-clique solver."});
    v(&CliqueParams::prune,
      {"prune",
       "Relax on the k-core that can hold a clique as large as a greedy one, and never return "
       "less than the greedy clique."});
    v(&CliqueParams::prove_first,
      {"prove_first",
       "Binary affinity: first try to prove the lower bound's clique maximum (on a dense level by "
       "a colouring seeded by that clique, then) by a bounded exact search (cascade_check_nodes); "
       "when that succeeds the relaxation is skipped. Off: the relaxation always runs (the "
       "paper's Alg. 1)."});
    v(&CliqueParams::prove_first_min_edges,
      {"prove_first_min_edges",
       "prove_first applies to levels with at least this many edges; on smaller graphs the "
       "relaxation is cheap and its choice among equal-size cliques is kept.",
       "", Range::closed(0, 1e12)});
    v(&CliqueParams::tol_u, {"tol_u", "The gradient ascent stops when u moves less than this.", "",
                             Range::above(0, 1), std::numeric_limits<double>::quiet_NaN(), true});
    v(&CliqueParams::tol_F,
      {"tol_F", "The gradient ascent stops when the objective changes less than this.", "",
       Range::above(0, 1), std::numeric_limits<double>::quiet_NaN(), true});
    v(&CliqueParams::max_inner_iterations,
      {"max_inner_iterations", "Gradient steps for one penalty d, at most.", "",
       Range::closed(1, 100000)});
    v(&CliqueParams::max_outer_iterations,
      {"max_outer_iterations", "Penalty increases, at most.", "", Range::closed(1, 100000)});
    v(&CliqueParams::beta,
      {"beta", "Backtracking line search: step reduction factor.", "", Range::open(0, 1)});
    v(&CliqueParams::max_line_search,
      {"max_line_search", "Backtracking steps per gradient step, at most.", "",
       Range::closed(1, 1000)});
    v(&CliqueParams::eps, {"eps", "Numerical zero of the relaxation.", "", Range::above(0, 1),
                           std::numeric_limits<double>::quiet_NaN(), true});
    v(&CliqueParams::support_tol,
      {"support_tol", "Entries of u below this fraction of the largest count as zero.", "",
       Range::below(0, 1)});
    v(&CliqueParams::seed, {"seed", "Seed of the relaxation's initial vector."});
    v(&CliqueParams::warm_start_mix,
      {"warm_start_mix", "Cascaded: weight of the random start mixed into a warm start.", "",
       Range::closed(0, 1000)});
    v(&CliqueParams::warm_start_penalty,
      {"warm_start_penalty",
       "Cascaded: a warm-started level begins with this fraction of the previous level's final "
       "penalty d (1: where it stopped; 0: from d = 0).",
       "", Range::closed(0, 1)});
    v(&CliqueParams::exact_max_nodes,
      {"exact_max_nodes",
       "Exact solver: branch-and-bound nodes over all levels, at most (a node whose reductions do "
       "the work of several counts as several).",
       "", Range::closed(1, 1e10), std::numeric_limits<double>::quiet_NaN(), true});
    v(&CliqueParams::exact_time_budget_ms,
      {"exact_time_budget_ms",
       "Exact solver: wall time of all levels, at most (a level may use what earlier ones left); "
       "the best clique found is returned, marked not proven, with the bound reached; 0: none.",
       "ms", Range::closed(1, 3.6e6), 0.0, true});
    v(&CliqueParams::greedy_starts,
      {"greedy_starts",
       "Greedy cliques grown from the highest cores for the pruning's bound (prove_first's search "
       "on a warm level starts from the previous level's clique grown instead; the relaxation "
       "still grows them).",
       "", Range::closed(1, 1000)});
    v(&CliqueParams::max_swaps,
      {"max_swaps", "Improving swaps (one member out, two in) tried on the rounded clique.", "",
       Range::closed(0, 100000)});
    v(&CliqueParams::pair_time_budget_ms,
      {"pair_time_budget_ms",
       "Wall time one registration may take up to the end of its clique step, from the start of "
       "the run; the clique search gets what is left (settling the selected level gets what the "
       "clique stage left), and when it runs out each unfinished level keeps the best clique "
       "found so far (its budget reads 'time'); 0: none.",
       "ms", Range::closed(1, 3.6e6), 0.0, true});
    v(&CliqueParams::cascade_fallback,
      {"cascade_fallback",
       "Cascaded: a warm-started level whose clique its check (a colouring, then the search of "
       "cascade_check_nodes) does not prove maximum is also solved from the cold start; the "
       "larger clique is kept (start 'fallback' when it wins)."});
    v(&CliqueParams::cascade_check_nodes,
      {"cascade_check_nodes",
       "Cascaded: node budget of the exact search for a larger clique that ends each "
       "warm-started level (a node whose reductions do the work of several counts as several); "
       "0: no search.",
       "", Range::closed(0, 1e10), std::numeric_limits<double>::quiet_NaN(), true});
    v(&CliqueParams::max_step,
      {"max_step", "The largest gradient step tried; beyond it a step only renormalises.", "",
       Range::above(0, 1e12), std::numeric_limits<double>::quiet_NaN(), true});
    v(&CliqueParams::settle_selected,
      {"settle_selected",
       "Cascaded: spend the relaxation of a level its bounded proof cannot settle, the full "
       "search (cascade_check_nodes) and the cold-start fallback only where they decide the "
       "result. A first pass gives each level's bounded searches probe_nodes, up to the first "
       "level they leave unproven: that level keeps their clique (improved by swaps), with no "
       "relaxation and no fallback, and the levels above it (denser graphs holding its) get the "
       "colouring's proof alone. The "
       "level the selection picks, if unsettled and its pose not the same answer as a settled "
       "level's (acceptance.distinct_*: a heuristic, settling would seldom change that answer), "
       "then takes the relaxation, and if still selected the search and the fallback, as the "
       "full cascade gives a level; the selection is re-run whenever its clique grows. Off: every "
       "level gets them (the paper preset)."});
    v(&CliqueParams::probe_nodes,
      {"probe_nodes",
       "settle_selected: node budget of each bounded search in the first pass (the proof of a "
       "level's lower bound, the search after its relaxation), up to the first level left "
       "unproven; a level left unproven has budget 'probe' unless it is selected and settled. "
       "Also the budget of the search for the largest clique through the pair's unique "
       "landmarks (an alternative the verdict weighs).",
       "", Range::closed(0, 1e10), std::numeric_limits<double>::quiet_NaN(), true});
  }
};

// -------------------- Poses by GNC-TLS (pose/gnc.hpp)

/// The pose model.
enum class PoseModel {
  se3,       ///< rotation and translation in 3D (outdoor)
  se2,       ///< yaw and planar translation (planar robots, scan vs floor plan)
  four_dof,  ///< yaw and 3-D translation, roll and pitch held level (ground vehicles, as Quatro)
  /// SE(3) and 4-DoF both fitted; 4-DoF kept where it explains the correspondences as well (as
  /// many inliers), else SE(3): any rotation, and level poses where the data is gravity-aligned
  automatic,
};
inline constexpr EnumEntry<PoseModel> kPoseModels[] = {
    {PoseModel::se3, "se3", "rotation and translation in 3-D"},
    {PoseModel::se2, "se2", "yaw and planar translation (planar robots, scan vs floor plan)"},
    {PoseModel::four_dof, "four_dof",
     "yaw and 3-D translation, roll and pitch held level (ground vehicles)"},
    {PoseModel::automatic, "auto",
     "fit SE(3) and 4-DoF; keep 4-DoF where it has as many inliers (gravity-aligned data), else "
     "SE(3)"},
};
inline const auto& enum_entries(PoseModel) {
  return kPoseModels;
}

/// GNC with a truncated least-squares cost.
struct GncParams {
  // Each field's meaning, unit and valid range: fields() below (docs/config.md).
  PoseModel model = PoseModel::se3;
  double noise_bound = 1.0;
  double mu_factor = 1.4;
  int max_iterations = 100;
  double cost_tolerance = 1e-6;
  double level_tolerance = 5.0;

  template <class V>
  static void fields(V&& v) {
    v(&GncParams::model, {"model", "The pose model."});
    v(&GncParams::noise_bound, {"noise_bound", "TLS truncation: residuals beyond it are outliers.",
                                "m", Range::above(0, 1000)});
    v(&GncParams::mu_factor, {"mu_factor", "GNC continuation factor.", "", Range::above(1, 100)});
    v(&GncParams::max_iterations,
      {"max_iterations", "GNC iterations, at most.", "", Range::closed(1, 10000)});
    v(&GncParams::cost_tolerance,
      {"cost_tolerance", "GNC stops when the TLS cost changes less than this.", "m^2",
       Range::above(0, 1e6), std::numeric_limits<double>::quiet_NaN(), true});
    v(&GncParams::level_tolerance,
      {"level_tolerance",
       "Model auto with clouds: when both scans' ground plane is within this angle of level, the "
       "pair is gravity-aligned and its poses are 4-DoF; otherwise each level keeps 4-DoF only "
       "where it has as many inliers as SE(3).",
       "deg", Range::closed(0, 90)});
  }
};

// -------------------- Verification on the dense clouds (verify/verification.hpp)

/// How a candidate pose is scored on the dense clouds.
enum class ScoreKind {
  truncated,  ///< D = sum min(d, mu) (default, "distrust and verify")
  trimmed,    ///< D = sum of d over d < mu (ablation)
  nearest,    ///< D = sum d (ablation)
};
inline constexpr EnumEntry<ScoreKind> kScoreKinds[] = {
    {ScoreKind::truncated, "truncated", "D = sum min(d, mu) (\"distrust and verify\")"},
    {ScoreKind::trimmed, "trimmed", "D = sum of d over d < mu (ablation)"},
    {ScoreKind::nearest, "nearest", "D = sum d (ablation)"},
};
inline const auto& enum_entries(ScoreKind) {
  return kScoreKinds;
}

/// Geometric verification on the metric clouds.
struct VerificationParams {
  // Each field's meaning, unit and valid range: fields() below (docs/config.md).
  double voxel_size = 0.5;
  double mu = 1.0;
  ScoreKind score = ScoreKind::truncated;

  template <class V>
  static void fields(V&& v) {
    v(&VerificationParams::voxel_size,
      {"voxel_size", "Downsampling of both clouds before scoring; 0: none.", "m",
       Range::closed(1e-3, 100), 0.0, true});
    v(&VerificationParams::mu,
      {"mu", "Truncation distance of D = sum min(|Tp - q_nn|, mu).", "m", Range::above(0, 1000),
       std::numeric_limits<double>::quiet_NaN(), true});
    v(&VerificationParams::score, {"score", "How a candidate is scored on the dense clouds."});
  }
};

// -------------------- Refinement of the selected pose (verify/refinement.hpp)

/// Optional fine alignment of the selected pose on the metric clouds.
struct RefinementParams {
  // Each field's meaning, unit and valid range: fields() below (docs/config.md).
  bool enabled = true;
  int max_iterations = 20;
  int max_points = 1000;
  double max_distance = 1.0;
  double min_distance = 0.3;
  double robust_scale = 0.2;
  double normal_radius = 1.0;
  double max_translation = 2.0;
  double max_rotation = 5.0;
  bool free_roll_pitch = true;

  template <class V>
  static void fields(V&& v) {
    v(&RefinementParams::enabled,
      {"enabled", "Refine the selected pose by ICP (kept only when it lowers D)."});
    v(&RefinementParams::max_iterations,
      {"max_iterations", "ICP iterations, at most.", "", Range::closed(1, 1000)});
    v(&RefinementParams::max_points,
      {"max_points", "Source points used, spread evenly over the verification's cloud.", "",
       Range::closed(10, 1e6)});
    v(&RefinementParams::max_distance,
      {"max_distance",
       "Pairing distance of the first iteration; it shrinks to min_distance over the first half.",
       "m", Range::above(0, 1000)});
    v(&RefinementParams::min_distance,
      {"min_distance", "Pairing distance of the later iterations.", "m", Range::above(0, 1000)});
    v(&RefinementParams::robust_scale,
      {"robust_scale", "Cauchy scale of the point-to-plane residuals.", "m",
       Range::above(0, 1000)});
    v(&RefinementParams::normal_radius,
      {"normal_radius", "Neighbourhood of the target normals.", "m", Range::above(0, 100)});
    v(&RefinementParams::max_translation,
      {"max_translation", "A refinement that moves the pose farther is rejected.", "m",
       Range::above(0, 1e4)});
    v(&RefinementParams::max_rotation,
      {"max_rotation", "A refinement that turns the pose more is rejected.", "deg",
       Range::above(0, 180)});
    v(&RefinementParams::free_roll_pitch,
      {"free_roll_pitch",
       "Refine roll and pitch too when the pose model holds them level (4-DoF)."});
  }
  template <class C>
  static void check(const RefinementParams& p, C& c) {
    c.require(p.max_distance >= p.min_distance, "max_distance",
              "must be >= refinement.min_distance [m]");
  }
};

// -------------------- The success criterion (verify/evaluation.hpp)

/// Success criterion against ground truth.
struct EvaluationParams {
  // Each field's meaning, unit and valid range: fields() below (docs/config.md).
  double max_translation_error = 2.0;
  double max_rotation_error = 5.0;

  template <class V>
  static void fields(V&& v) {
    v(&EvaluationParams::max_translation_error,
      {"max_translation_error", "A pose within this translation error of the truth is right.", "m",
       Range::above(0, 1e6)});
    v(&EvaluationParams::max_rotation_error,
      {"max_rotation_error", "A pose within this rotation error of the truth is right.", "deg",
       Range::above(0, 180)});
  }
};

// -------------------- The verdict (verify/acceptance.hpp)

/// Whether the selected pose is trusted.
struct AcceptanceParams {
  // Each field's meaning, unit and valid range: fields() below (docs/config.md).
  double inlier_distance = 0.5;
  double ground_thickness = 0.4;
  // least fraction of structure points aligned, in [0, 1]; calibrated on the shared data with
  // refinement on: true pairs 0.27-0.61, scans that share nothing 0.03-0.20
  double min_overlap = 0.24;
  int min_inliers = 2;
  double minimal_support_overlap = 0.3;
  // least D margin to a distinct candidate, fraction of mu * points; calibrated on the shared
  // data: true pairs 0.18-1 (1: no distinct candidate), scans that share nothing 0.02-0.05
  double min_margin = 0.1;
  // least sharpness: the share of the overlap a shift of distinct_translation
  // along a horizontal axis loses (Acceptance::sharpness). Measured with refinement on: right
  // poses 0.17-0.55 (KITTI 0.36-0.43, semreg-dev with and without labels 0.17-0.55); wrong poses
  // that reach the overlap threshold 0.01-0.07 (a street that slides along itself, hedges)
  double min_sharpness = 0.1;
  double max_ambiguity = 0.55;
  double ambiguity_range = 40.0;
  bool adopt_alternative = true;
  double adopt_max_ambiguity = 0.55;
  double distinct_translation = 2.0;
  double distinct_rotation = 5.0;

  /// What the verdict counts as another answer: poses apart by more than this.
  EvaluationParams distinct() const { return {distinct_translation, distinct_rotation}; }

  /// The ratio above which the ambiguity's alternative is refitted and judged in place of the
  /// selection (adopt_alternative): 1 / adopt_max_ambiguity squared, never below 1.
  double adoption_bar() const {
    return std::max(1.0, 1.0 / (adopt_max_ambiguity * adopt_max_ambiguity));
  }
  /// The ambiguity threshold an adopted alternative's refit is judged at.
  double adopted_max_ambiguity() const { return std::min(max_ambiguity, adopt_max_ambiguity); }

  template <class V>
  static void fields(V&& v) {
    v(&AcceptanceParams::inlier_distance,
      {"inlier_distance", "A verification point counts as aligned within this distance.", "m",
       Range::above(0, 1000)});
    v(&AcceptanceParams::ground_thickness,
      {"ground_thickness", "Points this far above the ground layer are structure.", "m",
       Range::closed(0, 100)});
    v(&AcceptanceParams::min_overlap,
      {"min_overlap", "The least fraction of structure points aligned under the pose.", "",
       Range::closed(0, 1)});
    v(&AcceptanceParams::min_inliers,
      {"min_inliers", "The least GNC inliers of the selected candidate.", "",
       Range::closed(0, 1e6)});
    v(&AcceptanceParams::minimal_support_overlap,
      {"minimal_support_overlap",
       "The least overlap when the pose rests on the minimal number of inliers.", "",
       Range::closed(0, 1)});
    v(&AcceptanceParams::min_sharpness,
      {"min_sharpness",
       "The least share of the overlap lost when the pose is moved by distinct_translation "
       "translation along a horizontal axis.",
       "", Range::closed(-1000, 1)});
    v(&AcceptanceParams::min_margin,
      {"min_margin",
       "The least D margin to the best distinct candidate, as a fraction of mu times the points.",
       "", Range::closed(0, 1)});
    v(&AcceptanceParams::max_ambiguity,
      {"max_ambiguity",
       "The largest ratio of points only a distinct alternative pose aligns (another level's, the "
       "pose turned 180 degrees, moved by a repetition of the scene, the pose a class seen once "
       "on each side fixes) to points only the selected pose aligns, 10 added to each; 10 or "
       "more: off. The indoor preset takes 0.8: against a floor plan, which shows the whole "
       "building, a rival is weighed on all the scan's evidence.",
       "", Range::closed(0, 1e6)});
    v(&AcceptanceParams::distinct_translation,
      {"distinct_translation",
       "Two poses farther apart than this are distinct answers: the margin's runner-up, the "
       "sharpness test's shift, the ambiguity's alternatives, and (clique.settle_selected) "
       "whether a settled level already gives the selected level's answer.",
       "m", Range::above(0, 1e6)});
    v(&AcceptanceParams::distinct_rotation,
      {"distinct_rotation", "Two poses turned further apart than this are distinct answers.", "deg",
       Range::above(0, 180)});
    v(&AcceptanceParams::ambiguity_range,
      {"ambiguity_range", "The furthest shift searched for a repetition along each principal axis.",
       "m", Range::closed(0, 1e4)});
    v(&AcceptanceParams::adopt_alternative,
      {"adopt_alternative",
       "Where the ambiguity's best alternative fits decisively better than the selected pose "
       "(its ratio above 1 / adopt_max_ambiguity squared), refit it by GNC to the correspondences "
       "it explains and judge it as the selection; it becomes the pose when that verdict accepts "
       "it. D counts a point the target "
       "never saw as unexplained, so a pose that slides a corridor's whole view onto the "
       "target's beats the true one, which leaves part of the source beyond the target's range "
       "and aligns the objects that fix it. Off in the paper preset."});
    v(&AcceptanceParams::adopt_max_ambiguity,
      {"adopt_max_ambiguity",
       "adopt_alternative: the ambiguity test's threshold for overturning the selection, which "
       "asks the evidence to be decisive twice over: the alternative is refitted and judged "
       "where its ratio exceeds 1 / adopt_max_ambiguity squared (and 1), and the refitted pose "
       "must then pass the ambiguity test at the lower of this and max_ambiguity. It does not "
       "follow max_ambiguity: on the generated car parks, max_ambiguity 0.7 with the adoption "
       "at that threshold adopted wrong half turns (seeds 11 and 34). At 1 the bar is a ratio "
       "above 1 and the refit is judged at max_ambiguity: the most permissive, not off (off: "
       "adopt_alternative false).",
       "", Range::above(0, 1)});
  }
};

// -------------------- Indoor: the column detector (indoor/column_detector.hpp)

/// The column detector: 2-D clusters of the projected scan whose extent and circle fit match a
/// column.
struct ColumnDetectorParams {
  // Each field's meaning, unit and valid range: fields() below (docs/config.md).
  double cluster_tolerance = 0.15;
  double min_radius = 0.2;
  double max_radius = 0.45;
  double max_rms = 0.03;
  int min_points = 6;
  double min_arc_deg = 60.0;

  template <class V>
  static void fields(V&& v) {
    v(&ColumnDetectorParams::cluster_tolerance,
      {"cluster_tolerance", "The largest gap between points of one cluster.", "m",
       Range::above(0, 10)});
    v(&ColumnDetectorParams::min_radius,
      {"min_radius", "The smallest fitted radius accepted.", "m", Range::above(0, 100)});
    v(&ColumnDetectorParams::max_radius,
      {"max_radius", "The largest fitted radius accepted.", "m", Range::above(0, 100)});
    v(&ColumnDetectorParams::max_rms,
      {"max_rms", "The largest RMS distance of the points to the fitted circle.", "m",
       Range::above(0, 10)});
    v(&ColumnDetectorParams::min_points,
      {"min_points", "The least points of a cluster (cells of the floor grid).", "",
       Range::closed(3, 1e6)});
    v(&ColumnDetectorParams::min_arc_deg,
      {"min_arc_deg", "The least angle the points cover around the centre.", "deg",
       Range::closed(0, 360)});
  }
  template <class C>
  static void check(const ColumnDetectorParams& p, C& c) {
    c.require(p.max_radius > p.min_radius, "max_radius", "must be > min_radius [m]");
  }
};

// -------------------- Indoor: scans against floor plans (indoor/floor_projection.hpp)

/// Indoor re-localization against a floor plan (floor_plan.hpp): the plan is sampled into points
/// and the scan is projected to the floor plane with its columns found. Applies when a pair's
/// target is a floor plan (`.json` or `.svg`).
struct IndoorParams {
  // Each field's meaning, unit and valid range: fields() below (docs/config.md).
  double plan_spacing = 0.05;
  double height_min = -0.3;
  double height_max = 1.9;
  double floor_voxel = 0.05;
  double furniture_gap = 1.0;
  bool detect_columns = true;
  ColumnDetectorParams columns;

  template <class V>
  static void fields(V&& v) {
    v(&IndoorParams::plan_spacing, {"plan_spacing", "Sampling of plan walls and column outlines.",
                                    "m", Range::closed(1e-3, 10)});
    v(&IndoorParams::height_min,
      {"height_min", "Scan points lower than this (scan frame, z up) are left out.", "m",
       Range::closed(-1000, 1000)});
    v(&IndoorParams::height_max, {"height_max", "Scan points higher than this are left out.", "m",
                                  Range::closed(-1000, 1000)});
    v(&IndoorParams::floor_voxel,
      {"floor_voxel", "The 2-D grid of the projected scan.", "m", Range::closed(1e-3, 10)});
    v(&IndoorParams::furniture_gap,
      {"furniture_gap",
       "A scan point is on furniture (a car, a person: lower than the walls, in no plan) when a "
       "higher beam of about its azimuth returned from at least this much further. A projected "
       "cell all of whose points are is labelled furniture: against the floor plan, acceptance's "
       "ambiguity test counts it for no pose, and against a pose that puts it on a wall or "
       "column. Needs the scan in its sensor's frame; 0: off.",
       "m", Range::closed(0, 1000)});
    v(&IndoorParams::detect_columns,
      {"detect_columns",
       "Find columns with the detector; off: take them from the scan's labels (indoor scheme)."});
    v(&IndoorParams::columns, {"columns", "The column detector."});
  }
  template <class C>
  static void check(const IndoorParams& p, C& c) {
    c.require(p.height_max > p.height_min, "height_max", "must be > height_min [m]");
  }
};

}  // namespace pagor
