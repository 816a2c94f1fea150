#pragma once
/// \file indoor_synthetic.hpp
/// A generated underground car park for indoor re-localization (the paper's second experiment,
/// whose data is not public): an irregular column grid with missing columns, outer and inner
/// walls, a ramp, a robot trajectory through the aisles, and ray-cast 16-beam lidar scans with
/// range noise. What the robot sees differs from the as-designed plan as in a real building:
/// parked cars and people are not in the plan, some walls were built elsewhere, glass returns
/// nothing, the ramp's sloped floor enters the height band. Everything follows from the seed.

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "pagor/indoor/column_detector.hpp"
#include "pagor/indoor/floor_plan.hpp"
#include "pagor/indoor/floor_projection.hpp"
#include "pagor/types.hpp"

namespace pagor {

/// The building and what is in it.
struct IndoorSceneParams {
  std::uint64_t seed = 1;
  int grid_x = 8;                     ///< column lines along x
  int grid_y = 5;                     ///< column lines along y
  double pitch_x = 8.1;               ///< nominal spacing of the column lines along x [m]
  double pitch_y = 7.6;               ///< nominal spacing of the column lines along y [m]
  double line_jitter = 0.35;          ///< each column line moved by up to this [m] (irregular grid)
  double column_jitter = 0.03;        ///< each column moved by up to this (as built vs plan) [m]
  double column_radius = 0.3;         ///< [m]
  double missing_columns = 0.12;      ///< fraction of grid positions without a column
  double border = 5.0;                ///< outer wall distance from the outermost column lines [m]
  double glass_fraction = 0.15;       ///< fraction of outer-wall pieces that are glass
  int moved_walls = 2;                ///< inner walls built up to `wall_shift` from the plan
  double wall_shift = 0.8;            ///< [m]
  double parking_probability = 0.55;  ///< chance that a bay beside a column row holds a car
  int people = 10;                    ///< people standing around
  double ceiling = 2.7;               ///< [m]
};

/// An obstacle not in the plan: a box (car) or an upright cylinder (person).
struct IndoorObstacle {
  bool box = true;
  Eigen::Vector2d center = Eigen::Vector2d::Zero();  ///< [m]
  Eigen::Vector2d half = Eigen::Vector2d::Zero();    ///< box: half extents along its axes [m]
  double yaw = 0.0;                                  ///< box orientation [rad]
  double radius = 0.0;                               ///< cylinder [m]
  double height = 1.5;                               ///< top [m]
};

/// A ramp: a rectangle whose floor rises along +x of its frame.
struct IndoorRamp {
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();  ///< low end, centre line [m]
  double length = 12.0, width = 4.0;                 ///< [m]
  double rise = 2.7;                                 ///< height gained over the length [m]
  double yaw = 0.0;                                  ///< direction of rise [rad]
};

/// The building as designed (the plan) and as built (what the lidar sees).
struct IndoorWorld {
  FloorPlan plan;                           ///< as designed
  FloorPlan built;                          ///< as built (moved walls, columns within jitter)
  std::vector<char> glass;                  ///< per wall of `built`: 1 = glass, returns nothing
  std::vector<IndoorObstacle> obstacles;    ///< cars and people
  IndoorRamp ramp;                          ///< one ramp
  std::vector<Eigen::Vector3d> trajectory;  ///< drivable path, (x, y, yaw) [m, m, rad]
  double ceiling = 2.7;                     ///< [m]
};

/// Generates the building and a drivable path through its aisles with `scans` poses.
IndoorWorld make_indoor_world(const IndoorSceneParams& params, int scans);

/// The lidar.
struct IndoorLidarParams {
  int beams = 16;              ///< rows
  double fov_down = -15.0;     ///< lowest beam [deg]
  double fov_up = 15.0;        ///< highest beam [deg]
  int azimuths = 1800;         ///< columns over 360 deg (VLP-16 at 10 Hz: 0.2 deg)
  double max_range = 40.0;     ///< [m]
  double range_noise = 0.02;   ///< standard deviation along the beam [m]
  double sensor_height = 0.5;  ///< above the floor [m]
  double dropout = 0.02;       ///< fraction of returns lost
};

/// One scan from pose (x, y, yaw) in the sensor frame (z up, origin at the sensor). `rng` draws
/// the noise.
PointCloud ray_cast_indoor(const IndoorWorld& world, const Eigen::Vector3d& pose,
                           const IndoorLidarParams& lidar, std::mt19937_64& rng);

/// `T_plan_sensor` of a pose (x, y, yaw): the ground truth of the scan against the plan.
Transform pose_transform(const Eigen::Vector3d& pose);

/// The column detector on one scan taken at `pose`, against the built columns (moved into the scan
/// frame): a column is visible with at least `min_visible_points` projected points on its outline,
/// and a detection is right within `match_distance` [m] of its centre.
DetectionScore score_scan_columns(const IndoorWorld& world, const Eigen::Vector3d& pose,
                                  const PointCloud& scan, const IndoorParams& params,
                                  int min_visible_points = 6, double match_distance = 0.15);

/// Writes a sequence into `dir` (created if needed): `plan.json` (as designed), `built.json`
/// (as built, the columns the detector should find), `scans/NNNNNN.bin` (KITTI float32 x, y, z,
/// reflectance 0), `gt/NNNNNN.txt` (4x4 T_plan_scan), `poses.txt` (one `x y yaw[rad]` per scan) and
/// `pairs.txt`, a manifest for `pagor bench --manifest` with each scan against the plan. Every file
/// is written atomically, and the manifest is removed first and written last, so an interrupted
/// run leaves no manifest pairing files of two runs. Throws InputError.
void write_indoor_sequence(const std::string& dir, const IndoorSceneParams& params, int scans,
                           const IndoorLidarParams& lidar = {});

}  // namespace pagor
