// The ground plane of a scan and the gravity-alignment test behind the automatic pose model.

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include "pagor/eval/synthetic.hpp"
#include "pagor/pose/gravity.hpp"

using namespace pagor;

namespace {

constexpr double kTiltTolerance = 1.5;  // [deg]: plane fit on points spaced ~0.1-0.5 m

PointCloud rotated(PointCloud cloud, double deg, const Eigen::Vector3d& axis) {
  const Eigen::Matrix3f R =
      Eigen::AngleAxisd(deg * M_PI / 180, axis.normalized()).toRotationMatrix().cast<float>();
  for (auto& p : cloud.points) p = R * p;
  return cloud;
}

}  // namespace

TEST_CASE("a level scan's ground is found level; a tilted one's by its tilt") {
  const SyntheticScene scene = make_synthetic_scene();
  const GroundPlane level = ground_plane(scene.source);
  REQUIRE(level.found);
  CHECK(level.tilt_deg < kTiltTolerance);
  CHECK(level.share > 0.2);
  for (double deg : {10.0, 30.0, 60.0}) {
    for (const Eigen::Vector3d& axis : {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(1, -2, 0.5)}) {
      INFO(deg << " deg about " << axis.transpose());
      const GroundPlane g = ground_plane(rotated(scene.source, deg, axis));
      REQUIRE(g.found);
      // The tilt a rotation gives the ground: the angle between R z and z.
      const Eigen::Vector3d z =
          Eigen::AngleAxisd(deg * M_PI / 180, axis.normalized()) * Eigen::Vector3d::UnitZ();
      const double expected = std::acos(z.z()) * 180 / M_PI;
      CHECK(g.tilt_deg == Approx(expected).margin(kTiltTolerance));
      CHECK(g.share == Approx(level.share).margin(0.05));  // the same ground, tilted
    }
  }
}

TEST_CASE("gravity-aligned: both grounds level and parallel to within the tolerance") {
  GroundPlane a, b;
  a.found = b.found = true;
  a.tilt_deg = b.tilt_deg = 2.0;
  a.normal =
      Eigen::AngleAxisd(2.0 * M_PI / 180, Eigen::Vector3d::UnitX()) * Eigen::Vector3d::UnitZ();
  b.normal =
      Eigen::AngleAxisd(-2.0 * M_PI / 180, Eigen::Vector3d::UnitX()) * Eigen::Vector3d::UnitZ();
  CHECK(gravity_aligned(a, b, 5.0));  // 4 deg apart
  CHECK_FALSE(gravity_aligned(a, b, 3.0));
  b.found = false;  // no ground: not known to be level
  CHECK_FALSE(gravity_aligned(a, b, 5.0));
  CHECK_FALSE(gravity_aligned(GroundPlane{}, GroundPlane{}, 90.0));
}

TEST_CASE("an empty or tiny cloud has no ground") {
  CHECK_FALSE(ground_plane(PointCloud{}).found);
  PointCloud two;
  two.points = {{0, 0, 0}, {1, 0, 0}};
  CHECK_FALSE(ground_plane(two).found);
}
