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
#include "pagor/params.hpp"
#include "pagor/types.hpp"

namespace pagor {

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
