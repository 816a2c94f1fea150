#include "pagor/indoor/floor_plan.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "pagor/errors.hpp"
#include "pagor/io/atomic_file.hpp"
#include "pagor/io/clouds.hpp"
#include "pagor/io/file_input.hpp"
#include "pagor/io/json_input.hpp"

namespace pagor {
namespace {

using json = nlohmann::json;

[[noreturn]] void fail(const std::string& where, const std::string& what) {
  throw InputError(where + ": " + what);
}

double finite_number(const json& j, const std::string& where) {
  if (!j.is_number()) fail(where, "expected a number, got " + json_excerpt(j));
  const double v = j.get<double>();
  if (!std::isfinite(v)) fail(where, "not a finite number");
  return v;
}

Eigen::Vector2d point_of(const json& j, const std::string& where) {
  if (!j.is_array() || j.size() != 2)
    fail(where, "expected a point [x, y] in metres, got " + json_excerpt(j));
  const Eigen::Vector2d p(finite_number(j[0], where + "[0]"), finite_number(j[1], where + "[1]"));
  if (!(p.cwiseAbs().maxCoeff() <= kMaxPlanCoordinate))
    fail(where, "lies more than 1e7 m from the origin");
  return p;
}

const json& member(const json& obj, const char* key, const std::string& where) {
  const auto it = obj.find(key);
  if (it == obj.end()) fail(where, std::string("missing \"") + key + "\"");
  return *it;
}

PlanWall wall_of(const json& j, const std::string& where) {
  if (!j.is_object()) fail(where, "expected an object {\"points\": [[x, y], ...]}");
  for (const auto& item : j.items())
    if (item.key() != "points" && item.key() != "closed")
      fail(where + "." + item.key(), "unknown key (a wall has \"points\" and \"closed\")");
  PlanWall w;
  const json& pts = member(j, "points", where);
  if (!pts.is_array()) fail(where + ".points", "expected an array of [x, y] points");
  if (pts.size() < 2) fail(where + ".points", "a wall needs at least two points");
  for (std::size_t i = 0; i < pts.size(); ++i)
    w.points.push_back(point_of(pts[i], where + ".points[" + std::to_string(i) + "]"));
  if (const auto it = j.find("closed"); it != j.end()) {
    if (!it->is_boolean()) fail(where + ".closed", "expected true or false");
    w.closed = it->get<bool>();
  }
  return w;
}

PlanColumn column_of(const json& j, const std::string& where) {
  if (!j.is_object()) fail(where, "expected an object {\"center\": [x, y], \"radius\": r}");
  for (const auto& item : j.items())
    if (item.key() != "center" && item.key() != "radius")
      fail(where + "." + item.key(), "unknown key (a column has \"center\" and \"radius\")");
  PlanColumn c;
  c.center = point_of(member(j, "center", where), where + ".center");
  c.radius = finite_number(member(j, "radius", where), where + ".radius");
  if (c.radius <= 0 || c.radius > kMaxColumnRadius)
    fail(where + ".radius", "must be in (0, 100] [m]");
  return c;
}

}  // namespace

FloorPlan parse_floor_plan_json(std::string_view text, const std::string& origin) {
  json j;
  try {
    j = parse_json_limited(std::string(text), origin);
  } catch (const ConfigError& e) {
    throw InputError(e.what());
  }
  if (!j.is_object()) fail(origin, "expected a JSON object with \"walls\" and \"columns\"");
  FloorPlan plan;
  for (const auto& item : j.items()) {
    const std::string& key = item.key();
    const json& v = item.value();
    const std::string where = origin + ": " + key;
    if (key == "format") {
      if (!v.is_string() || v.get<std::string>() != "pagor.floor_plan/1")
        fail(where, "expected \"pagor.floor_plan/1\", got " + json_excerpt(v));
    } else if (key == "walls" || key == "columns") {
      if (!v.is_array()) fail(where, "expected an array");
      for (std::size_t i = 0; i < v.size(); ++i) {
        const std::string at = where + "[" + std::to_string(i) + "]";
        if (key == "walls")
          plan.walls.push_back(wall_of(v[i], at));
        else
          plan.columns.push_back(column_of(v[i], at));
      }
    } else {
      fail(where, "unknown key (a plan has \"format\", \"walls\" and \"columns\")");
    }
  }
  if (plan.walls.empty() && plan.columns.empty())
    fail(origin, "the plan has neither walls nor columns");
  return plan;
}

bool is_floor_plan_path(const std::string& path) {
  const std::string ext = file_extension(path);
  return ext == ".json" || ext == ".svg";
}

FloorPlan read_floor_plan(const std::string& path) {
  if (!is_floor_plan_path(path))
    fail(path, "a floor plan must be a .json or .svg file (format: floor_plan.hpp, README)");
  const std::string text = read_file(path, "floor plan", kMaxTextFileBytes);
  return file_extension(path) == ".svg" ? parse_floor_plan_svg(text, path)
                                        : parse_floor_plan_json(text, path);
}

std::string floor_plan_to_json(const FloorPlan& plan) {
  json walls = json::array(), columns = json::array();
  for (const PlanWall& w : plan.walls) {
    json pts = json::array();
    for (const auto& p : w.points) pts.push_back({p.x(), p.y()});
    walls.push_back({{"points", pts}, {"closed", w.closed}});
  }
  for (const PlanColumn& c : plan.columns)
    columns.push_back({{"center", {c.center.x(), c.center.y()}}, {"radius", c.radius}});
  const json j = {{"format", "pagor.floor_plan/1"}, {"walls", walls}, {"columns", columns}};
  return j.dump(1) + "\n";
}

void write_floor_plan(const FloorPlan& plan, const std::string& path) {
  write_file_atomic(path, floor_plan_to_json(plan));
}

namespace {

// Points sample_circle makes for a column, as a double (no overflow whatever the input).
double circle_samples(double radius, double spacing) {
  return std::max(8.0, std::ceil(2.0 * M_PI * radius / spacing));
}

// Steps sample_floor_plan makes along a segment [a, b], as a double.
double segment_steps(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double spacing) {
  return std::max(1.0, std::ceil((b - a).norm() / spacing));
}

// Throws, naming the element, when sampling would make more than kMaxPlanSamples points.
void check_samples(const FloorPlan& plan, double spacing) {
  double total = 0;
  const auto over = [&](const std::string& element) {
    char buf[200];
    std::snprintf(buf, sizeof(buf),
                  "%s: sampling the plan every %g m would make more than %zu points (the budget, "
                  "kMaxPlanSamples); is a coordinate in the wrong unit?",
                  element.c_str(), spacing, kMaxPlanSamples);
    throw InputError(buf);
  };
  for (std::size_t i = 0; i < plan.walls.size(); ++i) {
    const PlanWall& w = plan.walls[i];
    const std::size_t n = w.points.size(), segments = w.closed ? n : n - 1;
    for (std::size_t k = 0; k < segments; ++k)
      total += segment_steps(w.points[k], w.points[(k + 1) % n], spacing);
    total += w.closed ? 0 : 1;
    if (!(total <= static_cast<double>(kMaxPlanSamples))) over("walls[" + std::to_string(i) + "]");
  }
  for (std::size_t i = 0; i < plan.columns.size(); ++i) {
    total += circle_samples(plan.columns[i].radius, spacing);
    if (!(total <= static_cast<double>(kMaxPlanSamples)))
      over("columns[" + std::to_string(i) + "]");
  }
}

}  // namespace

void sample_circle(const Eigen::Vector2d& center, double radius, double spacing,
                   std::uint32_t label, PointCloud& out) {
  const double samples = circle_samples(radius, spacing);
  if (!(samples <= static_cast<double>(kMaxPlanSamples)))
    throw InputError("a column of radius " + std::to_string(radius) + " m sampled every " +
                     std::to_string(spacing) + " m would make more than 10^7 points");
  const int n = static_cast<int>(samples);
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * M_PI * i / n;
    out.points.emplace_back(static_cast<float>(center.x() + radius * std::cos(a)),
                            static_cast<float>(center.y() + radius * std::sin(a)), 0.0f);
    out.labels.push_back(label);
  }
}

PointCloud sample_floor_plan(const FloorPlan& plan, double spacing) {
  if (!(spacing > 0)) throw InputError("floor plan sampling: spacing must be > 0 [m]");
  check_samples(plan, spacing);
  PointCloud out;
  for (const PlanWall& w : plan.walls) {
    const std::size_t n = w.points.size();
    const std::size_t segments = w.closed ? n : n - 1;
    for (std::size_t i = 0; i < segments; ++i) {
      const Eigen::Vector2d a = w.points[i], b = w.points[(i + 1) % n];
      const int steps = static_cast<int>(segment_steps(a, b, spacing));  // <= kMaxPlanSamples
      // The end vertex belongs to the next segment (or is added below for an open polyline).
      for (int k = 0; k < steps; ++k) {
        const Eigen::Vector2d p = a + (b - a) * (static_cast<double>(k) / steps);
        out.points.emplace_back(static_cast<float>(p.x()), static_cast<float>(p.y()), 0.0f);
        out.labels.push_back(kWallLabel);
      }
    }
    if (!w.closed) {
      out.points.emplace_back(static_cast<float>(w.points.back().x()),
                              static_cast<float>(w.points.back().y()), 0.0f);
      out.labels.push_back(kWallLabel);
    }
  }
  for (const PlanColumn& c : plan.columns)
    sample_circle(c.center, c.radius, spacing, kColumnLabel, out);
  return out;
}

}  // namespace pagor
