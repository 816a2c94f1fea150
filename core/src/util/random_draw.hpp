#pragma once
/// \file random_draw.hpp
/// Random vectors drawn one coordinate per statement. The order in which function arguments are
/// evaluated is unspecified, so `Vector3d(d(rng), d(rng), d(rng))` gives different points with
/// different compilers (GCC and Clang disagree), and a seeded scene or association problem would
/// not be the same everywhere. These draw z, then y, then x: the order GCC evaluated those
/// expressions in, so the scenes the tests and benchmarks were written against stay the same.

#include <Eigen/Core>

namespace pagor {

/// (dx(rng), dy(rng), dz(rng)), drawn z first.
template <class DistX, class DistY, class DistZ, class Rng>
Eigen::Vector3d draw3(DistX& dx, DistY& dy, DistZ& dz, Rng& rng) {
  const double z = static_cast<double>(dz(rng));
  const double y = static_cast<double>(dy(rng));
  const double x = static_cast<double>(dx(rng));
  return {x, y, z};
}

/// (d(rng), d(rng), d(rng)), drawn z first.
template <class Dist, class Rng>
Eigen::Vector3d draw3(Dist& d, Rng& rng) {
  return draw3(d, d, d, rng);
}

/// (d(rng), d(rng)), drawn y first.
template <class Dist, class Rng>
Eigen::Vector2d draw2(Dist& d, Rng& rng) {
  const double y = static_cast<double>(d(rng));
  const double x = static_cast<double>(d(rng));
  return {x, y};
}

/// (d(rng), d(rng), z): a point on the horizontal plane at height `z`, drawn y first.
template <class Dist, class Rng>
Eigen::Vector3d draw_on_plane(Dist& d, Rng& rng, double z) {
  const Eigen::Vector2d xy = draw2(d, rng);
  return {xy.x(), xy.y(), z};
}

}  // namespace pagor
