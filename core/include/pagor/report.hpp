#pragma once
/// \file report.hpp
/// The JSON form of a `Registration` (registration.hpp), schema `pagor.register/1`:
///   T_target_source   selected 4x4 transform, row-major nested list (null if none)
///   selected_level    index into `levels` (null if none)
///   levels[]          epsilon, vertices, edges, clique (correspondence indices), clique_size,
///                     clique_proven, clique_upper_bound (a bound on the level's clique number),
///                     pose_valid, T_target_source, inliers, score_D (null if invalid), with
///                     ground truth translation_error_m, rotation_error_deg, success, and with a
///                     correspondences file's inlier flags precision, recall, true_inliers
///   selected_by       "score_D" (verified on the clouds) or "without_clouds" (level_selection.hpp)
///   acceptance        accepted, verified (false: no clouds to verify on), overlap, inliers,
///                     margin, sharpness, ambiguity, alternative (null, or the best distinct
///                     pose: description, ratio, T_target_source), tests[] (name, value,
///                     threshold, comparison ">=" or "<=", passed, applies, unit, description),
///                     reason (see acceptance.hpp), and wrong_pose_accepted: accepted while the
///                     ground truth calls the pose wrong
///   ground_truth      T_target_source, translation_error_m, rotation_error_deg, success,
///                     upper_bound: whether any level's candidate is right (null without truth)
///   correspondences   count, candidates, capped, per_class {name: count} (landmark ones),
///                     origin {landmark, matcher: {count, selected_clique, selected_inliers}}
///                     (the selected level's clique members and GNC inliers of each origin),
///                     and from a correspondences file: file, weights, inlier_flags,
///                     flagged_inliers
///   landmarks         source / target: {class name: count}
///   labels            source / target: scheme, automatic, looks_like, margin_nats, mismatch
///   timings_ms        landmarks, correspondences, graph, clique, gnc, verification, refinement,
///                     acceptance, evaluation, total
///   warnings[], pair_time_budget_hit, config (the full configuration used)
///   diagnosis         the stage at fault (diagnosis.hpp); null without ground truth
/// `to_json` (registration.hpp) writes it; these are its parts for writers that add members.

#include <nlohmann/json.hpp>
#include <string>

#include "pagor/registration.hpp"

namespace pagor {

/// A 4x4 transform as the report writes it: four rows of four numbers.
nlohmann::json matrix_json(const Transform& T);

/// The report as a JSON object (`with_config`: include the configuration used).
nlohmann::json report_object(const Registration& registration, bool with_config = true);

/// Text of a report: `indent` spaces a level, clamped to [-1, 16] (-1: one line); bytes that are
/// not UTF-8 (paths) are replaced, never thrown on.
std::string dump_report(const nlohmann::json& report, int indent);

}  // namespace pagor
