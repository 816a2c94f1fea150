#pragma once
/// \file report.hpp
/// The JSON result of a registration, schema `pagor.register/1`:
///   T_target_source   selected 4x4 transform, row-major nested list (null if none)
///   selected_level    index into `levels` (null if none)
///   levels[]          epsilon, vertices, edges, clique (correspondence indices), clique_size,
///                     pose_valid, T_target_source, inliers, score_D (null if invalid),
///                     and with ground truth translation_error_m, rotation_error_deg, success
///   selected_by       "score_D" (verified on the clouds) or "without_clouds" (level_selection.hpp)
///   acceptance        accepted, verified (false: no clouds to verify on), overlap, inliers,
///                     margin, reason (see acceptance.hpp)
///   ground_truth      T_target_source, translation_error_m, rotation_error_deg, success,
///                     upper_bound (null without ground truth)
///   correspondences   count, candidates, capped, per_class {name: count} (landmark ones),
///                     origin {landmark, matcher: {count, selected_clique, selected_inliers}}
///                     (the selected level's clique members and GNC inliers of each origin)
///   landmarks         source / target: {class name: count}
///   timings_ms        landmarks, correspondences, graph, clique, gnc, verification, evaluation,
///   total warnings[], config (the full configuration used)
///   diagnosis         the stage at fault (diagnosis.hpp; null without ground truth), when given

#include <optional>
#include <string>

#include "pagor/pipeline.hpp"
#include "pagor/verify/diagnosis.hpp"

namespace pagor {

/// Serialises the state of a pipeline that has run. `source_name`/`target_name` describe inputs.
std::string registration_report_json(const Pipeline& pipeline, const std::string& source_name,
                                     const std::string& target_name, int indent = 2);

/// The same with `diagnosis` as the member `diagnosis` (null when nullopt): what `pagor register
/// --json` writes and what the Python module's Result.to_json() returns.
std::string registration_report_json(const Pipeline& pipeline, const std::string& source_name,
                                     const std::string& target_name,
                                     const std::optional<Diagnosis>& diagnosis, int indent = 2);

}  // namespace pagor
