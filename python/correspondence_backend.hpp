#pragma once
/// \file correspondence_backend.hpp
/// The back end on a matcher's correspondences, as `pagor register --correspondences` composes it
/// today (app/cli/cmd_register_correspondences.cpp): pyramid graph -> densest clique per level ->
/// GNC-TLS pose per level; without clouds, the level whose pose keeps the most GNC inliers is
/// selected. This is the one function pagor.register_correspondences calls: when the Pipeline
/// takes a matcher's correspondences itself, it becomes a Pipeline run and its report.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "pagor/config.hpp"
#include "pagor/types.hpp"

namespace pagor::python {

/// Runs graph, clique and pose on `items` with `threads` threads for the graph. Returns the
/// result in the shape of `pagor register --correspondences --json` (schema
/// `pagor.register-correspondences/1`, without verification): T_target_source, selected_level,
/// selected_by, levels[] (epsilon, vertices, edges, clique, clique_size, pose_valid, inliers,
/// T_target_source), timings_ms, config. Throws InputError when there are more items than the
/// consistency graph takes (kMaxGraphCorrespondences).
nlohmann::json solve_correspondences(const std::vector<Correspondence>& items,
                                     const std::vector<double>& weights, const Config& config,
                                     int threads);

}  // namespace pagor::python
