#pragma once
/// \file ground.hpp
/// The ground of a cloud without labels (z up, a ground vehicle's or a walker's scan): a surface
/// over a horizontal grid that follows the lowest points of each cell but rises by no more than a
/// slope bound from cell to cell, so a street climbing a hill stays ground while a wall, a car or a
/// bush, which rise abruptly, do not. A single height layer (ground_layer_top) leaves the uphill
/// side of a sloped street as "structure", whose FPFH descriptors match anything.

#include <vector>

#include <Eigen/Core>

namespace pagor {

/// Parameters of the ground surface.
struct GroundParams {
  double thickness = 0.4;  ///< points this far above the surface are not ground [m]
  double cell = 2.0;       ///< horizontal grid of the surface [m]
  double max_slope = 0.3;  ///< steepest rise of the surface between cells [m per m]
};

/// Per point, whether it is ground: within `thickness` above the surface of its grid cell. The
/// surface of a cell is the lower of the cell's low points (the 10th percentile of its heights)
/// and of any other cell's surface plus `max_slope` times the distance between them. Cells
/// without points get theirs from their neighbours. A coarser grid is used when the cloud is more
/// than 2048 cells across. Non-finite points are never ground.
std::vector<char> ground_points(const std::vector<Eigen::Vector3f>& points,
                                const GroundParams& params = {});

}  // namespace pagor
