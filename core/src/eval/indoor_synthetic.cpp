#include "pagor/eval/indoor_synthetic.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>

#include "pagor/errors.hpp"
#include "pagor/indoor/floor_projection.hpp"
#include "pagor/io/atomic_file.hpp"
#include "pagor/eval/pair_set.hpp"
#include "pagor/io/clouds.hpp"

namespace pagor {
namespace {

using Vec2 = Eigen::Vector2d;
constexpr double kInf = std::numeric_limits<double>::infinity();

double uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

// Column lines: nominal pitch, each line moved by up to `jitter`.
std::vector<double> column_lines(int n, double pitch, double jitter, std::mt19937_64& rng) {
  std::vector<double> out;
  for (int i = 0; i < n; ++i) out.push_back(i * pitch + uniform(rng, -jitter, jitter));
  return out;
}

// Outer walls as pieces of about 6 m, so some can be glass.
void add_outer_walls(const Vec2& lo, const Vec2& hi, IndoorWorld& w, double glass,
                     std::mt19937_64& rng) {
  const Vec2 corners[4] = {lo, {hi.x(), lo.y()}, hi, {lo.x(), hi.y()}};
  for (int side = 0; side < 4; ++side) {
    const Vec2 a = corners[side], b = corners[(side + 1) % 4];
    const int pieces = std::max(1, static_cast<int>(std::round((b - a).norm() / 6.0)));
    for (int k = 0; k < pieces; ++k) {
      const PlanWall piece{{a + (b - a) * k / pieces, a + (b - a) * (k + 1) / pieces}, false};
      w.plan.walls.push_back(piece);
      w.built.walls.push_back(piece);
      w.glass.push_back(uniform(rng, 0, 1) < glass ? 1 : 0);
    }
  }
}

// Storage rooms along the lower and upper outer walls: a front wall 1.2 m from the outer wall
// and two side walls. The first `moved` front walls were built `shift` further in.
void add_rooms(const Vec2& lo, const Vec2& hi, const IndoorSceneParams& p, IndoorWorld& w,
               std::mt19937_64& rng) {
  const int rooms = std::max(3, p.moved_walls + 1);
  for (int r = 0; r < rooms; ++r) {
    const bool lower = r % 2 == 0;
    const double len = uniform(rng, 4.0, 7.0);
    const double x0 = uniform(rng, lo.x() + 1.0, hi.x() - len - 1.0);
    const double wall_y = lower ? lo.y() : hi.y();
    const double front_y = wall_y + (lower ? 1.2 : -1.2);
    const double shift = r < p.moved_walls ? (lower ? p.wall_shift : -p.wall_shift) : 0.0;
    const PlanWall designed{{{x0, wall_y}, {x0, front_y}, {x0 + len, front_y}, {x0 + len, wall_y}},
                            false};
    PlanWall built = designed;
    built.points[1].y() += shift;
    built.points[2].y() += shift;
    w.plan.walls.push_back(designed);
    w.built.walls.push_back(built);
    w.glass.push_back(0);
  }
}

void add_cars_and_people(const std::vector<double>& xs, const std::vector<double>& ys,
                         const IndoorSceneParams& p, IndoorWorld& w, std::mt19937_64& rng) {
  for (double y : ys)
    for (std::size_t i = 0; i + 1 < xs.size(); ++i)
      for (int side : {-1, 1}) {
        if (uniform(rng, 0, 1) >= p.parking_probability) continue;
        IndoorObstacle car;
        car.center = {0.5 * (xs[i] + xs[i + 1]) + uniform(rng, -1.0, 1.0),
                      y + side * uniform(rng, 1.2, 1.5)};
        car.half = {uniform(rng, 2.0, 2.4), uniform(rng, 0.85, 0.95)};
        car.yaw = uniform(rng, -0.05, 0.05);
        car.height = uniform(rng, 1.4, 1.9);
        w.obstacles.push_back(car);
      }
  for (int k = 0; k < p.people; ++k) {
    IndoorObstacle person;
    person.box = false;
    const std::size_t j = static_cast<std::size_t>(uniform(rng, 0, ys.size() - 1.0));
    person.center = {uniform(rng, xs.front(), xs.back()),
                     0.5 * (ys[j] + ys[j + 1]) + (k % 2 ? 1.0 : -1.0) * uniform(rng, 0.9, 1.3)};
    person.radius = uniform(rng, 0.17, 0.24);
    person.height = uniform(rng, 1.6, 1.9);
    w.obstacles.push_back(person);
  }
}

// A lawnmower path along the aisles between column rows, joined beyond the outer column lines.
std::vector<Vec2> aisle_path(const std::vector<double>& xs, const std::vector<double>& ys,
                             double border) {
  std::vector<Vec2> path;
  const double left = xs.front() - 0.5 * border, right = xs.back() + 0.5 * border;
  for (std::size_t j = 0; j + 1 < ys.size(); ++j) {
    const double y = 0.5 * (ys[j] + ys[j + 1]);
    if (j % 2 == 0) {
      path.push_back({left, y});
      path.push_back({right, y});
    } else {
      path.push_back({right, y});
      path.push_back({left, y});
    }
  }
  return path;
}

std::vector<Eigen::Vector3d> sample_path(const std::vector<Vec2>& path, int n,
                                         std::mt19937_64& rng) {
  double total = 0;
  for (std::size_t i = 1; i < path.size(); ++i) total += (path[i] - path[i - 1]).norm();
  std::vector<Eigen::Vector3d> out;
  for (int k = 0; k < n; ++k) {
    double s = total * (k + 0.5) / n;
    std::size_t i = 1;
    while (i + 1 < path.size() && s > (path[i] - path[i - 1]).norm()) {
      s -= (path[i] - path[i - 1]).norm();
      ++i;
    }
    const Vec2 dir = (path[i] - path[i - 1]).normalized();
    const Vec2 normal(-dir.y(), dir.x());
    const Vec2 at = path[i - 1] + dir * s + normal * uniform(rng, -0.3, 0.3);
    out.emplace_back(at.x(), at.y(), std::atan2(dir.y(), dir.x()) + uniform(rng, -0.4, 0.4));
  }
  return out;
}

// ---- ray casting (horizontal distance t along a unit 2-D direction) --------------------------

double hit_segment(const Vec2& o, const Vec2& d, const Vec2& a, const Vec2& b) {
  const Vec2 e = b - a;
  const double den = d.x() * e.y() - d.y() * e.x();
  if (std::abs(den) < 1e-12) return kInf;
  const Vec2 ao = a - o;
  const double t = (ao.x() * e.y() - ao.y() * e.x()) / den;
  const double u = (ao.x() * d.y() - ao.y() * d.x()) / den;
  return t > 1e-6 && u >= 0 && u <= 1 ? t : kInf;
}

double hit_circle(const Vec2& o, const Vec2& d, const Vec2& c, double r) {
  const Vec2 oc = o - c;
  const double b = oc.dot(d), cc = oc.squaredNorm() - r * r;
  const double disc = b * b - cc;
  if (disc < 0) return kInf;
  const double t = -b - std::sqrt(disc);
  return t > 1e-6 ? t : kInf;
}

// Entry and exit of the ray through a rectangle given by centre, half extents and yaw.
bool slab(const Vec2& o, const Vec2& d, const Vec2& c, const Vec2& half, double yaw, double& t0,
          double& t1) {
  const Eigen::Rotation2Dd R(-yaw);
  const Vec2 lo = R * (o - c), ld = R * d;
  t0 = 0;
  t1 = kInf;
  for (int k = 0; k < 2; ++k) {
    if (std::abs(ld[k]) < 1e-12) {
      if (std::abs(lo[k]) > half[k]) return false;
      continue;
    }
    double a = (-half[k] - lo[k]) / ld[k], b = (half[k] - lo[k]) / ld[k];
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
  }
  return t0 <= t1;
}

struct Hit {
  double t;
  double top;
};

// Everything a horizontal ray meets, nearest first (walls and columns reach the ceiling).
std::vector<Hit> ray_hits(const IndoorWorld& w, const Vec2& o, const Vec2& d) {
  std::vector<Hit> hits;
  for (std::size_t k = 0; k < w.built.walls.size(); ++k) {
    if (w.glass[k]) continue;
    const auto& pts = w.built.walls[k].points;
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
      const double t = hit_segment(o, d, pts[i], pts[i + 1]);
      if (t < kInf) hits.push_back({t, w.ceiling});
    }
  }
  for (const PlanColumn& c : w.built.columns) {
    const double t = hit_circle(o, d, c.center, c.radius);
    if (t < kInf) hits.push_back({t, w.ceiling});
  }
  for (const IndoorObstacle& ob : w.obstacles) {
    double t0 = kInf, t1 = kInf;
    if (ob.box) {
      if (!slab(o, d, ob.center, ob.half, ob.yaw, t0, t1)) continue;
    } else {
      t0 = hit_circle(o, d, ob.center, ob.radius);
    }
    if (t0 > 1e-6 && t0 < kInf) hits.push_back({t0, ob.height});
  }
  std::sort(hits.begin(), hits.end(), [](const Hit& a, const Hit& b) { return a.t < b.t; });
  return hits;
}

// Horizontal distance at which a beam of slope `s` (tan of elevation) from height h meets the
// ramp's sloped floor, or infinity.
double hit_ramp(const IndoorRamp& ramp, const Vec2& o, const Vec2& d, double h, double s) {
  const Vec2 axis(std::cos(ramp.yaw), std::sin(ramp.yaw));
  const Vec2 c = ramp.origin + axis * (0.5 * ramp.length);
  double t0, t1;
  if (!slab(o, d, c, {0.5 * ramp.length, 0.5 * ramp.width}, ramp.yaw, t0, t1)) return kInf;
  // Floor along the ray inside the ramp: a + b t.
  const double k = ramp.rise / ramp.length;
  const double a = k * (o - ramp.origin).dot(axis), b = k * d.dot(axis);
  if (std::abs(b - s) < 1e-12) return kInf;
  const double t = (h - a) / (b - s);
  return t >= t0 && t <= t1 && t > 0 ? t : kInf;
}

}  // namespace

IndoorWorld make_indoor_world(const IndoorSceneParams& p, int scans) {
  if (p.grid_x < 2 || p.grid_y < 2) throw InputError("indoor scene: needs at least a 2x2 grid");
  std::mt19937_64 rng(p.seed);
  IndoorWorld w;
  w.ceiling = p.ceiling;
  const auto xs = column_lines(p.grid_x, p.pitch_x, p.line_jitter, rng);
  const auto ys = column_lines(p.grid_y, p.pitch_y, p.line_jitter, rng);
  for (double x : xs)
    for (double y : ys) {
      if (uniform(rng, 0, 1) < p.missing_columns) continue;
      w.plan.columns.push_back({{x, y}, p.column_radius});
      // One draw per statement (argument order is unspecified; compilers differ), y first.
      const double off_y = uniform(rng, -p.column_jitter, p.column_jitter);
      const Vec2 off(uniform(rng, -p.column_jitter, p.column_jitter), off_y);
      w.built.columns.push_back({Vec2(x, y) + off, p.column_radius});
    }
  const Vec2 lo(xs.front() - p.border, ys.front() - p.border);
  const Vec2 hi(xs.back() + p.border, ys.back() + p.border);
  add_outer_walls(lo, hi, w, p.glass_fraction, rng);
  add_rooms(lo, hi, p, w, rng);
  // The ramp in the upper border strip; its inner edge is drawn in the plan, not built.
  w.ramp.origin = {xs[1], ys.back() + 0.5 * p.border + 0.3};
  w.ramp.length = std::min(12.0, xs.back() - xs[1]);
  w.ramp.width = 3.6;
  w.ramp.rise = p.ceiling;
  const double edge = w.ramp.origin.y() - 0.5 * w.ramp.width;
  w.plan.walls.push_back({{{xs[1], edge}, {xs[1] + w.ramp.length, edge}}, false});
  add_cars_and_people(xs, ys, p, w, rng);
  w.trajectory = sample_path(aisle_path(xs, ys, p.border), scans, rng);
  return w;
}

Transform pose_transform(const Eigen::Vector3d& pose) {
  Transform T = Transform::Identity();
  T.block<2, 2>(0, 0) = Eigen::Rotation2Dd(pose.z()).toRotationMatrix();
  T(0, 3) = pose.x();
  T(1, 3) = pose.y();
  return T;
}

PointCloud ray_cast_indoor(const IndoorWorld& w, const Eigen::Vector3d& pose,
                           const IndoorLidarParams& lidar, std::mt19937_64& rng) {
  PointCloud cloud;
  std::normal_distribution<double> noise(0.0, lidar.range_noise);
  const Vec2 o(pose.x(), pose.y());
  const double h = lidar.sensor_height;
  for (int a = 0; a < lidar.azimuths; ++a) {
    const double az = 2.0 * M_PI * a / lidar.azimuths;
    const Vec2 d(std::cos(pose.z() + az), std::sin(pose.z() + az));
    const std::vector<Hit> hits = ray_hits(w, o, d);
    for (int b = 0; b < lidar.beams; ++b) {
      const double el =
          (lidar.fov_down + (lidar.fov_up - lidar.fov_down) * b / std::max(1, lidar.beams - 1)) *
          M_PI / 180.0;
      const double s = std::tan(el);
      double t = kInf;
      for (const Hit& hit : hits) {
        const double z = h + s * hit.t;
        if (z < 0 || z > w.ceiling) break;  // the beam met floor or ceiling first
        if (z <= hit.top) {
          t = hit.t;
          break;
        }
      }
      if (s < 0) t = std::min(t, h / -s);
      if (s > 0) t = std::min(t, (w.ceiling - h) / s);
      t = std::min(t, hit_ramp(w.ramp, o, d, h, s));
      const double range = t / std::cos(el);
      if (!(range < lidar.max_range) || uniform(rng, 0, 1) < lidar.dropout) continue;
      const double r = range + noise(rng);
      cloud.points.emplace_back(static_cast<float>(r * std::cos(el) * std::cos(az)),
                                static_cast<float>(r * std::cos(el) * std::sin(az)),
                                static_cast<float>(r * std::sin(el)));
    }
  }
  return cloud;
}

DetectionScore score_scan_columns(const IndoorWorld& world, const Eigen::Vector3d& pose,
                                  const PointCloud& scan, const IndoorParams& params,
                                  int min_visible_points, double match_distance) {
  const FloorScan fs = prepare_floor_scan(scan, params);
  const Eigen::Rotation2Dd R_scan_plan(-pose.z());
  std::vector<PlanColumn> planted;
  for (const PlanColumn& c : world.built.columns)
    planted.push_back({R_scan_plan * (c.center - Vec2(pose.x(), pose.y())), c.radius});
  return score_detection(fs.columns, planted, fs.floor, min_visible_points, match_distance);
}

void write_indoor_sequence(const std::string& dir, const IndoorSceneParams& params, int scans,
                           const IndoorLidarParams& lidar) {
  if (scans < 1) throw InputError("indoor sequence: needs at least one scan");
  namespace fs = std::filesystem;
  std::error_code ec;
  for (const char* sub : {"", "scans", "gt"}) {
    fs::create_directories(fs::path(dir) / sub, ec);
    if (ec) throw InputError(dir + ": cannot create directory " + sub + " (" + ec.message() + ")");
  }
  // The manifest goes first and comes back last: an interrupted run leaves no manifest that
  // would pair the files of two runs (every file itself is written whole, atomic_file.hpp).
  const fs::path manifest = fs::path(dir) / "pairs.txt";
  fs::remove(manifest, ec);
  if (ec)
    throw InputError(manifest.string() + ": cannot remove the old manifest (" + ec.message() + ")");
  const IndoorWorld w = make_indoor_world(params, scans);
  write_floor_plan(w.plan, (fs::path(dir) / "plan.json").string());
  write_floor_plan(w.built, (fs::path(dir) / "built.json").string());
  std::string poses = "# x [m] y [m] yaw [rad] of each scan in the plan frame\n";
  std::string pairs = "# generated indoor sequence (seed " + std::to_string(params.seed) +
                      "): each scan against the floor plan; run with pagor bench --preset indoor\n";
  char buf[160];
  for (int k = 0; k < scans; ++k) {
    const Eigen::Vector3d& pose = w.trajectory[static_cast<std::size_t>(k)];
    std::mt19937_64 rng(params.seed * 1000003u + static_cast<std::uint64_t>(k));
    std::snprintf(buf, sizeof(buf), "%06d", k);
    const std::string name = buf;
    write_kitti_bin(ray_cast_indoor(w, pose, lidar, rng),
                    (fs::path(dir) / "scans" / (name + ".bin")).string());
    write_file_atomic((fs::path(dir) / "gt" / (name + ".txt")).string(),
                      transform_file_text(pose_transform(pose)));
    std::snprintf(buf, sizeof(buf), "%.6f %.6f %.6f\n", pose.x(), pose.y(), pose.z());
    poses += buf;
    pairs += "scans/" + name + ".bin plan.json gt=gt/" + name + ".txt name=" + name + "\n";
  }
  write_file_atomic((fs::path(dir) / "poses.txt").string(), poses);
  write_file_atomic(manifest.string(), pairs);
}

}  // namespace pagor
