#include "pagor/eval/synthetic.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <random>

#include "eval/planar_pose.hpp"

namespace pagor {
namespace {

// Random vectors drawn in a fixed order (z, y, x), one draw per statement: the order in which
// function arguments are evaluated is unspecified, so `Vector3d(n(rng), n(rng), n(rng))` gives
// different scenes from different compilers.
template <class Dist>
Eigen::Vector3d noise3(Dist& d, std::mt19937_64& rng) {
  const double z = d(rng);
  const double y = d(rng);
  const double x = d(rng);
  return {x, y, z};
}
template <class Dist>
Eigen::Vector2d draw2(Dist& d, std::mt19937_64& rng) {
  const double y = d(rng);
  const double x = d(rng);
  return {x, y};
}

constexpr std::uint32_t kCar = 0, kRoad = 8, kBuilding = 12, kTrunk = 15, kPole = 17;
constexpr double kPi = 3.14159265358979323846;

struct Sampled {
  std::vector<Eigen::Vector3d> points;
  std::vector<std::uint32_t> labels;
  std::vector<int> object;  // object index, or -1 for ground and buildings cut per point
};

void add_cylinder(Sampled& s, const Eigen::Vector2d& c, double r, double h, double spacing,
                  std::uint32_t label, int obj) {
  const int around = std::max(6, static_cast<int>(std::ceil(2 * kPi * r / spacing)));
  for (double z = 0; z <= h; z += spacing)
    for (int k = 0; k < around; ++k) {
      const double a = 2 * kPi * k / around;
      s.points.emplace_back(c.x() + r * std::cos(a), c.y() + r * std::sin(a), z);
      s.labels.push_back(label);
      s.object.push_back(obj);
    }
}

// Samples the faces of an oriented box standing on the ground (the bottom face is skipped).
void add_box(Sampled& s, const Eigen::Vector2d& c, double yaw, const Eigen::Vector3d& size,
             double spacing, std::uint32_t label, int obj) {
  const Eigen::Matrix2d R = Eigen::Rotation2Dd(yaw).toRotationMatrix();
  const Eigen::Vector3d h = size / 2;
  auto emit = [&](double x, double y, double z) {
    const Eigen::Vector2d xy = c + R * Eigen::Vector2d(x, y);
    s.points.emplace_back(xy.x(), xy.y(), z);
    s.labels.push_back(label);
    s.object.push_back(obj);
  };
  for (double u = -h.x(); u <= h.x(); u += spacing)
    for (double z = 0; z <= size.z(); z += spacing) {
      emit(u, -h.y(), z);
      emit(u, h.y(), z);
    }
  for (double v = -h.y(); v <= h.y(); v += spacing)
    for (double z = 0; z <= size.z(); z += spacing) {
      emit(-h.x(), v, z);
      emit(h.x(), v, z);
    }
  for (double u = -h.x(); u <= h.x(); u += spacing)
    for (double v = -h.y(); v <= h.y(); v += spacing) emit(u, v, size.z());
}

// A building: a box with facade details (pilasters, bays and a lower wing at random places), so
// that, as on real facades, local geometry tells one part of a wall from another.
void add_building(Sampled& s, const Eigen::Vector2d& c, double yaw, const Eigen::Vector3d& size,
                  double spacing, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  add_box(s, c, yaw, size, spacing, kBuilding, -1);
  const Eigen::Matrix2d R = Eigen::Rotation2Dd(yaw).toRotationMatrix();
  const int details = 6 + static_cast<int>(unit(rng) * 6);
  for (int k = 0; k < details; ++k) {
    const int face = static_cast<int>(unit(rng) * 4) % 4;  // +x, -x, +y, -y
    const bool along_x = face >= 2;
    const double half_len = along_x ? size.x() / 2 : size.y() / 2;
    const double offset = (unit(rng) * 2 - 1) * (half_len - 1.5);
    const double depth = 0.4 + 1.2 * unit(rng);
    const double width = 0.8 + 2.5 * unit(rng);
    const double height = size.z() * (0.3 + 0.7 * unit(rng));
    const double sign = face % 2 == 0 ? 1.0 : -1.0;
    Eigen::Vector2d local = along_x ? Eigen::Vector2d(offset, sign * (size.y() / 2 + depth / 2))
                                    : Eigen::Vector2d(sign * (size.x() / 2 + depth / 2), offset);
    const Eigen::Vector3d dsize =
        along_x ? Eigen::Vector3d(width, depth, height) : Eigen::Vector3d(depth, width, height);
    add_box(s, c + R * local, yaw, dsize, spacing, kBuilding, -1);
  }
}

PointCloud observe(const Sampled& s, const std::vector<SyntheticObject>& objects, bool source,
                   const Transform& T_world_sensor, double range, double noise,
                   std::mt19937_64& rng) {
  const Transform T_sensor_world = T_world_sensor.inverse();
  const Eigen::Vector3d origin = T_world_sensor.block<3, 1>(0, 3);
  std::normal_distribution<double> n(0.0, noise);
  PointCloud out;
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const int obj = s.object[i];
    bool seen;
    if (obj >= 0) {
      const auto& o = objects[static_cast<std::size_t>(obj)];
      seen = source ? o.in_source : o.in_target;
    } else {
      seen = (s.points[i] - origin).head<2>().norm() <= range;
    }
    if (!seen) continue;
    const Eigen::Vector3d p = T_sensor_world.block<3, 3>(0, 0) * s.points[i] +
                              T_sensor_world.block<3, 1>(0, 3) + noise3(n, rng);
    out.points.push_back(p.cast<float>());
    out.intensities.push_back(0.5f);
    out.labels.push_back(s.labels[i]);
  }
  return out;
}

}  // namespace

SyntheticScene make_synthetic_scene(const SyntheticParams& params) {
  std::mt19937_64 rng(params.seed);
  std::uniform_real_distribution<double> coord(-params.half_extent, params.half_extent);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  SyntheticScene scene;
  scene.T_world_source = planar_pose(0, 0, 0);
  const Transform T_world_target =
      planar_pose(params.target_x, params.target_y, params.target_yaw_deg * kPi / 180.0);
  scene.T_target_source = T_world_target.inverse() * scene.T_world_source;

  Sampled s;
  std::vector<Eigen::Vector2d> building_centres, object_centres;
  // A random spot at least `clearance` from every object and 16 m from every building centre
  // (buildings are at most 20 x 14 m, so objects stand outside them).
  auto free_spot = [&](double clearance, double building_clearance) {
    for (int attempt = 0; attempt < 2000; ++attempt) {
      const Eigen::Vector2d c = draw2(coord, rng);
      bool ok = true;
      for (const auto& o : object_centres) ok = ok && (o - c).norm() >= clearance;
      for (const auto& o : building_centres) ok = ok && (o - c).norm() >= building_clearance;
      if (ok) return c;
    }
    return draw2(coord, rng);
  };

  // Buildings first: they are large, and objects keep clear of them.
  for (int b = 0; b < params.buildings; ++b) {
    const Eigen::Vector2d c = free_spot(0.0, 30.0);
    building_centres.push_back(c);
    // One draw per statement: the order of function arguments is unspecified, and compilers
    // differ (the scene must be the same whichever built it). Drawn z, y, x as before.
    const double size_z = 6 + 8 * unit(rng);
    const double size_y = 8 + 6 * unit(rng);
    const Eigen::Vector3d size(10 + 10 * unit(rng), size_y, size_z);
    add_building(s, c, unit(rng) * kPi, size, 2 * params.spacing, rng);
  }
  auto add_objects = [&](int count, const char* name, std::uint32_t label) {
    for (int k = 0; k < count; ++k) {
      const Eigen::Vector2d c = free_spot(params.min_separation, 16.0);
      object_centres.push_back(c);
      const int obj = static_cast<int>(scene.objects.size());
      const std::size_t first = s.points.size();
      if (label == kCar)
        add_box(s, c, unit(rng) * kPi, {4.4, 1.8, 1.5}, params.spacing, label, obj);
      if (label == kTrunk) add_cylinder(s, c, 0.2, 3.0, params.spacing, label, obj);
      if (label == kPole) add_cylinder(s, c, 0.1, 6.0, params.spacing, label, obj);
      Eigen::Vector3d mean = Eigen::Vector3d::Zero();
      for (std::size_t i = first; i < s.points.size(); ++i) mean += s.points[i];
      SyntheticObject o;
      o.class_name = name;
      o.label = label;
      o.centroid_world = mean / static_cast<double>(s.points.size() - first);
      const Eigen::Vector3d cw(c.x(), c.y(), 0);
      o.in_source = (cw - scene.T_world_source.block<3, 1>(0, 3)).norm() <= params.range;
      o.in_target = (cw - T_world_target.block<3, 1>(0, 3)).norm() <= params.range;
      scene.objects.push_back(o);
    }
  };
  add_objects(params.cars, "car", kCar);
  add_objects(params.trunks, "trunk", kTrunk);
  add_objects(params.poles, "pole", kPole);

  // Ground: a regular grid, coarser than the objects.
  for (double x = -params.half_extent; x <= params.half_extent; x += 4 * params.spacing)
    for (double y = -params.half_extent; y <= params.half_extent; y += 4 * params.spacing) {
      s.points.emplace_back(x, y, 0.0);
      s.labels.push_back(kRoad);
      s.object.push_back(-1);
    }

  scene.source =
      observe(s, scene.objects, true, scene.T_world_source, params.range, params.noise, rng);
  scene.target = observe(s, scene.objects, false, T_world_target, params.range, params.noise, rng);
  return scene;
}

}  // namespace pagor
