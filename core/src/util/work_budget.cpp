#include "pagor/util/work_budget.hpp"

#include <cstdio>

#include "pagor/errors.hpp"

namespace pagor {

void check_radius_work(const std::vector<Eigen::Vector3f>& points, double radius,
                       const std::string& key, const std::string& what) {
  const std::size_t n = points.size();
  // Fast exit: even if every point saw every other, the work is within budget.
  if (static_cast<double>(n) * static_cast<double>(n) <= kMaxNeighbourVisits) return;
  const std::size_t samples = 64;
  const double r2 = radius * radius;
  double found = 0;
  for (std::size_t s = 0; s < samples; ++s) {
    const Eigen::Vector3d p = points[s * n / samples].cast<double>();
    for (const auto& q : points) found += (q.cast<double>() - p).squaredNorm() <= r2;
  }
  const double visits = found / static_cast<double>(samples) * static_cast<double>(n);
  if (visits <= kMaxNeighbourVisits) return;
  char buf[256];
  std::snprintf(buf, sizeof(buf),
                "%s: %g m over the %zu voxels of %s means about %.3g neighbour visits (budget "
                "%.0e); use a smaller radius or a larger voxel_size",
                key.c_str(), radius, n, what.c_str(), visits, kMaxNeighbourVisits);
  throw ConfigError(buf);
}

}  // namespace pagor
