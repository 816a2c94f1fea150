#pragma once
/// \file acceptance.hpp
/// Whether the selected pose should be trusted: the verdict a loop-closure user acts on. After
/// verification has picked the lowest-D candidate, four measures are taken:
/// - overlap: the fraction of verification source points above the ground surface (ground.hpp)
///   that lie within `inlier_distance` of a target point under the selected pose. True overlaps
///   leave a substantial part of the structure aligned; any level pose aligns the ground of two
///   scans that share nothing, so the ground is left out, also when little else is left (all
///   points count only for a flat cloud: under 1 % of them off the ground, a floor projection);
/// - inliers: how many correspondences of the selected clique agree with the pose (GNC inliers);
/// - margin: how much better the selected D is than the best *distinct* candidate (one that
///   differs from the selection by more than distinct_translation or distinct_rotation), as a
///   fraction of the largest possible D (mu times the number of source points); 1 when there is no
///   distinct candidate.
/// - sharpness: how much of the overlap is lost when the pose is moved by the success criterion's
///   translation along each horizontal axis (a true alignment is a sharp peak).
/// - ambiguity: whether a distinct alternative fits the clouds as well: of the structure points on
///   which the two disagree (one aligns within inlier_distance, the other not within twice it),
///   (those only the alternative aligns + 10) / (those only the selected pose aligns + 10). The
///   alternatives: the other levels' candidates, the pose turned 180 degrees about the vertical
///   through the centre of what it aligns, and both moved along the target structure's axes (a
///   scan's principal axes; a plan's the directions its walls run along) by the shifts where the
///   clouds' occupancy agrees best, which is where a repetition period shows; such a shift is
///   also tried moved across its axis, by up to twice distinct_translation, to where the occupancy
///   agrees best (against a plan every one, a scan the two most rivalling), and the two most
///   rivalling then moved to their best ratio (verify/ambiguity.cpp); and, from the pipeline, the
///   pose the pair's unique landmarks fix (a class with one landmark on each side: its
///   correspondence and the largest clique through it, Pipeline::anchored_alternatives). A corridor
///   of pillars, a street of identical facades, a symmetric hall: a pose off by whole periods, or
///   turned, fits as well as the right one.
/// The pose is accepted when every measure reaches its threshold; a pose resting on the minimal
/// number of inliers for its model must reach the higher `minimal_support_overlap`.

#include <functional>
#include <string>
#include <vector>

#include "pagor/params.hpp"
#include "pagor/pose/gnc.hpp"
#include "pagor/verify/evaluation.hpp"
#include "pagor/verify/verification.hpp"

namespace pagor {

/// One test of the verdict, for display: "overlap 0.31 >= 0.24".
struct AcceptanceTest {
  /// "overlap", "inliers", "sharpness", "margin", "minimal support" or "ambiguity"
  std::string name;
  double value = 0.0;      ///< the measure
  double threshold = 0.0;  ///< what it is compared with
  bool at_most = false;    ///< passes when value <= threshold (ambiguity), else value >= threshold
  bool passed = false;     ///< whether the test passed (also true when it does not apply)
  /// false: not taken (minimal support when the inliers are more than the minimum; ambiguity when
  /// an earlier test other than the margin or the sharpness failed, or with adoption off any
  /// earlier test, or max_ambiguity turns it off; the margin for an adopted alternative)
  bool applies = true;
  std::string unit;         ///< "" for fractions and counts
  std::string description;  ///< what the measure is, one line
};

/// A distinct pose that explains the clouds about as well as the selected one.
struct AcceptanceAlternative {
  Transform T_target_source = Transform::Identity();  ///< the alternative pose
  /// what it is, in words: "a pose moved 18.0 m (x +17.9, y -1.2)", "the pose turned 180 deg and
  /// moved 0.4 m (...)", "level 2's candidate (25.8 m, 3 deg away)"; empty when there is none
  std::string description;
  /// (points only it aligns + 10) / (points only the selected pose aligns + 10): about 1, nothing
  /// tells the two apart; over 1, the alternative fits better
  double ratio = 0.0;
  /// the disagreeing structure points behind the ratio: those only the alternative aligns, and
  /// those only the selected pose aligns
  std::size_t only_alternative = 0, only_selected = 0;
};

/// A pose the ambiguity test weighs beside the other levels' candidates and the repetitions it
/// finds, with what it is in words (Pipeline: the pose the pair's unique landmarks fix). Named as
/// "NAME (DETAIL; 25.7 m, 0 deg away)", the distance from the pose judged.
struct NamedPose {
  Transform T_target_source = Transform::Identity();
  std::string name;    ///< "the pose its unique landmarks fix"
  std::string detail;  ///< "car, traffic-sign; 20 correspondences at level 0"
};

/// The ambiguity's alternative taken in place of the selected pose (AcceptanceParams::
/// adopt_alternative): it fitted decisively better, was refitted by GNC to the correspondences it
/// explains, and the verdict on it as the selection accepted it.
struct AcceptanceAdoption {
  bool applied = false;
  Transform T_target_source = Transform::Identity();  ///< the pose taken: the refit
  std::vector<int> inliers;     ///< the refit's GNC inliers (indices into the correspondences)
  std::string from;             ///< the alternative it came from, as described
  double ratio = 0.0;           ///< that alternative's ratio against the selected pose
  double score_D = 0.0;         ///< the refit's D [m]
  std::string selected_reason;  ///< why the selected pose itself was not accepted
};

/// The verdict and the measures behind it.
struct Acceptance {
  bool accepted = false;  ///< trust the selected pose
  /// false when there was nothing to verify on (a matcher's correspondences without clouds):
  /// the pose is then neither accepted nor rejected on evidence, and `reason` says so
  bool verified = true;
  double overlap = 0.0;  ///< fraction of source points within inlier_distance, in [0, 1]
  int inliers = 0;       ///< GNC inliers of the selected candidate
  double margin = 0.0;   ///< D margin to the best distinct candidate, fraction of mu * points
  /// 1 - (best overlap of the pose moved by distinct_translation along +-x, +-y)
  /// / overlap: near 1 for an alignment of distinct structure, near 0 (or below) for one that
  /// slides along itself or aligns what matches anywhere
  double sharpness = 0.0;
  /// the best distinct alternative's ratio (Acceptance::alternative); 0 when there is none or the
  /// test is off
  double ambiguity = 0.0;
  AcceptanceAlternative alternative;  ///< the best distinct alternative (empty description: none)
  /// every test with its value and threshold, in the order the reason is chosen: overlap, inliers,
  /// sharpness, margin, minimal support, ambiguity; empty when nothing was judged
  std::vector<AcceptanceTest> tests;
  /// applied: the measures above are the adopted pose's, judged as the selection
  AcceptanceAdoption adopted;
  /// which measure failed, e.g. "overlap 0.08 < 0.25", or "ambiguous: a pose moved 18.0 m (x
  /// +18.0, y +0.1) fits as well: it alone aligns 0.97 times the points the selected pose alone
  /// aligns"; empty if accepted
  std::string reason;
};

/// Judges the selection of `verification` among `candidates`. No selection: not accepted.
/// `threads` > 1 splits the searches of the points over threads (same verdict). `furniture`, if
/// given, marks the verifier's source points on furniture (what stands lower than the walls: a
/// parked car, a person); against a floor plan the ambiguity test counts them for no pose, and
/// against a pose that puts them on the plan's walls or columns. `adopting`: the selection is an
/// alternative being adopted (AcceptanceAdoption) that fitted decisively better than the candidates
/// of lower D where the clouds overlap; the D margin is not taken (the ambiguity test judges it
/// against every candidate on the points both see). `more_alternatives`, if given, is called when
/// the ambiguity test runs (only then: it may cost a search) for more poses it weighs (those
/// within the distinct distance of the selection are not distinct).
Acceptance judge_selection(const Verifier& verifier, const std::vector<PoseEstimate>& candidates,
                           const VerificationResult& verification,
                           const VerificationParams& verification_params,
                           const AcceptanceParams& params, PoseModel model, int threads = 1,
                           const std::vector<char>* furniture = nullptr, bool adopting = false,
                           const std::function<std::vector<NamedPose>()>& more_alternatives = {});

}  // namespace pagor
