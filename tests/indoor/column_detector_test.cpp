// The column detector: circle fit, clusters, and recall and precision on generated scans with
// planted columns; and the floor projection of a scan.

#include <catch2/catch.hpp>
#include <random>

#include "pagor/config.hpp"
#include "pagor/eval/indoor_synthetic.hpp"
#include "pagor/indoor/column_detector.hpp"
#include "pagor/indoor/floor_projection.hpp"

using namespace pagor;

namespace {

// The side of a circle facing the origin: `arc_deg` around the direction to the origin.
std::vector<Eigen::Vector2d> facing_arc(const Eigen::Vector2d& c, double r, double arc_deg, int n,
                                        double noise, std::mt19937_64& rng) {
  std::normal_distribution<double> g(0.0, noise);
  const double towards = std::atan2(-c.y(), -c.x());
  std::vector<Eigen::Vector2d> out;
  for (int i = 0; i < n; ++i) {
    const double a = towards + (arc_deg * M_PI / 180.0) * (static_cast<double>(i) / (n - 1) - 0.5);
    out.push_back(c + (r + g(rng)) * Eigen::Vector2d(std::cos(a), std::sin(a)));
  }
  return out;
}

}  // namespace

TEST_CASE("the circle fit recovers a circle from a noisy half arc") {
  std::mt19937_64 rng(3);
  const auto exact = facing_arc({4, 1}, 0.3, 360, 40, 0.0, rng);
  const CircleFit e = fit_circle(exact);
  REQUIRE(e.ok);
  CHECK(e.center.isApprox(Eigen::Vector2d(4, 1), 1e-9));
  CHECK(e.radius == Approx(0.3));
  CHECK(e.rms < 1e-9);
  const CircleFit n = fit_circle(facing_arc({4, 1}, 0.3, 150, 25, 0.01, rng));
  REQUIRE(n.ok);
  CHECK((n.center - Eigen::Vector2d(4, 1)).norm() < 0.03);  // tolerance: 3 noise sigmas
  CHECK(n.radius == Approx(0.3).margin(0.03));
  CHECK_FALSE(fit_circle({{0, 0}, {1, 0}, {2, 0}}).ok);  // collinear
  CHECK_FALSE(fit_circle({{0, 0}, {1, 0}}).ok);
}

TEST_CASE("the detector keeps columns and rejects walls, cars, concave shapes") {
  std::mt19937_64 rng(5);
  std::vector<Eigen::Vector2d> pts = facing_arc({6, 0}, 0.3, 140, 20, 0.005, rng);
  const std::size_t column_end = pts.size();
  for (int i = 0; i < 60; ++i) pts.emplace_back(-3.0, -1.5 + 0.05 * i);  // a wall
  for (int i = 0; i < 40; ++i) pts.emplace_back(2.0 + 0.05 * i, 5.0);    // a car's side ...
  for (int i = 0; i < 18; ++i) pts.emplace_back(2.0, 5.0 + 0.05 * i);    // ... and its end
  // The inside of a circle seen from its centre's far side: concave towards the sensor.
  for (const auto& p : facing_arc({0, -8}, 0.3, 140, 20, 0.0, rng))
    pts.push_back(Eigen::Vector2d(0, -8) - (p - Eigen::Vector2d(0, -8)));
  const auto found = detect_columns(pts, ColumnDetectorParams{});
  REQUIRE(found.size() == 1);
  CHECK((found[0].center - Eigen::Vector2d(6, 0)).norm() < 0.02);
  CHECK(found[0].points.size() == column_end);
  CHECK(found[0].arc_deg == Approx(140).margin(5));
}

TEST_CASE("projection keeps the height band, one point per floor cell") {
  PointCloud scan;
  for (float z : {-0.5f, 0.0f, 1.0f, 2.5f}) scan.points.emplace_back(1.01f, 2.01f, z);
  scan.points.emplace_back(1.02f, 2.02f, 0.5f);  // same 5 cm cell
  IndoorParams p;
  std::size_t band = 0;
  const auto floor = project_to_floor(scan, p, nullptr, &band);
  CHECK(band == 3);
  REQUIRE(floor.size() == 1);
  CHECK(floor[0].x() == Approx(1.0133).margin(1e-3));
}

TEST_CASE("the detector finds the planted columns of generated scans") {
  // Measured on these 20 scans (seed 2): recall 0.93 (169/181), precision 0.88 (169/191);
  // bench/README.md has the 120-scan figures. The floors sit below.
  IndoorSceneParams scene;
  scene.seed = 2;
  const int scans = 20;
  const IndoorWorld world = make_indoor_world(scene, scans);
  const IndoorParams params = preset_config("indoor").indoor;
  DetectionScore total;
  for (int k = 0; k < scans; ++k) {
    std::mt19937_64 rng(100 + k);
    const auto& pose = world.trajectory[static_cast<std::size_t>(k)];
    total += score_scan_columns(world, pose, ray_cast_indoor(world, pose, {}, rng), params);
  }
  INFO("recall " << total.recall() << " (" << total.found << "/" << total.visible << "), precision "
                 << total.precision() << " (" << total.true_detections << "/" << total.detections
                 << ")");
  CHECK(total.visible > 100);
  CHECK(total.recall() >= 0.85);
  CHECK(total.precision() >= 0.75);
}
