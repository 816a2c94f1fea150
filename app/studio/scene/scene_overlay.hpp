#pragma once
/// \file scene_overlay.hpp
/// What the 3D view draws over the rendered clouds with ImGui's draw list, so that it is always
/// on top and as thick as asked: correspondence lines, a ground grid, XYZ axes, a scale bar and
/// the colour legend. Also the box that "fit" frames.

#include <imgui.h>

#include <Eigen/Core>

#include "runners/worker.hpp"
#include "scene/scene_view.hpp"
#include "state/app_state.hpp"

namespace pagor::studio {

/// A viewport of the 3D view on screen.
struct ViewRect {
  ImVec2 origin;  ///< top-left [px]
  float width = 1, height = 1;
  Eigen::Matrix4f view_projection;
};

/// "Nice" length near `x` (1, 2 or 5 times a power of ten) [m].
float nice_length(float x);

/// Metres per pixel at the camera target for a viewport `height` pixels high.
float metres_per_pixel(const Camera& camera, float height);

/// The box around everything shown (dense clouds without their farthest 2 %, landmarks, lines).
/// False when nothing is shown.
bool shown_bounds(const Snapshot& s, const ViewState& view, const Transform& source_pose,
                  Eigen::Vector3f& lo, Eigen::Vector3f& hi);

/// Ground grid (at the target's 2 % height quantile), axes at the target origin, scale bar.
void draw_grid_axes_scale(ImDrawList* dl, const ViewRect& r, const Camera& camera, float ground_z);

/// The shown level's clique (green / red against ground truth) and optionally every other
/// correspondence (faint, class colours), `width` pixels wide. Returns the lines drawn.
int draw_correspondence_lines(ImDrawList* dl, const ViewRect& r, const Snapshot& s,
                              const ViewState& view, const Transform& source_pose, int level,
                              const ClassColors& colors);

/// The legend's point entries (colour, text): the classes drawn, source / target, and a matcher's
/// points p and q when there are such correspondences.
std::vector<std::pair<ImU32, std::string>> point_entries(const Snapshot& s, const ViewState& view,
                                                         const ClassColors& colors,
                                                         const std::vector<DrawnClass>& drawn);

/// Legend: line meanings, and what the points are drawn in: the classes drawn (`drawn`, with the
/// classes that made landmarks only), source / target, or the colour scale of height or
/// intensity (`scale`).
void draw_legend(ImDrawList* dl, ImVec2 at, const Snapshot& s, const ViewState& view,
                 const ClassColors& colors, const std::vector<DrawnClass>& drawn,
                 const ColorScale& scale);

}  // namespace pagor::studio
