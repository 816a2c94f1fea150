// Voxel downsampling far from the origin: the grid follows the cloud, so a cloud moved by 300 km
// gives the same voxels (moved), and a cloud too wide for its voxel size is an error.

#include <catch2/catch.hpp>
#include <random>

#include "pagor/errors.hpp"
#include "pagor/voxel_grid.hpp"

using namespace pagor;

TEST_CASE("voxel downsampling is the same 300 km from the origin") {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(0.0f, 80.0f);
  // Points on a 1/32 m lattice, exactly representable both near the origin and 300 km out.
  std::vector<Eigen::Vector3f> near, far;
  const Eigen::Vector3f offset(300000.0f, -250000.0f, 1000.0f);
  for (int i = 0; i < 5000; ++i) {
    const Eigen::Vector3f p =
        (Eigen::Vector3f(u(rng), u(rng), u(rng) / 8) * 32).array().round() / 32;
    near.push_back(p);
    far.push_back(p + offset);
  }
  const VoxelDownsample a = voxel_downsample(near, 0.5);
  const VoxelDownsample b = voxel_downsample(far, 0.5);
  REQUIRE(a.points.size() == b.points.size());
  CHECK(a.voxel_of == b.voxel_of);
  CHECK(a.counts == b.counts);
  for (std::size_t v = 0; v < a.points.size(); ++v)
    CHECK((b.points[v] - offset - a.points[v]).norm() < 0.05f);
}

TEST_CASE("points hundreds of kilometres apart never share a voxel") {
  // With 21-bit keys relative to the origin these two points used to collide.
  const std::vector<Eigen::Vector3f> pts = {{0.0f, 0.0f, 0.0f}, {1048576.0f * 0.2f, 0.0f, 0.0f}};
  CHECK(voxel_downsample(pts, 0.1).points.size() == 2);
  const std::vector<Eigen::Vector3f> wide = {{-3e5f, 0, 0}, {3e5f, 0, 0}, {3e5f, 0.01f, 0}};
  const VoxelDownsample d = voxel_downsample(wide, 0.1);  // 6e6 voxels across: the wide key
  CHECK(d.points.size() == 2);
  CHECK(d.counts == std::vector<int>{1, 2});
}

TEST_CASE("a grid of more than 2^52 voxels per axis is an error, not undefined behaviour") {
  const std::vector<Eigen::Vector3f> huge = {{-1e29f, 0, 0}, {1e29f, 0, 0}};
  CHECK_THROWS_AS(voxel_downsample(huge, 0.5), InputError);
  const std::vector<Eigen::Vector3f> small = {{0, 0, 0}, {100, 0, 0}};
  CHECK_THROWS_WITH(voxel_downsample(small, 1e-300), Catch::Contains("beyond 2^52"));
}
