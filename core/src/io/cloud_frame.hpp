#pragma once
// The frame a cloud's points are stored in. A cloud far from its file's origin (a scan in a
// national grid, 300 km out) keeps float32 points relative to a frame origin near them, chosen
// from the coordinates in double before they are narrowed; near the origin (a sensor-frame scan)
// the origin is zero and nothing changes. See PointCloud::origin (types.hpp).

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "io/parse_numbers.hpp"

namespace pagor {

/// A cloud whose median point lies farther than this from its file's origin gets a frame origin
/// near its points [m]. Sensor-frame scans (a lidar sees ~100 m) stay in their own frame.
constexpr double kFarFromOrigin = 1000.0;

/// A frame origin lies within this of the file's origin on every axis [m]: geocentric and
/// national grids stay within it; a cloud centred farther is corrupt, its points are not moved.
constexpr double kMaxFrameOrigin = 1e7;

/// Points farther than this from their cloud's frame origin on any axis are dropped as
/// corrupt (load_cloud) [m]: beyond any scan or map, and where float32 holds no better than 6 cm.
constexpr double kMaxCoordinate = 1e6;

/// The frame origin for the `n` points `at(i)` (Eigen::Vector3d): zero when their median (per
/// axis, over at most ~4097 evenly spread finite points) lies within kFarFromOrigin of the
/// origin, or beyond kMaxFrameOrigin; else that median rounded to whole metres (so float inputs
/// shift exactly).
template <class At>
Eigen::Vector3d frame_origin(std::size_t n, const At& at) {
  constexpr std::size_t kSamples = 4097;
  const std::size_t step = n <= kSamples ? 1 : n / kSamples;
  std::vector<double> axis[3];
  for (std::size_t i = 0; i < n; i += step) {
    const Eigen::Vector3d p = at(i);
    if (!p.allFinite()) continue;
    for (int k = 0; k < 3; ++k) axis[k].push_back(p[k]);
  }
  if (axis[0].empty()) return Eigen::Vector3d::Zero();
  Eigen::Vector3d median;
  for (int k = 0; k < 3; ++k) {
    auto mid = axis[k].begin() + static_cast<std::ptrdiff_t>(axis[k].size() / 2);
    std::nth_element(axis[k].begin(), mid, axis[k].end());
    median[k] = *mid;
  }
  if (!(median.norm() > kFarFromOrigin) || !(median.cwiseAbs().maxCoeff() <= kMaxFrameOrigin))
    return Eigen::Vector3d::Zero();
  return median.array().round().matrix();
}

/// `v - origin` as a float (out of float's range: +-inf); `loss` grows to the largest rounding
/// error seen [m].
inline float narrowed(double v, double origin, double& loss) {
  const double d = v - origin;
  const float f = parse::to_float(d);
  if (std::isfinite(f)) loss = std::max(loss, std::abs(static_cast<double>(f) - d));
  return f;
}

}  // namespace pagor
