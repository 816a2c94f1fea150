#pragma once
/// \file floor_projection.hpp
/// A scan (2-D or 3-D points, sensor frame, z up) brought to a floor plan: points within the
/// height band are projected to the floor plane (z = 0) on a 2-D grid, columns are found
/// (column_detector.hpp, or taken from the scan's labels), and each column's points are replaced by
/// its fitted outline sampled like the plan's columns, so a column's cluster centroid is its centre
/// in the scan and in the plan alike (the visible half-arc alone would pull it towards the sensor).
/// The other points are labelled wall (the verification's metric points).

#include <vector>

#include "pagor/indoor/column_detector.hpp"
#include "pagor/types.hpp"

namespace pagor {

/// Indoor re-localization against a floor plan (floor_plan.hpp): the plan is sampled into points
/// and the scan is projected to the floor plane with its columns found. Applies when a pair's
/// target is a floor plan (`.json` or `.svg`).
struct IndoorParams {
  // Each field's meaning, unit and valid range: fields() below (docs/config.md).
  double plan_spacing = 0.05;
  double height_min = -0.3;
  double height_max = 1.9;
  double floor_voxel = 0.05;
  double furniture_gap = 1.0;
  bool detect_columns = true;
  ColumnDetectorParams columns;

  template <class V>
  static void fields(V&& v) {
    v(&IndoorParams::plan_spacing, {"plan_spacing", "Sampling of plan walls and column outlines.",
                                    "m", Range::closed(1e-3, 10)});
    v(&IndoorParams::height_min,
      {"height_min", "Scan points lower than this (scan frame, z up) are left out.", "m",
       Range::closed(-1000, 1000)});
    v(&IndoorParams::height_max, {"height_max", "Scan points higher than this are left out.", "m",
                                  Range::closed(-1000, 1000)});
    v(&IndoorParams::floor_voxel,
      {"floor_voxel", "The 2-D grid of the projected scan.", "m", Range::closed(1e-3, 10)});
    v(&IndoorParams::furniture_gap,
      {"furniture_gap",
       "A scan point is on furniture (a car, a person: lower than the walls, in no plan) when a "
       "higher beam of about its azimuth returned from at least this much further. A projected "
       "cell all of whose points are is labelled furniture: against the floor plan, acceptance's "
       "ambiguity test counts it for no pose, and against a pose that puts it on a wall or "
       "column. Needs the scan in its sensor's frame; 0: off.",
       "m", Range::closed(0, 1000)});
    v(&IndoorParams::detect_columns,
      {"detect_columns",
       "Find columns with the detector; off: take them from the scan's labels (indoor scheme)."});
    v(&IndoorParams::columns, {"columns", "The column detector."});
  }
  template <class C>
  static void check(const IndoorParams& p, C& c) {
    c.require(p.height_max > p.height_min, "height_max", "must be > height_min [m]");
  }
};

/// A projected scan.
struct FloorScan {
  PointCloud cloud;                     ///< z = 0, labels kWallLabel, kColumnLabel, kFurnitureLabel
  std::vector<Eigen::Vector2d> floor;   ///< the projected points before the column outlines [m]
  std::vector<DetectedColumn> columns;  ///< columns found (indices into `floor`)
  std::size_t in_band = 0;              ///< input points within the height band
  std::size_t furniture = 0;            ///< projected cells labelled furniture
};

/// Points within [height_min, height_max], one per cell of the `floor_voxel` grid (the cell's
/// mean). With `labels` (same length as `scan`), the most frequent label of each cell. With
/// `furniture`, per cell whether each of its points was passed over by a higher beam that returned
/// from at least params.furniture_gap further (passed_over).
std::vector<Eigen::Vector2d> project_to_floor(const PointCloud& scan, const IndoorParams& params,
                                              std::vector<std::uint32_t>* labels = nullptr,
                                              std::size_t* in_band = nullptr,
                                              std::vector<char>* furniture = nullptr);

/// Per point of a scan in its sensor's frame: whether a point of a higher beam, within half a
/// degree of its azimuth, lies at least `gap` [m] further out horizontally (the beam passed over
/// it: what it hit is lower than what stands behind). All false for gap <= 0 or a flat scan.
std::vector<char> passed_over(const PointCloud& scan, double gap);

/// The whole preparation (above). Throws InputError when no point lies within the height band.
FloorScan prepare_floor_scan(const PointCloud& scan, const IndoorParams& params);

}  // namespace pagor
