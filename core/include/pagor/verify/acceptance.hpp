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
///   through the centre of what it aligns, and both moved along the target structure's principal
///   axes by the shifts where the clouds' occupancy agrees best, which is where a repetition
///   period shows (verify/ambiguity.cpp). A corridor of pillars, a street of identical facades,
///   a symmetric hall: a pose off by whole periods, or turned, fits as well as the right one.
/// The pose is accepted when every measure reaches its threshold; a pose resting on the minimal
/// number of inliers for its model must reach the higher `minimal_support_overlap`.

#include <string>
#include <vector>

#include "pagor/pose/gnc.hpp"
#include "pagor/util/fields.hpp"
#include "pagor/verify/evaluation.hpp"
#include "pagor/verify/verification.hpp"

namespace pagor {

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
  double distinct_translation = 2.0;
  double distinct_rotation = 5.0;

  /// What the verdict counts as another answer: poses apart by more than this.
  EvaluationParams distinct() const { return {distinct_translation, distinct_rotation}; }

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
       "pose turned 180 degrees, moved by a repetition of the scene) to points only the selected "
       "pose aligns, 10 added to each; 10 or more: off.",
       "", Range::closed(0, 1e6)});
    v(&AcceptanceParams::distinct_translation,
      {"distinct_translation",
       "Two poses farther apart than this are distinct answers: the margin's runner-up, the "
       "sharpness test's shift and the ambiguity's alternatives.",
       "m", Range::above(0, 1e6)});
    v(&AcceptanceParams::distinct_rotation,
      {"distinct_rotation", "Two poses turned further apart than this are distinct answers.", "deg",
       Range::above(0, 180)});
    v(&AcceptanceParams::ambiguity_range,
      {"ambiguity_range", "The furthest shift searched for a repetition along each principal axis.",
       "m", Range::closed(0, 1e4)});
  }
};

/// One test of the verdict, for display: "overlap 0.31 >= 0.24".
struct AcceptanceTest {
  /// "overlap", "inliers", "sharpness", "margin", "minimal support" or "ambiguity"
  std::string name;
  double value = 0.0;      ///< the measure
  double threshold = 0.0;  ///< what it is compared with
  bool at_most = false;    ///< passes when value <= threshold (ambiguity), else value >= threshold
  bool passed = false;     ///< whether the test passed (also true when it does not apply)
  /// false: not taken (minimal support when the inliers are more than the minimum; ambiguity when
  /// an earlier test failed or max_ambiguity turns it off)
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
  /// which measure failed, e.g. "overlap 0.08 < 0.25", or "ambiguous: a pose moved 18.0 m (x
  /// +18.0, y +0.1) fits as well: it alone aligns 0.97 times the points the selected pose alone
  /// aligns"; empty if accepted
  std::string reason;
};

/// Judges the selection of `verification` among `candidates`. No selection: not accepted.
/// `threads` > 1 splits the searches of the points over threads (same verdict). `furniture`, if
/// given, marks the verifier's source points on furniture (what stands lower than the walls: a
/// parked car, a person); against a floor plan the ambiguity test counts them for no pose, and
/// against a pose that puts them on the plan's walls or columns.
Acceptance judge_selection(const Verifier& verifier, const std::vector<PoseEstimate>& candidates,
                           const VerificationResult& verification,
                           const VerificationParams& verification_params,
                           const AcceptanceParams& params, PoseModel model, int threads = 1,
                           const std::vector<char>* furniture = nullptr);

}  // namespace pagor
