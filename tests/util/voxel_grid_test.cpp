// Voxel downsampling far from the origin: the grid follows the cloud, so a cloud moved by 300 km
// gives the same voxels (moved), and a cloud too wide for its voxel size is an error.

#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <set>

#include "pagor/errors.hpp"
#include "util/random_draw.hpp"
#include "util/voxel_grid.hpp"

using namespace pagor;

namespace {

// n points drawn from u on each axis, then scaled per axis (a flat cloud, as a scan is).
template <class Rng>
std::vector<Eigen::Vector3f> random_points(Rng& rng, std::uniform_real_distribution<float>& u,
                                           int n, const Eigen::Vector3f& scale) {
  std::vector<Eigen::Vector3f> out;
  for (int i = 0; i < n; ++i)
    out.push_back(draw3(u, rng).template cast<float>().cwiseProduct(scale));
  return out;
}

}  // namespace

TEST_CASE("voxel downsampling is the same 300 km from the origin") {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(0.0f, 80.0f);
  // Points on a 1/32 m lattice, exactly representable both near the origin and 300 km out.
  std::vector<Eigen::Vector3f> near, far;
  const Eigen::Vector3f offset(300000.0f, -250000.0f, 1000.0f);
  for (int i = 0; i < 5000; ++i) {
    const Eigen::Vector3f p =
        (draw3(u, rng).cast<float>().cwiseQuotient(Eigen::Vector3f(1, 1, 8)) * 32).array().round() /
        32;
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

TEST_CASE("a non-finite coordinate anywhere is an error for the voxels and the grid") {
  // The bounding box's min and max pass a NaN over: every point is checked.
  std::vector<Eigen::Vector3f> pts(10, Eigen::Vector3f(1, 2, 3));
  pts[5].y() = std::numeric_limits<float>::quiet_NaN();
  CHECK_THROWS_AS(voxel_downsample(pts, 0.5), InputError);
  CHECK_THROWS_AS(RadiusGrid(pts, 0.5), InputError);
  pts[5].y() = HUGE_VALF;
  CHECK_THROWS_AS(voxel_downsample(pts, 0.5), InputError);
  CHECK_THROWS_AS(RadiusGrid(pts, 0.5), InputError);
}

TEST_CASE("a grid of more than 2^52 voxels per axis is an error, not undefined behaviour") {
  const std::vector<Eigen::Vector3f> huge = {{-1e29f, 0, 0}, {1e29f, 0, 0}};
  CHECK_THROWS_AS(voxel_downsample(huge, 0.5), InputError);
  const std::vector<Eigen::Vector3f> small = {{0, 0, 0}, {100, 0, 0}};
  CHECK_THROWS_WITH(voxel_downsample(small, 1e-300), Catch::Contains("beyond 2^52"));
}

TEST_CASE("voxel downsampling equals a straightforward map-based reference") {
  // The reference: voxels keyed by their integer indices in a std::map, numbered in order of
  // first appearance, centroids as double sums.
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-40.0f, 40.0f);
  std::vector<Eigen::Vector3f> pts;
  for (int i = 0; i < 20000; ++i)
    pts.push_back(draw3(u, rng).cast<float>().cwiseQuotient(Eigen::Vector3f(1, 1, 10)));
  for (int i = 0; i < 500; ++i) pts.push_back(pts[static_cast<std::size_t>(i) * 7]);  // repeats
  // On voxel edges, below zero too (a voxel index is a floor: -1.0 / 0.5 is -2, not -1).
  for (float x : {-1.0f, -0.5f, -0.2f, 0.0f, -0.0f, 0.5f, -3.0f}) pts.emplace_back(x, x, -x);
  for (double voxel : {0.2, 0.5, 3.0}) {
    std::map<std::array<long long, 3>, int> id;
    std::vector<Eigen::Vector3d> sums;
    std::vector<int> counts, voxel_of;
    for (const auto& p : pts) {
      const auto idx = [&](int a) {
        return static_cast<long long>(std::floor(p[a] * static_cast<float>(1.0 / voxel)));
      };
      const auto [it, inserted] =
          id.insert({{idx(0), idx(1), idx(2)}, static_cast<int>(sums.size())});
      if (inserted) sums.emplace_back(Eigen::Vector3d::Zero()), counts.push_back(0);
      sums[static_cast<std::size_t>(it->second)] += p.cast<double>();
      ++counts[static_cast<std::size_t>(it->second)];
      voxel_of.push_back(it->second);
    }
    const VoxelDownsample d = voxel_downsample(pts, voxel);
    INFO("voxel " << voxel << " m");
    const VoxelDownsample lean = voxel_downsample(pts, voxel, nullptr, false);
    CHECK(lean.voxel_of.empty());
    CHECK(lean.points == d.points);
    CHECK(lean.counts == d.counts);
    CHECK(d.counts == counts);
    CHECK(d.voxel_of == voxel_of);
    REQUIRE(d.points.size() == sums.size());
    for (std::size_t v = 0; v < sums.size(); ++v)
      CHECK(d.points[v] == (sums[v] / counts[v]).cast<float>());
  }
}

TEST_CASE("the grid's nearest neighbour, and whether there is one, agree with a linear scan") {
  // The search skips cells whose box is farther than the best so far: it must still find the
  // nearest point strictly within the radius, for queries inside, beside and far off the grid.
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<float> u(-20.f, 20.f);
  std::vector<Eigen::Vector3f> pts = random_points(rng, u, 4000, Eigen::Vector3f(1, 1, 0.1f));
  // Points on cell boundaries of a 1 m grid anchored at the lowest point.
  for (int i = 0; i < 200; ++i) pts.emplace_back(std::round(u(rng)), std::round(u(rng)), 0.0f);
  pts.push_back(pts.front());  // a duplicate
  // The same points and one far away: a box too large for a bit per cell (the hash table).
  std::vector<Eigen::Vector3f> sparse = pts;
  sparse.emplace_back(5000.0f, 5000.0f, 500.0f);
  for (float cell : {0.3f, 1.0f, 2.5f})
    for (const auto* cloud : {&pts, &sparse}) {
      const RadiusGrid grid(*cloud, cell);
      CHECK(grid.dense() == (cloud == &pts));
      for (int k = 0; k < 2000; ++k) {
        Eigen::Vector3f q(u(rng) * 1.3f, u(rng) * 1.3f, u(rng) * 0.3f);
        if (k % 10 == 0) q = pts[static_cast<std::size_t>(k)] + Eigen::Vector3f(0.0f, 0.0f, 1e-3f);
        if (k % 97 == 0) q *= 1e4f;  // clamped into the border cells
        for (float radius : {cell, cell * 0.5f, cell * 0.01f}) {
          int ref = -1;
          float ref_d2 = radius * radius;
          for (std::size_t i = 0; i < cloud->size(); ++i) {
            const float d2 = ((*cloud)[i] - q).squaredNorm();
            if (d2 < ref_d2) ref_d2 = d2, ref = static_cast<int>(i);
          }
          const auto [got, d2] = grid.nearest(q, radius);
          INFO("cell " << cell << " radius " << radius << " query " << q.transpose()
                       << (grid.dense() ? " (dense)" : " (hashed)"));
          REQUIRE(grid.any_within(q, radius) == (ref >= 0));
          REQUIRE(d2 == ref_d2);
          REQUIRE((got >= 0) == (ref >= 0));
          if (ref >= 0)
            CHECK(((*cloud)[static_cast<std::size_t>(got)] - q).squaredNorm() == ref_d2);
        }
      }
    }
}

TEST_CASE("the grid's dense box and its hash table give the same neighbours in the same order") {
  // Cells are found through a bit per cell when the box is small enough, else through the hash
  // table; either way a search sees the same cells in the same order and a cell's points in
  // input order, so that sums over neighbours (normals, FPFH) do not depend on the choice.
  std::mt19937_64 rng(29);
  std::uniform_real_distribution<float> u(-15.f, 15.f);
  std::vector<Eigen::Vector3f> pts = random_points(rng, u, 3000, Eigen::Vector3f(1, 1, 0.2f));
  std::vector<Eigen::Vector3f> sparse = pts;
  sparse.emplace_back(4000.0f, 6000.0f, 300.0f);  // above every point: the same cells
  for (float cell : {0.5f, 1.0f, 3.0f}) {
    const RadiusGrid dense(pts, cell), hashed(sparse, cell);
    REQUIRE(dense.dense());
    REQUIRE_FALSE(hashed.dense());
    for (int k = 0; k < 1000; ++k) {
      Eigen::Vector3f q(u(rng) * 1.2f, u(rng) * 1.2f, u(rng) * 0.3f);
      if (k % 50 == 0) q *= 100.0f;  // off the box
      std::vector<int> a, b;
      std::vector<float> da, db;
      dense.within(q, cell, a, da);
      hashed.within(q, cell, b, db);
      INFO("cell " << cell << " query " << q.transpose());
      REQUIRE(a == b);
      REQUIRE(da == db);
      CHECK(dense.nearest(q, cell) == hashed.nearest(q, cell));
    }
  }
}

TEST_CASE("the grid's pairs within a radius are a brute-force search's, each once") {
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<float> u(-6.f, 6.f);
  std::vector<Eigen::Vector3f> pts = random_points(rng, u, 1500, Eigen::Vector3f(1, 1, 0.3f));
  pts.push_back(pts[3]);  // a duplicate: a pair at distance 0
  std::vector<Eigen::Vector3f> sparse = pts;
  sparse.emplace_back(3000.0f, 3000.0f, 3000.0f);  // far from all: the hash table
  for (float cell : {0.4f, 1.0f})
    for (const auto* cloud : {&pts, &sparse}) {
      const RadiusGrid grid(*cloud, cell);
      CHECK(grid.dense() == (cloud == &pts));
      for (float radius : {cell, 0.5f * cell}) {
        std::set<std::pair<int, int>> expected, got;
        for (std::size_t i = 0; i < cloud->size(); ++i)
          for (std::size_t j = i + 1; j < cloud->size(); ++j)
            if (((*cloud)[i] - (*cloud)[j]).squaredNorm() < radius * radius)
              expected.insert({static_cast<int>(i), static_cast<int>(j)});
        std::size_t calls = 0;
        bool distances_right = true;
        grid.for_each_pair_within(radius, [&](int i, int j, float d2) {
          ++calls;
          got.insert({std::min(i, j), std::max(i, j)});
          distances_right = distances_right && d2 == ((*cloud)[static_cast<std::size_t>(i)] -
                                                      (*cloud)[static_cast<std::size_t>(j)])
                                                         .squaredNorm();
        });
        INFO("cell " << cell << " radius " << radius << (grid.dense() ? " dense" : " hashed"));
        CHECK(got == expected);
        CHECK(calls == expected.size());  // no pair twice
        CHECK(distances_right);
      }
    }
}
