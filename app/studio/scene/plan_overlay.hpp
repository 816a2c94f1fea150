#pragma once
/// \file plan_overlay.hpp
/// An indoor pair's floor plan over the 3D view as vector geometry: walls as line segments,
/// columns as circle outlines (the plan's own radii), and the columns found in the scan as circles
/// with a centre cross under the shown source pose. Drawn with ImGui's draw list like the other
/// overlays (scene_overlay.hpp); the geometry comes from the worker's snapshot.

#include <imgui.h>

#include <vector>

#include "pagor/indoor/column_detector.hpp"
#include "pagor/indoor/floor_plan.hpp"
#include "scene/scene_overlay.hpp"

namespace pagor::studio {

/// Colours of the plan overlay, shared with the legend.
struct PlanPalette {
  static constexpr ImU32 wall = IM_COL32(235, 235, 240, 230);
  static constexpr ImU32 column = IM_COL32(255, 150, 40, 255);       ///< as the target cloud
  static constexpr ImU32 scan_column = IM_COL32(60, 180, 255, 255);  ///< as the source cloud
};

/// Segments a circle of `radius` [m] is drawn with.
constexpr int kPlanCircleSegments = 32;

/// Draws the plan's walls (every polyline edge, closing edge included) and columns at height
/// `z` [m]. Returns the number of wall segments and columns drawn (for tests).
int draw_floor_plan(ImDrawList* dl, const ViewRect& r, const FloorPlan& plan, float z);

/// Draws the scan's columns (scan frame) moved by `T_target_source`, at height `z` [m].
/// Returns the number drawn.
int draw_scan_columns(ImDrawList* dl, const ViewRect& r, const std::vector<DetectedColumn>& columns,
                      const Transform& T_target_source, float z);

/// The number of straight wall segments of a plan (a closed polyline of n points has n).
int wall_segment_count(const FloorPlan& plan);

}  // namespace pagor::studio
