#include "pagor/voxel_grid.hpp"

#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace pagor {
namespace {

// Packs a voxel coordinate into 63 bits (21 bits per axis, about +-1e6 voxels).
std::uint64_t voxel_key(const Eigen::Vector3f& p, float inv) {
  const auto axis = [inv](float v) {
    const std::int64_t c = static_cast<std::int64_t>(std::floor(v * inv)) + (1 << 20);
    return static_cast<std::uint64_t>(c) & 0x1FFFFFu;
  };
  return (axis(p.x()) << 42) | (axis(p.y()) << 21) | axis(p.z());
}

}  // namespace

VoxelDownsample voxel_downsample(const std::vector<Eigen::Vector3f>& points, double voxel_size,
                                 const std::vector<int>* subset) {
  const std::size_t n = subset ? subset->size() : points.size();
  const auto point = [&](std::size_t i) -> const Eigen::Vector3f& {
    return points[subset ? static_cast<std::size_t>((*subset)[i]) : i];
  };
  VoxelDownsample out;
  out.voxel_of.resize(n);
  if (voxel_size <= 0) {
    out.points.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
      out.points.push_back(point(i));
      out.counts.push_back(1);
      out.voxel_of[i] = static_cast<int>(i);
    }
    return out;
  }
  const float inv = static_cast<float>(1.0 / voxel_size);
  std::unordered_map<std::uint64_t, int> index;
  index.reserve(n / 2 + 16);
  std::vector<Eigen::Vector3d> sums;
  for (std::size_t i = 0; i < n; ++i) {
    const auto [it, inserted] =
        index.emplace(voxel_key(point(i), inv), static_cast<int>(sums.size()));
    if (inserted) {
      sums.emplace_back(Eigen::Vector3d::Zero());
      out.counts.push_back(0);
    }
    sums[static_cast<std::size_t>(it->second)] += point(i).cast<double>();
    ++out.counts[static_cast<std::size_t>(it->second)];
    out.voxel_of[i] = it->second;
  }
  out.points.resize(sums.size());
  for (std::size_t v = 0; v < sums.size(); ++v)
    out.points[v] = (sums[v] / out.counts[v]).cast<float>();
  return out;
}

}  // namespace pagor
