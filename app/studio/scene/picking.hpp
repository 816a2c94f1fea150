#pragma once
/// \file picking.hpp
/// Points picked in the 3D view: the shown cloud point under the mouse, with its coordinates,
/// class and label value and its distance to the nearest target point; two picks measure the
/// distance between them.

#include <optional>
#include <string>
#include <vector>

#include "scene/scene_overlay.hpp"

namespace pagor::studio {

/// The point of the shown clouds drawn nearest to `mouse` (pixels in `r`), within `radius_px`:
/// the source's points under `pose` and the target's (each when its layer is shown). nullopt
/// when none is that close.
std::optional<Pick> pick_point(const Snapshot& s, const ViewState& view, const Transform& pose,
                               const ViewRect& r, const Eigen::Vector2f& mouse, float radius_px);

/// What a pick says, one fact a line: cloud and index, coordinates in its own frame and in the
/// target frame [m], class and label value, distance to the nearest target point [m].
std::string pick_text(const Pick& pick);

/// Distance between two picks, in the target frame [m].
double pick_distance(const Pick& a, const Pick& b);

/// The picks as markers (numbered), and with two the segment between them and its length.
void draw_picks(ImDrawList* dl, const ViewRect& r, const std::vector<Pick>& picks);

}  // namespace pagor::studio
