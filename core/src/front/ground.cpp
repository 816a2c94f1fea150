#include "pagor/front/ground.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pagor {
namespace {

constexpr int kMaxCellsAcross = 2048;  // a 4 km wide cloud on the default 2 m grid
constexpr double kLowQuantile = 0.1;   // a cell's low point: below-ground outliers left out

// The horizontal grid over the finite points.
struct Grid {
  double x0 = 0, y0 = 0, cell = 1;
  int nx = 0, ny = 0;
  int index(const Eigen::Vector3f& p) const {
    const int ix = std::clamp(static_cast<int>((p.x() - x0) / cell), 0, nx - 1);
    const int iy = std::clamp(static_cast<int>((p.y() - y0) / cell), 0, ny - 1);
    return iy * nx + ix;
  }
};

Grid grid_over(const std::vector<Eigen::Vector3f>& points, double cell) {
  Grid g;
  double lo_x = HUGE_VAL, lo_y = HUGE_VAL, hi_x = -HUGE_VAL, hi_y = -HUGE_VAL;
  for (const auto& p : points) {
    if (!p.allFinite()) continue;
    lo_x = std::min(lo_x, double(p.x())), hi_x = std::max(hi_x, double(p.x()));
    lo_y = std::min(lo_y, double(p.y())), hi_y = std::max(hi_y, double(p.y()));
  }
  if (!(lo_x <= hi_x)) return g;
  g.cell = std::max({cell, (hi_x - lo_x) / kMaxCellsAcross, (hi_y - lo_y) / kMaxCellsAcross});
  g.x0 = lo_x, g.y0 = lo_y;
  g.nx = static_cast<int>((hi_x - lo_x) / g.cell) + 1;
  g.ny = static_cast<int>((hi_y - lo_y) / g.cell) + 1;
  return g;
}

// Each cell's low point: the kLowQuantile height of its points (+inf for an empty cell).
std::vector<double> low_points(const std::vector<Eigen::Vector3f>& points, const Grid& g) {
  const std::size_t cells = static_cast<std::size_t>(g.nx) * static_cast<std::size_t>(g.ny);
  std::vector<int> start(cells + 1, 0);
  for (const auto& p : points)
    if (p.allFinite()) ++start[static_cast<std::size_t>(g.index(p)) + 1];
  for (std::size_t c = 0; c < cells; ++c) start[c + 1] += start[c];
  std::vector<float> z(static_cast<std::size_t>(start[cells]));
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (const auto& p : points)
    if (p.allFinite())
      z[static_cast<std::size_t>(fill[static_cast<std::size_t>(g.index(p))]++)] = p.z();
  std::vector<double> low(cells, HUGE_VAL);
  for (std::size_t c = 0; c < cells; ++c) {
    const auto b = z.begin() + start[c], e = z.begin() + start[c + 1];
    if (b == e) continue;
    const auto k = b + static_cast<long>(kLowQuantile * static_cast<double>(e - b - 1));
    std::nth_element(b, k, e);
    low[c] = *k;
  }
  return low;
}

// surface(c) = min over cells d of low(d) + rise * |c - d|: a chamfer transform (forward and
// backward raster passes over the 8 neighbours), repeated until nothing changes.
void bound_slope(std::vector<double>& s, const Grid& g, double rise) {
  const double diagonal = rise * std::sqrt(2.0);
  const auto relax = [&](int x, int y, int dx, int dy, double step) {
    const int u = x + dx, v = y + dy;
    if (u < 0 || v < 0 || u >= g.nx || v >= g.ny) return false;
    double& here = s[static_cast<std::size_t>(y * g.nx + x)];
    const double via = s[static_cast<std::size_t>(v * g.nx + u)] + step;
    if (via >= here) return false;
    here = via;
    return true;
  };
  for (bool changed = true; changed;) {
    changed = false;
    for (int y = 0; y < g.ny; ++y)
      for (int x = 0; x < g.nx; ++x) {  // every neighbour relaxed, in this order
        changed |= relax(x, y, -1, 0, rise);
        changed |= relax(x, y, 0, -1, rise);
        changed |= relax(x, y, -1, -1, diagonal);
        changed |= relax(x, y, 1, -1, diagonal);
      }
    for (int y = g.ny - 1; y >= 0; --y)
      for (int x = g.nx - 1; x >= 0; --x) {
        changed |= relax(x, y, 1, 0, rise);
        changed |= relax(x, y, 0, 1, rise);
        changed |= relax(x, y, 1, 1, diagonal);
        changed |= relax(x, y, -1, 1, diagonal);
      }
  }
}

}  // namespace

std::vector<char> ground_points(const std::vector<Eigen::Vector3f>& points,
                                const GroundParams& params) {
  std::vector<char> ground(points.size(), 0);
  const Grid g = grid_over(points, params.cell);
  if (g.nx == 0) return ground;
  std::vector<double> surface = low_points(points, g);
  bound_slope(surface, g, params.max_slope * g.cell);
  for (std::size_t i = 0; i < points.size(); ++i)
    if (points[i].allFinite())
      ground[i] =
          points[i].z() <= surface[static_cast<std::size_t>(g.index(points[i]))] + params.thickness;
  return ground;
}

}  // namespace pagor
