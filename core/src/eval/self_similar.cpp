#include "pagor/eval/self_similar.hpp"

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <iterator>
#include <random>

#include "eval/planar_pose.hpp"
#include "pagor/errors.hpp"

namespace pagor {
namespace {

constexpr std::uint32_t kCar = 0, kRoad = 8, kBuilding = 12, kFence = 13, kTrunk = 15, kPole = 17,
                        kSign = 18;
constexpr double kPi = 3.14159265358979323846;
constexpr double kSensorHeight = 1.7;  // above the floor, as KITTI's [m]

// The world of one scene: surface samples, and where the distinct objects may not stand.
struct World {
  std::vector<Eigen::Vector3d> points;
  std::vector<std::uint32_t> labels;
  std::vector<Eigen::Vector2d> obstacles;  // pillar, lamp and column centres
  void add(double x, double y, double z, std::uint32_t label) {
    points.emplace_back(x, y, z);
    labels.push_back(label);
  }
};

void add_cylinder(World& w, const Eigen::Vector2d& c, double r, double h, double spacing,
                  std::uint32_t label) {
  const int around = std::max(6, static_cast<int>(std::ceil(2 * kPi * r / spacing)));
  for (double z = 0; z <= h; z += spacing)
    for (int k = 0; k < around; ++k) {
      const double a = 2 * kPi * k / around;
      w.add(c.x() + r * std::cos(a), c.y() + r * std::sin(a), z, label);
    }
  w.obstacles.push_back(c);
}

// The faces of a box standing at height `z0` (bottom face skipped), its sides along x and y.
void add_box(World& w, const Eigen::Vector2d& c, const Eigen::Vector3d& size, double z0,
             double spacing, std::uint32_t label) {
  const Eigen::Vector3d h = size / 2;
  for (double u = -h.x(); u <= h.x(); u += spacing)
    for (double z = 0; z <= size.z(); z += spacing) {
      w.add(c.x() + u, c.y() - h.y(), z0 + z, label);
      w.add(c.x() + u, c.y() + h.y(), z0 + z, label);
    }
  for (double v = -h.y(); v <= h.y(); v += spacing)
    for (double z = 0; z <= size.z(); z += spacing) {
      w.add(c.x() - h.x(), c.y() + v, z0 + z, label);
      w.add(c.x() + h.x(), c.y() + v, z0 + z, label);
    }
  for (double u = -h.x(); u <= h.x(); u += spacing)
    for (double v = -h.y(); v <= h.y(); v += spacing)
      w.add(c.x() + u, c.y() + v, z0 + size.z(), label);
}

// A vertical wall from (x0, y0) to (x1, y1), `height` high.
void add_wall(World& w, const Eigen::Vector2d& a, const Eigen::Vector2d& b, double height,
              double spacing) {
  const double length = (b - a).norm();
  for (double s = 0; s <= length; s += spacing)
    for (double z = 0; z <= height; z += spacing) {
      const Eigen::Vector2d p = a + (b - a) * (s / length);
      w.add(p.x(), p.y(), z, kBuilding);
    }
}

void add_floor(World& w, const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, double spacing) {
  // Counted steps, not accumulated ones: the last row is there whatever the rounding.
  const int nx = static_cast<int>(std::round((hi.x() - lo.x()) / spacing));
  const int ny = static_cast<int>(std::round((hi.y() - lo.y()) / spacing));
  for (int i = 0; i <= nx; ++i)
    for (int j = 0; j <= ny; ++j) w.add(lo.x() + i * spacing, lo.y() + j * spacing, 0.0, kRoad);
}

// The half turn about the vertical through (x, y).
Transform half_turn(double x, double y) {
  return planar_pose(x, y, 0) * planar_pose(0, 0, kPi) * planar_pose(-x, -y, 0);
}

// What a scene kind lays out: the world, the two sensors, and the world motions under which the
// repeated part of the world maps onto itself.
struct Layout {
  World world;
  Transform T_world_target = Transform::Identity(), T_world_source = Transform::Identity();
  double range = 30.0;
  double period = 0.0;
  std::vector<Transform> symmetries;  // world to world
  double object_y[3] = {0, 0, 0};     // where the car, sign and bench stand across the axis
};

// The target sensor near the axis at x = 0, the source 6-28 m along it either way; both headings
// anywhere.
void place_sensors_along(Layout& l, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double target_y = unit(rng) * 2 - 1, target_yaw = (unit(rng) * 2 - 1) * kPi;
  const double shift = (unit(rng) < 0.5 ? -1 : 1) * (6 + 22 * unit(rng));
  const double source_y = unit(rng) * 2 - 1, source_yaw = (unit(rng) * 2 - 1) * kPi;
  l.T_world_target = planar_pose(0, target_y, target_yaw);
  l.T_world_source = planar_pose(shift, source_y, source_yaw);
}

// Shifts by +-1 and +-2 `step` along x, and the half turn about (`turn_x`, 0).
void along_axis_symmetries(Layout& l, double step, double turn_x) {
  for (double k : {-2.0, -1.0, 1.0, 2.0}) l.symmetries.push_back(planar_pose(k * step, 0, 0));
  l.symmetries.push_back(half_turn(turn_x, 0));
}

// The turn centre of a periodic row starting at `x0`: the repeated point nearest both sensors.
double periodic_centre(const Layout& l, double x0, double period) {
  const double mid = (l.T_world_target(0, 3) + l.T_world_source(0, 3)) / 2;
  return x0 + period * std::round((mid - x0) / period);
}

// The points x0 + k period within [-half_length, half_length], increasing.
std::vector<double> lattice(double x0, double period, double half_length) {
  std::vector<double> xs;
  for (double x = x0 - period * std::floor(half_length / period); x <= half_length; x += period)
    xs.push_back(x);
  return xs;
}

// The end of a periodic layout: sensors placed along it seeing `range` [m], the symmetries of the
// lattice x0 + k period, the distinct objects' lateral places [m].
void finish_periodic(Layout& l, std::mt19937_64& rng, double x0, double range,
                     const std::array<double, 3>& object_y) {
  place_sensors_along(l, rng);
  l.range = range;
  along_axis_symmetries(l, l.period, periodic_centre(l, x0, l.period));
  for (std::size_t i = 0; i < object_y.size(); ++i) l.object_y[i] = object_y[i];
}

Layout corridor(const SelfSimilarParams& p, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Layout l;
  l.period = 3 + 5 * unit(rng);
  const double x0 = l.period * unit(rng), half_length = 70;
  for (double side : {-3.0, 3.0})
    add_wall(l.world, {-half_length, side}, {half_length, side}, 3.0, 2 * p.spacing);
  add_floor(l.world, {-half_length, -3}, {half_length, 3}, 4 * p.spacing);
  // on the lattice x0 + k period, about whose points the corridor turns
  for (double x : lattice(x0, l.period, half_length))
    for (double side : {-2.6, 2.6}) add_cylinder(l.world, {x, side}, 0.25, 3.0, p.spacing, kTrunk);
  finish_periodic(l, rng, x0, 30, {-1.1, 1.9, 1.6});
  return l;
}

Layout facades(const SelfSimilarParams& p, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Layout l;
  const double width = 8 + 6 * unit(rng), gap = 2 + 2 * unit(rng), height = 8 + 6 * unit(rng);
  l.period = width + gap;
  const double x0 = l.period * unit(rng), half_length = 90;
  for (double x : lattice(x0, l.period, half_length))
    for (double side : {-1.0, 1.0}) {
      add_box(l.world, {x, side * 12}, {width, 10, height}, 0, 2 * p.spacing, kBuilding);
      add_cylinder(l.world, {x, side * 6}, 0.1, 6.0, p.spacing, kPole);
    }
  add_floor(l.world, {-half_length, -7}, {half_length, 7}, 4 * p.spacing);
  finish_periodic(l, rng, x0, 40, {-3.5, 5.0, 4.6});
  return l;
}

Layout sliding_street(const SelfSimilarParams& p, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Layout l;
  const double height = 6 + 6 * unit(rng), half_length = 100;
  for (double side : {-8.0, 8.0})
    add_wall(l.world, {-half_length, side}, {half_length, side}, height, 2 * p.spacing);
  add_floor(l.world, {-half_length, -8}, {half_length, 8}, 4 * p.spacing);
  place_sensors_along(l, rng);
  l.range = 40;
  along_axis_symmetries(l, 6.0, l.T_world_source(0, 3) / 2);
  l.object_y[0] = -5.5, l.object_y[1] = 6.5, l.object_y[2] = 6.0;
  return l;
}

Layout symmetric_hall(const SelfSimilarParams& p, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Layout l;
  const Eigen::Vector2d corners[4] = {{-15, -10}, {15, -10}, {15, 10}, {-15, 10}};
  for (int k = 0; k < 4; ++k)
    add_wall(l.world, corners[k], corners[(k + 1) % 4], 5.0, 2 * p.spacing);
  add_floor(l.world, {-15, -10}, {15, 10}, 4 * p.spacing);
  for (double x : {-7.5, 0.0, 7.5})
    for (double y : {-5.0, 5.0}) add_cylinder(l.world, {x, y}, 0.3, 5.0, p.spacing, kPole);
  // Two sensors at least 6 m apart, anywhere in the hall but the columns' rows.
  Eigen::Vector2d t, s;
  do {
    t = {(unit(rng) * 2 - 1) * 11, (unit(rng) * 2 - 1) * 3};
    s = {(unit(rng) * 2 - 1) * 11, (unit(rng) * 2 - 1) * 3};
  } while ((t - s).norm() < 6);
  const double target_yaw = (unit(rng) * 2 - 1) * kPi, source_yaw = (unit(rng) * 2 - 1) * kPi;
  l.T_world_target = planar_pose(t.x(), t.y(), target_yaw);
  l.T_world_source = planar_pose(s.x(), s.y(), source_yaw);
  l.range = 40;
  l.symmetries.push_back(half_turn(0, 0));
  return l;
}

// A car, a sign and a bench at irregular places both scans see, clear of the pillars and of each
// other. Along an axis they stand between the sensors (+-4 m); in the hall anywhere inside.
std::vector<SyntheticObject> add_distinct_objects(Layout& l, const SelfSimilarParams& p,
                                                  std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const bool hall = p.kind == SelfSimilarKind::symmetric_hall;
  const double a = std::min(l.T_world_target(0, 3), l.T_world_source(0, 3)) - 4;
  const double b = std::max(l.T_world_target(0, 3), l.T_world_source(0, 3)) + 4;
  const std::vector<Eigen::Vector2d> obstacles = l.world.obstacles;
  std::vector<Eigen::Vector2d> placed;
  std::vector<SyntheticObject> objects;
  const char* names[3] = {"car", "traffic-sign", "bench"};
  const std::uint32_t labels[3] = {kCar, kSign, kFence};
  for (int k = 0; k < 3; ++k) {
    Eigen::Vector2d c;
    for (int attempt = 0;; ++attempt) {
      c = hall ? Eigen::Vector2d((unit(rng) * 2 - 1) * 12, (unit(rng) * 2 - 1) * 7.5)
               : Eigen::Vector2d(a + (b - a) * unit(rng), l.object_y[k]);
      bool clear = true;
      for (const auto& o : obstacles) clear = clear && (o - c).norm() >= (k == 0 ? 3.2 : 1.2);
      for (const auto& o : placed) clear = clear && (o - c).norm() >= 5.0;
      if (clear || attempt > 1000) break;
    }
    placed.push_back(c);
    const std::size_t first = l.world.points.size();
    if (k == 0) add_box(l.world, c, {4.4, 1.8, 1.5}, 0, p.spacing, kCar);
    if (k == 1) {
      add_cylinder(l.world, c, 0.05, 2.2, p.spacing, kSign);
      add_box(l.world, c, {0.8, 0.05, 0.6}, 2.2, p.spacing, kSign);
    }
    if (k == 2) add_box(l.world, c, {1.8, 0.5, 0.8}, 0, p.spacing, kFence);
    for (std::size_t i = first; i < l.world.labels.size(); ++i) l.world.labels[i] = labels[k];
    SyntheticObject o;
    o.class_name = names[k];
    o.label = labels[k];
    o.centroid_world = Eigen::Vector3d::Zero();
    for (std::size_t i = first; i < l.world.points.size(); ++i)
      o.centroid_world += l.world.points[i];
    o.centroid_world /= static_cast<double>(l.world.points.size() - first);
    const Eigen::Vector3d cw(c.x(), c.y(), 0);
    o.in_source = (cw - l.T_world_source.block<3, 1>(0, 3)).head<2>().norm() <= l.range;
    o.in_target = (cw - l.T_world_target.block<3, 1>(0, 3)).head<2>().norm() <= l.range;
    objects.push_back(o);
  }
  return objects;
}

// The world as a sensor at `T_world_sensor` sees it: every sample within `range` horizontally.
PointCloud observe(const World& w, const Transform& T_world_sensor, double range,
                   const SelfSimilarParams& p, std::mt19937_64& rng) {
  const Transform T_sensor_world = T_world_sensor.inverse();
  const Eigen::Vector2d origin = T_world_sensor.block<2, 1>(0, 3);
  std::normal_distribution<double> n(0.0, p.noise);
  PointCloud out;
  for (std::size_t i = 0; i < w.points.size(); ++i) {
    if ((w.points[i].head<2>() - origin).norm() > range) continue;
    // One draw per statement (z, y, x), as synthetic.cpp: the same scene from every compiler.
    const double nz = n(rng), ny = n(rng), nx = n(rng);
    const Eigen::Vector3d p3 = T_sensor_world.block<3, 3>(0, 0) * w.points[i] +
                               T_sensor_world.block<3, 1>(0, 3) + Eigen::Vector3d(nx, ny, nz);
    out.points.push_back(p3.cast<float>());
    out.intensities.push_back(0.5f);
    if (p.labelled) out.labels.push_back(w.labels[i]);
  }
  return out;
}

}  // namespace

const char* self_similar_kind_name(SelfSimilarKind kind) {
  return to_string(kind);
}

SelfSimilarScene make_self_similar_scene(const SelfSimilarParams& params) {
  std::mt19937_64 rng(params.seed);
  // The layouts in the order of SelfSimilarKind.
  using MakeLayout = Layout (*)(const SelfSimilarParams&, std::mt19937_64&);
  static constexpr MakeLayout kLayouts[] = {corridor, facades, sliding_street, symmetric_hall};
  static_assert(
      std::size(kLayouts) == static_cast<std::size_t>(SelfSimilarKind::symmetric_hall) + 1,
      "a layout for every SelfSimilarKind");
  const auto kind = static_cast<std::size_t>(params.kind);
  if (kind >= std::size(kLayouts)) throw ConfigError("unknown self-similar scene kind");
  Layout l = kLayouts[kind](params, rng);
  SelfSimilarScene scene;
  if (params.distinct_objects) scene.objects = add_distinct_objects(l, params, rng);
  scene.name = std::string(self_similar_kind_name(params.kind)) + "-" +
               std::to_string(params.seed) + (params.distinct_objects ? "+objects" : "") +
               (params.labelled ? "" : "-xyz");
  // Sensors above the floor, the floor at z = 0 of the world.
  l.T_world_target(2, 3) = l.T_world_source(2, 3) = kSensorHeight;
  scene.T_target_source = l.T_world_target.inverse() * l.T_world_source;
  scene.period = params.kind == SelfSimilarKind::corridor || params.kind == SelfSimilarKind::facades
                     ? l.period
                     : 0.0;
  for (const Transform& M : l.symmetries)
    scene.look_alikes.push_back(l.T_world_target.inverse() * M * l.T_world_source);
  scene.source = observe(l.world, l.T_world_source, l.range, params, rng);
  scene.target = observe(l.world, l.T_world_target, l.range, params, rng);
  return scene;
}

std::vector<SelfSimilarParams> self_similar_set(int seeds) {
  std::vector<SelfSimilarParams> set;
  for (int seed = 1; seed <= seeds; ++seed)
    for (SelfSimilarKind kind : {SelfSimilarKind::corridor, SelfSimilarKind::facades,
                                 SelfSimilarKind::sliding_street, SelfSimilarKind::symmetric_hall})
      for (bool objects : {false, true})
        for (bool labelled : {true, false}) {
          SelfSimilarParams p;
          p.kind = kind;
          p.seed = static_cast<std::uint64_t>(seed);
          p.distinct_objects = objects;
          p.labelled = labelled;
          set.push_back(p);
        }
  return set;
}

}  // namespace pagor
