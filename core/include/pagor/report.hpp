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
///                     origin {landmark: count, matcher: count}
///   landmarks         source / target: {class name: count}
///   timings_ms        landmarks, correspondences, graph, clique, gnc, verification, evaluation,
///   total warnings[], config (the full configuration used)

#include <string>

#include "pagor/pipeline.hpp"

namespace pagor {

/// Serialises the state of a pipeline that has run. `source_name`/`target_name` describe inputs.
std::string registration_report_json(const Pipeline& pipeline, const std::string& source_name,
                                     const std::string& target_name, int indent = 2);

}  // namespace pagor
