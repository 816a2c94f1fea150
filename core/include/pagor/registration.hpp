#pragma once
/// \file registration.hpp
/// One call for the common case, one result type for all. `register_clouds` and
/// `register_correspondences` run a pair through a `Pipeline` and return a `Registration`: the
/// pose, each pyramid level, the verdict with its tests, the diagnosis against a ground truth,
/// the stage times and the warnings. The JSON report (`to_json`, schema pagor.register/1), the
/// CLI, the studio, the bench rows and the Python module are all written from this one struct.
///
///   pagor::Registration r = pagor::register_clouds(source, target);
///   if (r.accepted()) use(*r.T_target_source);
///   else std::puts(r.acceptance.reason.c_str());
///
/// Poses are in the frames of the points as given (a cloud's `origin` included: a georeferenced
/// file's frame), `T_target_source` mapping source points into the target frame. Use `Pipeline`
/// directly for incremental re-runs (a new threshold re-runs only what it invalidates) and build
/// the same result from it with `make_registration`.

#include <array>
#include <atomic>
#include <optional>
#include <string>
#include <vector>

#include "pagor/config.hpp"
#include "pagor/io/correspondence_file.hpp"
#include "pagor/pipeline.hpp"
#include "pagor/verify/diagnosis.hpp"

namespace pagor {

/// How the selected level was chosen.
enum class SelectedBy {
  score_D,         ///< the lowest D on the clouds ("distrust and verify")
  without_clouds,  ///< the best support among the correspondences (level_selection.hpp)
};
const char* to_string(SelectedBy by);

/// One pyramid level as a registration reports it.
struct LevelSummary {
  double epsilon = 0.0;        ///< TRIM threshold: [m] for `difference`, a ratio for `ratio`
  std::size_t vertices = 0;    ///< correspondences with an edge at this level
  std::size_t edges = 0;       ///< consistency edges at this level
  std::vector<int> clique;     ///< the level's densest clique (correspondence indices), increasing
  bool clique_proven = false;  ///< the clique is proven maximum on its level
  /// upper bound on the level's clique number the search reached (0: none computed)
  int clique_number_bound = 0;
  CliqueBudget clique_budget = CliqueBudget::none;  ///< which budget cut the search short
  CliqueStart clique_start = CliqueStart::cold;     ///< how the level's search started
  double clique_time_ms = 0.0;                      ///< [ms]
  int clique_gradient_steps = 0;
  int clique_penalty_updates = 0;
  /// The level's GNC-TLS candidate; its T_target_source in the frames of the points as given.
  PoseEstimate pose;
  double score_D = 0.0;  ///< D of the candidate [m]; +infinity when invalid or not verified
  /// Selected without clouds: the correspondences the pose explains and their score S [m].
  std::optional<int> support;
  double support_score = 0.0;
  std::optional<PoseError> error;  ///< against the ground truth (nullopt: none, or no pose)
  /// Against a correspondences file's ground-truth inlier flags (nullopt: the file has none).
  std::optional<InlierQuality> file_inliers;
};

/// A correspondences file registered (pagor register --correspondences, the studio's files mode).
struct MatchesFileInfo {
  std::string path;
  bool weighted = false;      ///< the file has a weight column
  std::vector<char> inliers;  ///< its ground-truth inlier flags, one per line (empty: none)
};

/// Each class's landmark count in the two clouds, in the configuration's class order.
struct ClassCount {
  std::string name;
  std::size_t source = 0, target = 0;
  std::size_t correspondences = 0;  ///< putative correspondences of the class
};

/// Whether a verdict that `accepted` a pose trusted a wrong one: its ground truth (`error`,
/// nullopt without one) says the pose misses the criterion. Registration::accepted_wrong and the
/// studio's verdict line both ask this.
inline bool wrong_pose_accepted(bool accepted, const std::optional<PoseError>& error) {
  return accepted && error && !error->success;
}

/// The result of one registration.
struct Registration {
  std::string source_name, target_name;  ///< what the inputs are (files, descriptions)
  /// The selected pose (the verdict's adopted alternative when it took one, acceptance.adopted;
  /// else refined when refinement lowered D), in the frames of the points as given; nullopt when
  /// no level has a valid candidate.
  std::optional<Transform> T_target_source;
  int selected_level = -1;  ///< index into `levels`; -1 when none
  SelectedBy selected_by = SelectedBy::score_D;
  std::vector<LevelSummary> levels;
  /// The verdict: trust the selected pose or not, and why (each test with its value and threshold;
  /// the best distinct alternative, its pose in the frames of the points as given).
  Acceptance acceptance;
  RefinementResult refinement;  ///< what refinement did (its poses in the clouds' own frames)
  PoseModel pose_model_configured = PoseModel::se3, pose_model_used = PoseModel::se3;
  /// With the pose model `automatic` and clouds: the ground planes that decided it.
  std::optional<std::pair<GroundPlane, GroundPlane>> ground_planes;

  // ---- against a ground truth (all empty without one) ----
  std::optional<Transform> T_target_source_gt;  ///< in the frames of the points as given
  std::optional<PoseError> error;               ///< of the selected pose
  std::optional<PoseError> unrefined_error;     ///< of the selected candidate before refinement
  /// some level's candidate, or the selected pose (refined, or adopted), is right
  bool any_level_succeeds = false;
  std::optional<Diagnosis> diagnosis;  ///< the stage at fault (diagnosis.hpp)

  // ---- the front end ----
  std::vector<ClassCount> classes;
  LabelReading source_labels, target_labels;  ///< how each cloud's labels were read
  std::size_t correspondences = 0;            ///< putative correspondences used
  std::size_t correspondence_candidates = 0;  ///< before the cap
  bool correspondences_capped = false;
  OriginCounts origin_all, origin_clique, origin_inliers;  ///< by origin: all, selected clique,
                                                          ///< its pose's inliers
  std::optional<MatchesFileInfo> matches_file;

  // ---- cost and messages ----
  std::array<double, kStageCount> stage_ms{};  ///< wall time of each stage's last run [ms]
  double total_ms = 0.0;                       ///< their sum [ms]
  std::size_t verification_points = 0;         ///< downsampled source points D sums over
  std::vector<std::string> warnings;
  bool pair_time_budget_hit = false;  ///< the clique search stopped at the pair's time budget
  Config config;                      ///< the configuration used

  /// Whether the selected pose is trusted (a pose exists and the verdict accepts it).
  bool accepted() const { return T_target_source.has_value() && acceptance.accepted; }
  /// Whether the selected pose is right against the ground truth (false without one).
  bool succeeded() const { return error && error->success; }
  /// Whether a ground truth called an accepted pose wrong: the one outcome a loop-closing user
  /// cannot afford.
  bool accepted_wrong() const { return wrong_pose_accepted(accepted(), error); }
};

/// One acceptance test as a person reads it: "overlap 0.41 (at least 0.24)", "ambiguity 0.97 (at
/// most 0.85): FAILED", "minimal support: not taken". What the CLI, the studio and the Python
/// module show.
std::string test_text(const AcceptanceTest& test);

/// Options of the one-call functions; every field has a sensible default.
struct RegisterOptions {
  int threads = 1;  ///< threads for the stages that parallelise
  /// The numbering of the clouds' labels in place of the configuration's (nullopt: configured).
  std::optional<LabelScheme> label_scheme;
  /// Known T_target_source in the frames of the points as given: adds errors and a diagnosis.
  std::optional<Transform> ground_truth;
  bool diagnose = true;  ///< run the diagnosis when a ground truth is given
  std::string source_name = "source", target_name = "target";  ///< for the report
  ProgressFn progress;                       ///< stage and overall fraction, as Pipeline::run
  const std::atomic<bool>* cancel = nullptr;  ///< true: stop with Cancelled
};

/// Registers two clouds with `config`. Throws ConfigError for an invalid configuration,
/// InputError for inputs the stages refuse (empty clouds, ...), Cancelled when cancelled.
Registration register_clouds(PointCloud source, PointCloud target,
                             const Config& config = default_config(),
                             const RegisterOptions& options = {});

/// Registers a matcher's correspondences (source point p, target point q [m], weight in
/// `score`): the back end alone; the level is selected without clouds and the verdict says there
/// was nothing to verify on. Throws as register_clouds.
Registration register_correspondences(std::vector<Correspondence> matches,
                                      const Config& config = default_config(),
                                      const RegisterOptions& options = {});

/// The same with clouds to verify on (and, with `correspondences.fuse_matches`, whose landmark
/// correspondences join the matcher's).
Registration register_correspondences(std::vector<Correspondence> matches, PointCloud source,
                                      PointCloud target, const Config& config = default_config(),
                                      const RegisterOptions& options = {});

/// What the report adds to a pipeline's state.
struct RegistrationContext {
  std::string source_name = "source", target_name = "target";
  bool diagnose = true;                        ///< diagnose when the pipeline has a ground truth
  std::optional<MatchesFileInfo> matches_file = std::nullopt;  ///< the correspondences file, when read
};

/// The result of a pipeline that has run (every stage up to date).
Registration make_registration(const Pipeline& pipeline, const RegistrationContext& context = {});

/// The report, schema pagor.register/1 (report.hpp lists its members). `indent` < 0: one line;
/// at most 16 spaces. Without `with_config` the `config` member is left out (bench rows).
std::string to_json(const Registration& registration, int indent = 2, bool with_config = true);

}  // namespace pagor
