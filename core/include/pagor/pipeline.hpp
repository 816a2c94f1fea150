#pragma once
/// \file pipeline.hpp
/// The whole method with caching: the pipeline owns the inputs and every stage's output, and a
/// change recomputes only what it invalidates (a new mu re-scores; a new threshold rebuilds the
/// graph and what follows; a new clustering parameter re-runs everything). Each stage reports its
/// wall time and how often it ran. One thread at a time may use a Pipeline; `run` can report
/// progress and be cancelled from another thread through an atomic flag.
///
/// Inputs: two clouds (set_input), a matcher's correspondences (set_matches), or both. With
/// matches and no clouds only the back end runs (graph, clique, pose), the level is selected
/// without clouds (level_selection.hpp) and the acceptance says there was nothing to verify on.
/// With both, the matches replace the landmark correspondences (or join them when
/// `correspondences.fuse_matches`) and verification, refinement and acceptance run as usual.

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "pagor/config.hpp"
#include "pagor/front/correspondences.hpp"
#include "pagor/front/landmarks.hpp"
#include "pagor/graph/densest_clique.hpp"
#include "pagor/graph/pyramid_graph.hpp"
#include "pagor/pose/gnc.hpp"
#include "pagor/pose/gravity.hpp"
#include "pagor/types.hpp"
#include "pagor/verify/acceptance.hpp"
#include "pagor/verify/evaluation.hpp"
#include "pagor/verify/refinement.hpp"
#include "pagor/verify/verification.hpp"

namespace pagor {

/// The stages, in the order they run.
enum class Stage : int {
  landmarks,          ///< landmarks of both clouds
  correspondences,    ///< putative correspondences
  graph,              ///< pyramid of consistency graphs
  clique,             ///< densest clique per level
  gnc,                ///< GNC-TLS pose per level
  verification_prep,  ///< downsampled metric clouds and target kd-tree
  verification,       ///< score D per candidate, selection
  refinement,         ///< optional fine alignment of the selected pose (kept if D drops)
  acceptance,         ///< whether the selected pose is trusted
  evaluation,         ///< errors against ground truth
};
constexpr int kStageCount = 10;

/// Lower-case name of a stage, as in timings.
const char* stage_name(Stage stage);

/// Progress callback: the stage about to run and the overall fraction done, in [0, 1].
using ProgressFn = std::function<void(Stage stage, double fraction)>;

class Pipeline {
 public:
  /// `threads` is used by the stages that parallelise (the two clouds' landmarks, graph
  /// construction, verification, refinement, acceptance); the results do not depend on it.
  explicit Pipeline(Config config = default_config(), int threads = 1);

  /// Sets both clouds; every stage becomes stale. `label_scheme`, when given, is the numbering of
  /// these clouds' labels in place of the configuration's (a manifest's `scheme=`; `none`: labels
  /// not used); it stays with the input.
  void set_input(PointCloud source, PointCloud target,
                 std::optional<LabelScheme> label_scheme = std::nullopt);
  /// Sets a matcher's correspondences (source point p, target point q [m], weight in `score`), or
  /// clears them with an empty vector. The pipeline tags each CorrespondenceOrigin::matcher with
  /// class_index -1; a negative source or target id becomes the correspondence's position (ids
  /// name keypoints: two correspondences sharing one are never consistent). The stages from the
  /// correspondences on become stale (from the landmarks on when the mode changes).
  void set_matches(std::vector<Correspondence> matches);
  /// Sets or clears the ground truth; only the evaluation becomes stale.
  void set_ground_truth(std::optional<Transform> T_target_source);
  /// Validates and applies a configuration; the stages it affects become stale.
  /// Throws ConfigError (the current configuration is kept).
  void set_config(const Config& config);
  void set_threads(int threads) { threads_ = threads < 1 ? 1 : threads; }
  int threads() const { return threads_; }
  /// Workers lent to this pipeline, read as each stage starts: it then runs on threads() * (1 +
  /// *lent) threads (the idle workers of a parallel set lend theirs to the pairs still running:
  /// runner.hpp). Null: none. The results do not depend on it; `lent` must outlive its use.
  void lend_threads(const std::atomic<int>* lent) { lent_ = lent; }
  /// The threads a stage starting now runs on.
  int threads_now() const { return threads_ * (1 + (lent_ ? std::max(0, lent_->load()) : 0)); }

  const Config& config() const { return config_; }
  /// Whether there is something to run on: clouds, matches or both.
  bool has_input() const { return has_clouds_ || !matches_.empty(); }
  /// Whether clouds were given (set_input): landmarks and verification need them.
  bool has_clouds() const { return has_clouds_; }
  /// The matcher's correspondences as given to set_matches (empty: none).
  const std::vector<Correspondence>& matches() const { return matches_; }
  /// The label scheme the landmarks read the clouds with: the input's, else the configuration's
  /// (`auto` resolves per cloud: see source_landmarks().labels).
  const LabelScheme& label_scheme() const {
    return input_scheme_ ? *input_scheme_ : config_.label_scheme;
  }
  /// Whether a stage's output is out of date.
  bool stale(Stage stage) const { return stale_[static_cast<std::size_t>(stage)]; }
  /// Whether every stage is up to date.
  bool up_to_date() const;

  /// Runs the stale stages in order; the stages the inputs make moot (landmarks without clouds or
  /// with unfused matches, verification and refinement without clouds) leave empty results.
  /// Throws InputError without input, Cancelled when `cancel`
  /// becomes true (stages finished so far keep their results).
  void run(const ProgressFn& progress = {}, const std::atomic<bool>* cancel = nullptr);

  // ---- results (valid once the stage has run) ----
  const PointCloud& source() const { return source_; }
  const PointCloud& target() const { return target_; }
  const LandmarkSet& source_landmarks() const { return source_landmarks_; }
  const LandmarkSet& target_landmarks() const { return target_landmarks_; }
  const CorrespondenceSet& correspondences() const { return correspondences_; }
  const PyramidGraph& graph() const { return graph_.graph(); }
  const std::vector<CliqueResult>& cliques() const { return cliques_; }
  const std::vector<PoseEstimate>& poses() const { return poses_; }
  const Verifier* verifier() const { return verifier_ ? &*verifier_ : nullptr; }
  const VerificationResult& verification() const { return verification_; }
  /// What the refinement did to the selected pose (ran = false when disabled or nothing selected).
  const RefinementResult& refinement() const { return refinement_; }
  /// The acceptance verdict on the selected pose.
  const Acceptance& acceptance() const { return acceptance_; }
  const std::optional<Transform>& ground_truth() const { return ground_truth_; }
  /// With the pose model `automatic` and clouds: each scan's ground plane, which decides whether
  /// the pair is gravity-aligned (4-DoF poses); nullopt otherwise.
  const std::optional<std::pair<GroundPlane, GroundPlane>>& ground_planes() const {
    return ground_;
  }
  /// The pose parameters the GNC stage used: the configured ones, with `automatic` resolved to
  /// `four_dof` for a gravity-aligned pair of clouds.
  GncParams gnc_params() const;
  /// Errors per level (empty without ground truth; nullopt for an invalid candidate).
  const std::vector<std::optional<PoseError>>& level_errors() const { return level_errors_; }

  /// Selected level, or -1 when no candidate is valid.
  int selected_level() const { return verification_.selected; }
  /// The selected pose, if any: the verdict's adopted alternative when it took one
  /// (AcceptanceParams::adopt_alternative), else the refined one when refinement lowered D.
  std::optional<Transform> selected_transform() const;
  /// Errors of the selected pose (needs ground truth and a valid selection).
  std::optional<PoseError> selected_error() const;
  /// Errors of the selected candidate before refinement (needs ground truth and a selection).
  std::optional<PoseError> unrefined_error() const;
  /// Whether any candidate, or the selected pose after refinement, succeeds (the paper's "upper
  /// bound", never below the success of the selection; needs ground truth).
  bool upper_bound_success() const;

  /// How many times a stage has run since construction.
  int runs(Stage stage) const { return runs_[static_cast<std::size_t>(stage)]; }
  /// Wall time of a stage's last run [ms].
  double time_ms(Stage stage) const { return times_[static_cast<std::size_t>(stage)]; }
  /// Warnings collected by the last run of each stage.
  std::vector<std::string> warnings() const;
  /// Whether the last run's clique search stopped at the pair's time budget
  /// (clique.pair_time_budget_ms, counted from the start of run()); the levels it cut short have
  /// budget `time` and keep the best clique found so far. The warnings say so too.
  bool pair_time_budget_hit() const;

 private:
  void mark_stale(Stage stage);
  void run_stage(Stage stage);
  void run_refinement();
  void run_correspondences();
  void run_gnc();
  void select_and_settle();
  /// Whether the landmarks take part: clouds, and no matches or fused ones.
  bool uses_landmarks() const;
  void warn_if_numberings_differ();
  void warn_if_numbering_unsure();
  void judge_acceptance();
  // The poses the pair's unique landmarks fix (a class with one landmark on each side), one per
  // distinct answer the levels' graphs give, for the ambiguity test to weigh.
  std::vector<NamedPose> anchored_alternatives() const;
  // Takes the ambiguity's alternative in place of the selection where it fits decisively better and
  // the verdict accepts it refitted (AcceptanceParams::adopt_alternative); `candidates` and
  // `verification` are those the verdict judged.
  void adopt_alternative(std::vector<PoseEstimate> candidates, VerificationResult verification,
                         const std::vector<char>* furniture,
                         const std::function<std::vector<NamedPose>()>& anchored);
  /// Calls f(cloud, landmarks) for the source and the target, in parallel with threads > 1.
  template <class F>
  void both_clouds(const F& f);

  Config config_;
  int threads_ = 1;
  const std::atomic<int>* lent_ = nullptr;
  bool has_clouds_ = false;
  PointCloud source_, target_;
  std::vector<Correspondence> matches_;
  std::optional<LabelScheme> input_scheme_;
  std::optional<Transform> ground_truth_;

  LandmarkSet source_landmarks_, target_landmarks_;
  CorrespondenceSet correspondences_;
  PyramidGraphBuilder graph_;  // keeps its storage from pair to pair
  // The clique and GNC stages' results (first_*), and those after the selected level is settled
  // (clique.settle_selected), which everything after the selection reads.
  std::vector<CliqueResult> first_cliques_, cliques_;
  std::vector<PoseEstimate> first_poses_, poses_;
  double settle_ms_ = 0.0;
  std::chrono::steady_clock::duration clique_left_ = std::chrono::steady_clock::duration::max();
  std::optional<std::pair<GroundPlane, GroundPlane>> ground_;  // of the clouds, when needed
  std::optional<Verifier> verifier_;
  VerificationResult verification_;
  std::optional<Refiner> refiner_;
  RefinementResult refinement_;
  Acceptance acceptance_;
  std::vector<std::optional<PoseError>> level_errors_;

  std::array<bool, kStageCount> stale_{};
  std::array<int, kStageCount> runs_{};
  std::array<double, kStageCount> times_{};
  std::chrono::steady_clock::time_point run_started_{};
  bool pair_budget_hit_ = false, pass_budget_hit_ = false;
  Deadline clique_deadline() const;
};

}  // namespace pagor
