#pragma once
/// \file column_detector.hpp
/// Columns in a scan projected to the floor plane: 2-D Euclidean clusters whose extent fits a
/// column and whose points lie on a circle of the configured radius range, seen from the sensor's
/// side (the fitted centre lies behind the points, as seen from the scan origin).

#include <Eigen/Core>
#include <vector>

#include "pagor/indoor/floor_plan.hpp"
#include "pagor/params.hpp"

namespace pagor {

/// A circle fitted to points.
struct CircleFit {
  bool ok = false;                                   ///< false: degenerate (collinear, < 3 points)
  Eigen::Vector2d center = Eigen::Vector2d::Zero();  ///< [m]
  double radius = 0.0;                               ///< [m]
  double rms = 0.0;  ///< RMS distance of the points to the circle [m]
};

/// Least-squares circle: the algebraic (Kasa) fit refined by Gauss-Newton on the geometric
/// distances.
CircleFit fit_circle(const std::vector<Eigen::Vector2d>& points);

/// Groups of points (indices) closer than `tolerance` [m] to a neighbour of the same group.
std::vector<std::vector<int>> cluster_2d(const std::vector<Eigen::Vector2d>& points,
                                         double tolerance);

/// A column found in a scan.
struct DetectedColumn {
  Eigen::Vector2d center = Eigen::Vector2d::Zero();  ///< in the scan frame [m]
  double radius = 0.0;                               ///< fitted [m]
  double rms = 0.0;                                  ///< fit residual [m]
  double arc_deg = 0.0;                              ///< angle the points cover [deg]
  std::vector<int> points;                           ///< indices of its points
};

/// Finds columns among 2-D points in the scan frame (sensor at the origin). Clusters whose extent
/// exceeds twice the largest radius plus the tolerance, that have too few points, or whose fit
/// misses the radius range, RMS bound or arc coverage are not columns.
std::vector<DetectedColumn> detect_columns(const std::vector<Eigen::Vector2d>& points,
                                           const ColumnDetectorParams& params);

/// Detections against planted columns (the truth, in the same frame).
struct DetectionScore {
  int visible = 0;          ///< planted columns with at least `min_visible_points` points on them
  int found = 0;            ///< of the visible: with a detection within the match distance
  int detections = 0;       ///< columns detected
  int true_detections = 0;  ///< detections within the match distance of a planted column
  double recall() const { return visible ? double(found) / visible : 1.0; }
  double precision() const { return detections ? double(true_detections) / detections : 1.0; }
  DetectionScore& operator+=(const DetectionScore& o);
};

/// Scores detections: a planted column is visible when at least `min_visible_points` of `points`
/// lie within 0.1 m of its outline; a detection is true within `match_distance` [m] of any
/// planted column's centre.
DetectionScore score_detection(const std::vector<DetectedColumn>& detected,
                               const std::vector<PlanColumn>& planted,
                               const std::vector<Eigen::Vector2d>& points, int min_visible_points,
                               double match_distance);

}  // namespace pagor
