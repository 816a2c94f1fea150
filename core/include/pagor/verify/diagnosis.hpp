#pragma once
/// \file diagnosis.hpp
/// Why a pair failed, stage by stage, when the ground truth T_target_source is known. Runs after
/// the pipeline and recomputes nothing of it; it measures each stage's output against the truth:
/// - front end: which putative correspondences are true (ground-truth residual
///   |T_gt p - q| <= `residual_tolerance`), per class; landmarks per class in each cloud; the best
///   achievable inlier set (the largest set of true correspondences that uses every landmark at
///   most once, which is all a clique can hold since the graph never joins two correspondences
///   sharing a landmark);
/// - per level: the true correspondences among the graph's vertices, how many of them are
///   mutually consistent at that epsilon (exact maximum clique of the graph restricted to them),
///   the clique's precision and recall against them, GNC's inliers and the candidate's errors;
/// - verification: D of the ground-truth pose beside each candidate's D;
/// - a verdict naming the first stage at fault; before the front end, the labels: when a cloud's
///   labels do not fit the configured scheme (LabelReading::mismatch), that is the cause named.

#include <optional>
#include <string>
#include <vector>

#include "pagor/pipeline.hpp"
#include "pagor/util/fields.hpp"

namespace pagor {

/// Parameters of the diagnosis.
struct DiagnosisParams {
  /// A correspondence is true when |T_gt p - q| is at most this [m]; 0: the success criterion's
  /// translation tolerance (2 m by default), as the studio's overlay uses. Landmarks are centroids
  /// of partial views and KITTI's ground truth is good to about a metre, so true ones are off by
  /// up to a metre or two.
  double residual_tolerance = 0.0;
  /// Fewest true correspondences that can fix a pose and outnumber chance agreements; below
  /// it the front end is at fault. 0: the pose model's minimum (3 for SE(3), 2 otherwise) + 1.
  int min_true = 0;
  /// A clique is "right" when at least this fraction of its members are true [0, 1].
  double right_clique_precision = 0.5;
  long exact_max_nodes = 2000000;  ///< budget of the exact clique among true correspondences
};

/// The stage at fault, in pipeline order; `success` when the selected pose is right.
enum class DiagnosisVerdict {
  success,            ///< the selected pose is within the success criterion
  label_scheme,       ///< labels: a cloud's labels do not fit the configured label scheme
  too_few_true,       ///< front end: too few true correspondences to fix a pose
  not_consistent,     ///< graph: the true correspondences are not consistent at any epsilon
  clique_missed,      ///< clique: they were consistent, but no level's clique holds them
  pose_wrong,         ///< pose: a level's clique was right, its pose was not
  verification_wrong  ///< verification: a candidate was right, a wrong one had the lowest D
};
/// Each verdict's name (JSON, tables) and sentence (for a user).
inline constexpr EnumEntry<DiagnosisVerdict> kDiagnosisVerdicts[] = {
    {DiagnosisVerdict::success, "success", "success: the selected pose is right"},
    {DiagnosisVerdict::label_scheme, "label-scheme",
     "labels: they do not fit the label scheme in use"},
    {DiagnosisVerdict::too_few_true, "too-few-true", "front end: too few true correspondences"},
    {DiagnosisVerdict::not_consistent, "not-consistent",
     "graph: the true correspondences are not consistent at any epsilon"},
    {DiagnosisVerdict::clique_missed, "clique-missed", "clique: the densest clique missed them"},
    {DiagnosisVerdict::pose_wrong, "pose-wrong", "pose: wrong from a right clique"},
    {DiagnosisVerdict::verification_wrong, "verification-wrong",
     "verification picked a wrong candidate although one was right"},
};
static_assert(covers_every_value(kDiagnosisVerdicts, DiagnosisVerdict::verification_wrong));
inline const auto& enum_entries(DiagnosisVerdict) {
  return kDiagnosisVerdicts;
}

/// Short name of a verdict, as in JSON and tables: `success`, `label-scheme`, `too-few-true`,
/// `not-consistent`, `clique-missed`, `pose-wrong`, `verification-wrong`.
const char* verdict_name(DiagnosisVerdict verdict);
/// One sentence for a user, e.g. "verification picked a wrong candidate although one was right".
const char* verdict_sentence(DiagnosisVerdict verdict);

/// Front end, one configured class (plus `structure` when the fallback ran, and `matcher` for a
/// matcher's correspondences, whose landmarks are the keypoints they use).
struct ClassDiagnosis {
  std::string name;
  std::size_t source_landmarks = 0, target_landmarks = 0;
  std::size_t correspondences = 0;  ///< putative correspondences of the class
  std::size_t true_correspondences = 0;
  std::size_t best_achievable = 0;  ///< largest one-to-one set of its true correspondences
};

/// One pyramid level against the truth.
struct LevelDiagnosis {
  double epsilon = 0.0;
  std::size_t vertices = 0;       ///< correspondences with an edge at this level
  std::size_t true_vertices = 0;  ///< of those, true ones
  /// Largest set of true correspondences mutually consistent at this epsilon (exact maximum
  /// clique among the true ones; `consistent_exact` false when its budget ran out).
  std::size_t consistent_true = 0;
  bool consistent_exact = true;
  std::size_t clique_size = 0;
  std::size_t clique_true = 0;  ///< clique members that are true
  double precision = 0.0;       ///< clique_true / clique_size (0 for an empty clique)
  double recall = 0.0;          ///< clique_true / consistent_true, at most 1 (1 when none exist)
  OriginCounts clique_origin;   ///< clique members by origin (landmark, matcher)
  OriginCounts clique_true_origin;  ///< true clique members by origin
  bool pose_valid = false;
  std::size_t gnc_inliers = 0;       ///< GNC inliers of the level's pose
  std::size_t gnc_true_inliers = 0;  ///< of those, true ones
  std::optional<PoseError> error;    ///< the candidate's errors (nullopt: no pose)
  double score = 0.0;                ///< the candidate's D [m]; +inf when invalid
};

/// The whole diagnosis of one pair.
struct Diagnosis {
  DiagnosisVerdict verdict = DiagnosisVerdict::success;
  std::string explanation;  ///< the verdict with the numbers behind it, one line
  int at_fault_level = -1;  ///< the level the verdict is about (pose/verification), else -1
  /// label_scheme: the built-in scheme the misread labels look like ("none" when none fits).
  std::string labels_look_like;
  double residual_tolerance = 0.0;  ///< used [m]
  int min_true = 0;                 ///< used
  std::vector<ClassDiagnosis> classes;
  std::size_t true_correspondences = 0;
  std::size_t best_achievable = 0;  ///< all classes together
  /// Ground-truth residual |T_gt p - q| of every correspondence [m], in the pipeline's order.
  std::vector<double> residuals;
  std::vector<LevelDiagnosis> levels;
  double gt_score = 0.0;  ///< D of the ground-truth pose [m] (+inf without a verifier)
  int selected = -1;      ///< the selected level
  /// Errors of the selected pose, after refinement when it applied (nullopt: none selected); the
  /// verdict is `success` exactly when this pose is right.
  std::optional<PoseError> selected_error;
  /// The ground truth scores worse than the selected (wrong) candidate: D itself misled.
  bool score_misled = false;
  /// The selected pose is wrong and the acceptance's ambiguity alternative
  /// (Acceptance::alternative) is right: the scene repeats, and the verdict found the right pose as
  /// the look-alike.
  bool alternative_right = false;
  double time_ms = 0.0;  ///< wall time [ms]

  /// Whether correspondence i is true under the tolerance used.
  bool is_true(std::size_t i) const {
    return i < residuals.size() && residuals[i] <= residual_tolerance;
  }
};

/// What the diagnosis reads: each stage's output (as the Pipeline holds them).
struct DiagnosisInput {
  const LandmarkSet* source_landmarks = nullptr;
  const LandmarkSet* target_landmarks = nullptr;
  const CorrespondenceSet* correspondences = nullptr;
  const PyramidGraph* graph = nullptr;
  const std::vector<CliqueResult>* cliques = nullptr;
  const std::vector<PoseEstimate>* poses = nullptr;
  const VerificationResult* verification = nullptr;
  const Verifier* verifier = nullptr;  ///< may be null: the ground truth's D is then +inf
  const Config* config = nullptr;
  /// The selected pose after refinement (nullopt: the selected level's candidate as it is).
  std::optional<Transform> selected_pose;
  /// The verdict (null: not judged); its ambiguity alternative is checked against the truth.
  const Acceptance* acceptance = nullptr;
};

/// Diagnoses the stages' outputs against `T_target_source_gt`. Every pointer but `verifier`
/// must be set; levels come from `cliques` (and `poses`, `verification.scores` alike).
Diagnosis diagnose(const DiagnosisInput& input, const Transform& T_target_source_gt,
                   const DiagnosisParams& params = {});

/// Diagnoses a pipeline that has run; nullopt when it has no ground truth.
std::optional<Diagnosis> diagnose(const Pipeline& pipeline, const DiagnosisParams& params = {});

/// Each verification source point's contribution to D under a pose: min(d, mu) with d its
/// distance to the nearest target point [m] (truncated kind; what the default D sums).
std::vector<float> point_contributions(const Verifier& verifier, const Transform& T_target_source,
                                       double mu);

/// The diagnosis as one JSON object (the `diagnosis` field of pagor.register/1): verdict,
/// explanation, at_fault_level, residual_tolerance_m, true_correspondences, best_achievable,
/// classes[], levels[] (each with origin {landmark, matcher: {clique, clique_true}}), verification
/// {gt_score_D, candidates_D[], selected, score_misled}, alternative_right (the acceptance's
/// best distinct alternative is right while the selected pose is not).
std::string diagnosis_json(const Diagnosis& diagnosis, int indent = -1);

}  // namespace pagor
