#pragma once
/// \file synthetic.hpp
/// A labelled outdoor-like scene generated from a seed, observed by two sensors with a known
/// relative pose. Used by the tests and as the embedded default scene when no data is at hand.
/// Labels follow the `semantickitti-train` scheme (car 0, road 8, building 12, trunk 15, pole 17).

#include <cstdint>
#include <string>
#include <vector>

#include "pagor/types.hpp"

namespace pagor {

/// Parameters of the generated scene.
struct SyntheticParams {
  std::uint64_t seed = 7;       ///< RNG seed; the same seed gives the same scene
  double half_extent = 70.0;    ///< the world spans [-half_extent, half_extent]^2 [m]
  int cars = 14;                ///< cars (boxes 4.4 x 1.8 x 1.5 m)
  int trunks = 18;              ///< tree trunks (cylinders r 0.2 m, 3 m high)
  int poles = 14;               ///< poles (cylinders r 0.1 m, 6 m high)
  int buildings = 8;            ///< buildings (boxes with walls 6 to 14 m high)
  double min_separation = 7.0;  ///< between object centres [m] (cars are 4.4 m long)
  double range = 45.0;          ///< sensor range; objects are kept or cut whole by their centre [m]
  double noise = 0.02;          ///< Gaussian noise on every coordinate [m]
  double spacing = 0.15;        ///< sampling of object surfaces [m]
  /// Pose of the target sensor in the source sensor's frame (the inverse of T_target_source).
  double target_x = 12.0, target_y = 3.0, target_yaw_deg = 25.0;
};

/// One generated object.
struct SyntheticObject {
  std::string class_name;          ///< "car", "trunk", "pole" or "building"
  std::uint32_t label = 0;         ///< its semantickitti-train id
  Eigen::Vector3d centroid_world;  ///< mean of its surface samples in the world frame [m]
  bool in_source = false, in_target = false;  ///< whether each scan sees it
};

/// The scene and its two scans.
struct SyntheticScene {
  PointCloud source;          ///< points in the source sensor frame
  PointCloud target;          ///< points in the target sensor frame
  Transform T_target_source;  ///< maps source points into the target frame
  Transform T_world_source;   ///< source sensor pose in the world
  std::vector<SyntheticObject> objects;
};

/// Generates the scene. Deterministic for a given `params`.
SyntheticScene make_synthetic_scene(const SyntheticParams& params = {});

}  // namespace pagor
