#pragma once
/// \file floor_plan.hpp
/// A floor plan as the map of indoor re-localization (the paper's car-park experiment): walls as
/// 2-D polylines and columns as circles, in metres. The plan is sampled into metric points (walls
/// and column outlines, z = 0) labelled in the `indoor` scheme (wall 1, column 2), so the columns
/// become landmarks of class `column` and the walls the points of the verification.
///
/// JSON format (`pagor.floor_plan/1`, every coordinate in metres, x right, y up):
///
///     {"format": "pagor.floor_plan/1",
///      "walls":   [{"points": [[0, 0], [40, 0], [40, 25]], "closed": false}, ...],
///      "columns": [{"center": [5.0, 5.0], "radius": 0.3}, ...]}
///
/// `format` and `closed` are optional; a wall needs at least two points, a column a radius in
/// (0, 100] m; no coordinate lies beyond ±10^7 m.
///
/// SVG (what CAD and drawing tools export): `<line>`, `<polyline>`, `<polygon>`, `<rect>` and
/// `<path>` (commands M, L, H, V, Z, absolute or relative) are walls, `<circle>` (and `<ellipse>`
/// with rx = ry) are columns. The scale is the attribute `data-scale` of the root `<svg>` (metres
/// per SVG unit), or else `width` in m, cm or mm together with a `viewBox`. The SVG y axis points
/// down; it is flipped so the plan has y up. The scale must lie in [10^-6, 10^4] m per unit.
/// Curves and anything that would move drawn geometry — `transform` attributes on any element
/// (`<g>` too), CSS transforms (`style`, `<style>`), nested `<svg>` elements, `<use>` — are
/// rejected with a message naming the element (flatten and apply them when exporting); shapes
/// inside `<defs>`, `<symbol>`, `<clipPath>`, `<mask>`, `<pattern>` and `<marker>` are not walls.
///
/// Every malformed element is an InputError naming the file and the element (`walls[3].points[1]`
/// in JSON; the tag, its number and line in SVG).

#include <Eigen/Core>
#include <string>
#include <string_view>
#include <vector>

#include "pagor/types.hpp"

namespace pagor {

/// Farthest a plan's point may lie from its origin, on either axis [m] (beyond any building).
constexpr double kMaxPlanCoordinate = 1e7;
/// Largest column radius a plan may give [m].
constexpr double kMaxColumnRadius = 100.0;
/// Most points a plan is sampled into (sample_floor_plan): 10^7, 500 km of wall at 5 cm.
constexpr std::size_t kMaxPlanSamples = 10000000;

/// A circular column of the plan.
struct PlanColumn {
  Eigen::Vector2d center = Eigen::Vector2d::Zero();  ///< [m]
  double radius = 0.3;                               ///< [m]
};

/// A wall: a polyline of at least two vertices.
struct PlanWall {
  std::vector<Eigen::Vector2d> points;  ///< vertices [m]
  bool closed = false;                  ///< whether the last vertex joins the first
};

/// A floor plan in metres.
struct FloorPlan {
  std::vector<PlanWall> walls;
  std::vector<PlanColumn> columns;
};

/// Label ids the sampled plan and the projected scans carry (the `indoor` label scheme).
constexpr std::uint32_t kWallLabel = 1;
constexpr std::uint32_t kColumnLabel = 2;
/// What stands lower than the building's walls in a projected scan (a car, a person): no plan
/// draws it (prepare_floor_scan, IndoorParams::furniture_gap).
constexpr std::uint32_t kFurnitureLabel = 4;

/// Parses the JSON format above. `origin` names the file in messages. Throws InputError.
FloorPlan parse_floor_plan_json(std::string_view text, const std::string& origin);

/// Parses an SVG plan (see above). Throws InputError naming the element.
FloorPlan parse_floor_plan_svg(std::string_view text, const std::string& origin);

/// Reads a plan by extension: `.json` or `.svg`. Throws InputError naming the file.
FloorPlan read_floor_plan(const std::string& path);

/// Whether a path names a floor plan rather than a cloud (extension `.json` or `.svg`).
bool is_floor_plan_path(const std::string& path);

/// The plan as JSON in the format above.
std::string floor_plan_to_json(const FloorPlan& plan);

/// Writes the plan as JSON, atomically. Throws InputError.
void write_floor_plan(const FloorPlan& plan, const std::string& path);

/// Points every `spacing` [m] along each wall (label kWallLabel) and around each column's outline
/// (kColumnLabel, at least 8 per column), all at z = 0. `spacing` must be > 0. Throws InputError
/// naming the wall or column at which the count would pass kMaxPlanSamples, before allocating.
PointCloud sample_floor_plan(const FloorPlan& plan, double spacing);

/// Points every `spacing` [m] around a circle, at least 8, z = 0, all with `label`.
void sample_circle(const Eigen::Vector2d& center, double radius, double spacing,
                   std::uint32_t label, PointCloud& out);

}  // namespace pagor
