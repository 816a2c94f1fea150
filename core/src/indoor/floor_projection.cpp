#include "pagor/indoor/floor_projection.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>

#include "pagor/errors.hpp"
#include "pagor/indoor/floor_plan.hpp"

namespace pagor {

std::vector<char> passed_over(const PointCloud& scan, double gap) {
  std::vector<char> out(scan.size(), 0);
  if (!(gap > 0)) return out;
  // Azimuth bins of half a degree; in each, from the highest elevation down, the furthest
  // horizontal range seen so far among points clearly higher (by more than 0.5 degrees).
  constexpr double kBin = 0.5 * M_PI / 180.0, kHigher = 0.5 * M_PI / 180.0;
  struct Ray {
    double elevation, range;
    std::size_t index;
  };
  std::unordered_map<int, std::vector<Ray>> bins;
  for (std::size_t i = 0; i < scan.size(); ++i) {
    const Eigen::Vector3f& p = scan.points[i];
    const double range = std::hypot(double(p.x()), double(p.y()));
    if (!(range > 0)) continue;
    const int bin = static_cast<int>(std::floor(std::atan2(double(p.y()), double(p.x())) / kBin));
    bins[bin].push_back({std::atan2(double(p.z()), range), range, i});
  }
  for (auto& [bin, rays] : bins) {
    std::sort(rays.begin(), rays.end(), [](const Ray& a, const Ray& b) {
      return a.elevation > b.elevation || (a.elevation == b.elevation && a.index < b.index);
    });
    double furthest = -HUGE_VAL;  // among the rays more than kHigher above the current one
    std::size_t above = 0;
    for (const Ray& r : rays) {
      while (above < rays.size() && rays[above].elevation > r.elevation + kHigher)
        furthest = std::max(furthest, rays[above++].range);
      out[r.index] = furthest >= r.range + gap;
    }
  }
  return out;
}

std::vector<Eigen::Vector2d> project_to_floor(const PointCloud& scan, const IndoorParams& params,
                                              std::vector<std::uint32_t>* labels,
                                              std::size_t* in_band, std::vector<char>* furniture) {
  struct Cell {
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    int n = 0;
    int passed = 0;  // points a higher beam passed over
    std::map<std::uint32_t, int> votes;
    std::size_t order = 0;
  };
  std::unordered_map<std::int64_t, Cell> cells;
  const double v = params.floor_voxel;
  std::size_t band = 0;
  const bool with_labels = labels && scan.has_labels();
  const std::vector<char> passed =
      furniture ? passed_over(scan, params.furniture_gap) : std::vector<char>(scan.size(), 0);
  for (std::size_t i = 0; i < scan.size(); ++i) {
    const Eigen::Vector3f& p = scan.points[i];
    if (p.z() < params.height_min || p.z() > params.height_max) continue;
    ++band;
    const auto ix = static_cast<std::int64_t>(std::floor(p.x() / v));
    const auto iy = static_cast<std::int64_t>(std::floor(p.y() / v));
    // Shifted as unsigned: a negative cell index shifted left is undefined behaviour.
    const auto key = static_cast<std::int64_t>((static_cast<std::uint64_t>(ix) << 32) ^
                                               (static_cast<std::uint64_t>(iy) & 0xFFFFFFFFu));
    auto [it, fresh] = cells.try_emplace(key);
    if (fresh) it->second.order = cells.size();
    it->second.sum += Eigen::Vector2d(p.x(), p.y());
    ++it->second.n;
    it->second.passed += passed[i];
    if (with_labels) ++it->second.votes[semantic_id(scan.labels[i])];
  }
  // Cells in first-seen order, so the output does not depend on the hash table's layout.
  std::vector<const Cell*> ordered(cells.size());
  for (const auto& [key, cell] : cells) ordered[cell.order - 1] = &cell;
  std::vector<Eigen::Vector2d> out;
  if (labels) labels->clear();
  if (furniture) furniture->clear();
  for (const Cell* c : ordered) {
    out.push_back(c->sum / c->n);
    if (furniture) furniture->push_back(c->passed == c->n);
    if (!labels) continue;
    std::uint32_t best = 0;
    int most = -1;
    for (const auto& [id, n] : c->votes)
      if (n > most) most = n, best = id;
    labels->push_back(best);
  }
  if (in_band) *in_band = band;
  return out;
}

namespace {

// Columns given as labels: each cluster of column-labelled cells, fitted with a circle.
std::vector<DetectedColumn> labelled_columns(const std::vector<Eigen::Vector2d>& floor,
                                             const std::vector<std::uint32_t>& labels,
                                             const ColumnDetectorParams& params) {
  std::vector<int> index;
  std::vector<Eigen::Vector2d> pts;
  for (std::size_t i = 0; i < floor.size(); ++i)
    if (i < labels.size() && labels[i] == kColumnLabel) {
      index.push_back(static_cast<int>(i));
      pts.push_back(floor[i]);
    }
  std::vector<DetectedColumn> out;
  for (const auto& group : cluster_2d(pts, params.cluster_tolerance)) {
    std::vector<Eigen::Vector2d> g;
    for (int i : group) g.push_back(pts[static_cast<std::size_t>(i)]);
    const CircleFit fit = fit_circle(g);
    if (!fit.ok || fit.radius > 4 * params.max_radius) continue;
    DetectedColumn d{fit.center, fit.radius, fit.rms, 0.0, {}};
    for (int i : group) d.points.push_back(index[static_cast<std::size_t>(i)]);
    out.push_back(std::move(d));
  }
  return out;
}

}  // namespace

FloorScan prepare_floor_scan(const PointCloud& scan, const IndoorParams& params) {
  FloorScan out;
  std::vector<std::uint32_t> labels;
  const bool use_labels = !params.detect_columns && scan.has_labels();
  std::vector<char> furniture;
  out.floor =
      project_to_floor(scan, params, use_labels ? &labels : nullptr, &out.in_band, &furniture);
  if (out.floor.empty())
    throw InputError("no scan point lies within the height band [" +
                     std::to_string(params.height_min) + ", " + std::to_string(params.height_max) +
                     "] m (indoor.height_min/max; z up, in the scan frame)");
  out.columns = use_labels ? labelled_columns(out.floor, labels, params.columns)
                           : detect_columns(out.floor, params.columns);
  std::vector<char> on_column(out.floor.size(), 0);
  for (const DetectedColumn& c : out.columns)
    for (int i : c.points) on_column[static_cast<std::size_t>(i)] = 1;
  for (std::size_t i = 0; i < out.floor.size(); ++i) {
    if (on_column[i]) continue;
    out.cloud.points.emplace_back(static_cast<float>(out.floor[i].x()),
                                  static_cast<float>(out.floor[i].y()), 0.0f);
    out.cloud.labels.push_back(furniture[i] ? kFurnitureLabel : kWallLabel);
    out.furniture += furniture[i] != 0;
  }
  for (const DetectedColumn& c : out.columns)
    sample_circle(c.center, c.radius, params.plan_spacing, kColumnLabel, out.cloud);
  return out;
}

}  // namespace pagor
