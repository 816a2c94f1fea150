#include "pagor/indoor/column_detector.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace pagor {
namespace {

// Shifted as unsigned: a negative cell index shifted left is undefined behaviour.
std::int64_t cell_key(std::int64_t ix, std::int64_t iy) {
  return static_cast<std::int64_t>((static_cast<std::uint64_t>(ix) << 32) ^
                                   (static_cast<std::uint64_t>(iy) & 0xFFFFFFFFu));
}

// Largest angular gap between the points around `c`, subtracted from 360 [deg].
double arc_coverage_deg(const std::vector<Eigen::Vector2d>& pts, const Eigen::Vector2d& c) {
  std::vector<double> a;
  for (const auto& p : pts) a.push_back(std::atan2(p.y() - c.y(), p.x() - c.x()));
  std::sort(a.begin(), a.end());
  double gap = 2 * M_PI - (a.back() - a.front());
  for (std::size_t i = 1; i < a.size(); ++i) gap = std::max(gap, a[i] - a[i - 1]);
  return (2 * M_PI - gap) * 180.0 / M_PI;
}

}  // namespace

CircleFit fit_circle(const std::vector<Eigen::Vector2d>& pts) {
  CircleFit f;
  if (pts.size() < 3) return f;
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const auto& p : pts) mean += p;
  mean /= static_cast<double>(pts.size());
  // Kasa: x^2 + y^2 + D x + E y + F = 0, on centred coordinates for conditioning.
  Eigen::MatrixXd A(pts.size(), 3);
  Eigen::VectorXd b(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Eigen::Vector2d d = pts[i] - mean;
    A.row(static_cast<Eigen::Index>(i)) << d.x(), d.y(), 1.0;
    b(static_cast<Eigen::Index>(i)) = -(d.x() * d.x() + d.y() * d.y());
  }
  const Eigen::Vector3d s = A.colPivHouseholderQr().solve(b);
  if (!s.allFinite()) return f;
  Eigen::Vector2d c(-s(0) / 2, -s(1) / 2);
  const double r2 = c.squaredNorm() - s(2);
  if (!(r2 > 0) || A.colPivHouseholderQr().rank() < 3) return f;
  double r = std::sqrt(r2);
  // Gauss-Newton on the geometric residuals |p - c| - r.
  for (int it = 0; it < 10; ++it) {
    Eigen::Matrix3d JtJ = Eigen::Matrix3d::Zero();
    Eigen::Vector3d Jtr = Eigen::Vector3d::Zero();
    for (const auto& p : pts) {
      const Eigen::Vector2d d = p - mean - c;
      const double n = d.norm();
      if (n < 1e-12) continue;
      const Eigen::Vector3d J(-d.x() / n, -d.y() / n, -1.0);
      JtJ += J * J.transpose();
      Jtr += J * (n - r);
    }
    const Eigen::Vector3d step = JtJ.ldlt().solve(-Jtr);
    if (!step.allFinite()) break;
    c += step.head<2>();
    r += step(2);
    if (step.norm() < 1e-9) break;
  }
  double ss = 0;
  for (const auto& p : pts) ss += std::pow((p - mean - c).norm() - r, 2);
  f.ok = r > 0 && std::isfinite(r);
  f.center = c + mean;
  f.radius = r;
  f.rms = std::sqrt(ss / static_cast<double>(pts.size()));
  return f;
}

std::vector<std::vector<int>> cluster_2d(const std::vector<Eigen::Vector2d>& points,
                                         double tolerance) {
  std::unordered_map<std::int64_t, std::vector<int>> grid;
  const auto cell = [&](const Eigen::Vector2d& p) {
    return std::make_pair(static_cast<std::int64_t>(std::floor(p.x() / tolerance)),
                          static_cast<std::int64_t>(std::floor(p.y() / tolerance)));
  };
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto [x, y] = cell(points[i]);
    grid[cell_key(x, y)].push_back(static_cast<int>(i));
  }
  std::vector<char> seen(points.size(), 0);
  std::vector<std::vector<int>> out;
  const double tol2 = tolerance * tolerance;
  for (std::size_t seed = 0; seed < points.size(); ++seed) {
    if (seen[seed]) continue;
    std::vector<int> group{static_cast<int>(seed)};
    seen[seed] = 1;
    for (std::size_t k = 0; k < group.size(); ++k) {
      const Eigen::Vector2d& p = points[static_cast<std::size_t>(group[k])];
      const auto [cx, cy] = cell(p);
      for (std::int64_t dx = -1; dx <= 1; ++dx)
        for (std::int64_t dy = -1; dy <= 1; ++dy) {
          const auto it = grid.find(cell_key(cx + dx, cy + dy));
          if (it == grid.end()) continue;
          for (int j : it->second)
            if (!seen[static_cast<std::size_t>(j)] &&
                (points[static_cast<std::size_t>(j)] - p).squaredNorm() <= tol2) {
              seen[static_cast<std::size_t>(j)] = 1;
              group.push_back(j);
            }
        }
    }
    out.push_back(std::move(group));
  }
  return out;
}

std::vector<DetectedColumn> detect_columns(const std::vector<Eigen::Vector2d>& points,
                                           const ColumnDetectorParams& params) {
  std::vector<DetectedColumn> out;
  const double max_extent = 2.0 * params.max_radius + params.cluster_tolerance;
  for (const auto& group : cluster_2d(points, params.cluster_tolerance)) {
    if (static_cast<int>(group.size()) < params.min_points) continue;
    std::vector<Eigen::Vector2d> pts;
    Eigen::Vector2d lo = points[static_cast<std::size_t>(group[0])], hi = lo;
    for (int i : group) {
      pts.push_back(points[static_cast<std::size_t>(i)]);
      lo = lo.cwiseMin(pts.back());
      hi = hi.cwiseMax(pts.back());
    }
    if ((hi - lo).norm() > max_extent) continue;
    const CircleFit fit = fit_circle(pts);
    if (!fit.ok || fit.radius < params.min_radius || fit.radius > params.max_radius ||
        fit.rms > params.max_rms)
      continue;
    // A column is convex towards the sensor: its centre lies behind its points.
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();
    for (const auto& p : pts) mean += p;
    mean /= static_cast<double>(pts.size());
    if (fit.center.norm() <= mean.norm()) continue;
    const double arc = arc_coverage_deg(pts, fit.center);
    if (arc < params.min_arc_deg) continue;
    out.push_back({fit.center, fit.radius, fit.rms, arc, group});
  }
  return out;
}

DetectionScore& DetectionScore::operator+=(const DetectionScore& o) {
  visible += o.visible;
  found += o.found;
  detections += o.detections;
  true_detections += o.true_detections;
  return *this;
}

DetectionScore score_detection(const std::vector<DetectedColumn>& detected,
                               const std::vector<PlanColumn>& planted,
                               const std::vector<Eigen::Vector2d>& points, int min_visible_points,
                               double match_distance) {
  DetectionScore s;
  s.detections = static_cast<int>(detected.size());
  for (const DetectedColumn& d : detected)
    for (const PlanColumn& c : planted)
      if ((d.center - c.center).norm() <= match_distance) {
        ++s.true_detections;
        break;
      }
  for (const PlanColumn& c : planted) {
    int on = 0;
    for (const auto& p : points) on += std::abs((p - c.center).norm() - c.radius) <= 0.1;
    if (on < min_visible_points) continue;
    ++s.visible;
    for (const DetectedColumn& d : detected)
      if ((d.center - c.center).norm() <= match_distance) {
        ++s.found;
        break;
      }
  }
  return s;
}

}  // namespace pagor
