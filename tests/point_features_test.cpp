// The landmark stage's neighbour search, clusters, normals and FPFH (core/src/point_features.hpp)
// against what they replace: a linear scan, and PCL's EuclideanClusterExtraction,
// NormalEstimation and FPFHEstimation over FLANN, on random points and on a real KITTI scan.

#include <pcl/features/fpfh.h>
#include <pcl/features/normal_3d.h>
#include <pcl/search/kdtree.h>
#include <pcl/segmentation/extract_clusters.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <random>

#include "pagor/config.hpp"
#include "pagor/kitti.hpp"
#include "pagor/voxel_grid.hpp"
#include "point_features.hpp"
#include "test_util.hpp"

using namespace pagor;

namespace {

using Points = std::vector<Eigen::Vector3f>;

pcl::PointCloud<pcl::PointXYZ>::Ptr to_pcl(const Points& points) {
  pcl::PointCloud<pcl::PointXYZ>::Ptr out(new pcl::PointCloud<pcl::PointXYZ>);
  for (const auto& p : points) out->push_back(pcl::PointXYZ(p.x(), p.y(), p.z()));
  return out;
}

// Random planes and blobs: surfaces as FPFH sees them, and separate groups for clustering.
Points random_scene(std::uint32_t seed, int n) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  Points out;
  for (int i = 0; i < n; ++i) {
    const int kind = i % 3;
    const float a = 20 * u(rng), b = 20 * u(rng), noise = 0.05f * (u(rng) - 0.5f);
    if (kind == 0) out.emplace_back(a, b, noise);                                      // ground
    if (kind == 1) out.emplace_back(a, 3.0f + noise, 4 * u(rng));                      // wall
    if (kind == 2) out.emplace_back(5 + 2 * u(rng), 12 + 2 * u(rng), 1 + 2 * u(rng));  // blob
  }
  return out;
}

// Voxelised points of one class of KITTI frame 0; empty without the data.
Points kitti_class(const std::string& name, double voxel) {
  if (!std::filesystem::exists(test::kitti_root() + "/sequences/00/velodyne/000000.bin")) return {};
  const KittiSequence seq(test::kitti_root(), "00");
  const LoadedCloud c = seq.load_frame(0);
  const Config config = default_config();
  const auto& ids = config.label_scheme.ids_of(name);
  std::vector<int> subset;
  for (std::size_t i = 0; i < c.cloud.size(); ++i)
    if (std::find(ids.begin(), ids.end(), semantic_id(c.cloud.labels[i])) != ids.end())
      subset.push_back(static_cast<int>(i));
  return voxel_downsample(c.cloud.points, voxel, &subset).points;
}

std::vector<Points> inputs(const std::string& kitti_name, double voxel) {
  std::vector<Points> out = {random_scene(1, 3000), random_scene(2, 6000)};
  Points k = kitti_class(kitti_name, voxel);
  if (!k.empty()) out.push_back(std::move(k));
  return out;
}

std::vector<pcl::Normal> pcl_normals(const Points& points, double radius) {
  auto cloud = to_pcl(points);
  pcl::search::KdTree<pcl::PointXYZ>::Ptr tree(new pcl::search::KdTree<pcl::PointXYZ>);
  pcl::NormalEstimation<pcl::PointXYZ, pcl::Normal> ne;
  ne.setInputCloud(cloud);
  ne.setSearchMethod(tree);
  ne.setRadiusSearch(radius);
  pcl::PointCloud<pcl::Normal> normals;
  ne.compute(normals);
  return {normals.begin(), normals.end()};
}

}  // namespace

TEST_CASE("the radius grid finds what a linear scan finds") {
  for (const float offset : {0.0f, 250000.0f}) {
    Points pts = random_scene(7, 4000);
    for (auto& p : pts) p.x() += offset;
    for (const double radius : {0.3, 1.0, 2.5}) {
      const RadiusGrid grid(pts, radius);
      std::vector<int> found;
      std::vector<float> d2;
      for (std::size_t q = 0; q < pts.size(); q += 37) {
        found.clear();
        d2.clear();
        grid.within(pts[q], static_cast<float>(radius), found, d2);
        std::vector<int> expected;
        for (std::size_t i = 0; i < pts.size(); ++i)
          if ((pts[i] - pts[q]).squaredNorm() < static_cast<float>(radius * radius))
            expected.push_back(static_cast<int>(i));
        std::sort(found.begin(), found.end());
        REQUIRE(found == expected);
      }
    }
  }
}

TEST_CASE("Euclidean clusters are PCL's") {
  for (const Points& pts : inputs("car", 0.2)) {
    for (const double tol : {0.3, 0.5}) {
      auto cloud = to_pcl(pts);
      pcl::search::KdTree<pcl::PointXYZ>::Ptr tree(new pcl::search::KdTree<pcl::PointXYZ>);
      pcl::EuclideanClusterExtraction<pcl::PointXYZ> ec;
      ec.setClusterTolerance(tol);
      ec.setMinClusterSize(5);
      ec.setMaxClusterSize(2000);
      ec.setSearchMethod(tree);
      ec.setInputCloud(cloud);
      std::vector<pcl::PointIndices> reference;
      ec.extract(reference);
      auto fast = detail::euclidean_clusters(pts, tol, 5, 2000);
      std::vector<std::vector<int>> expected;
      for (const auto& c : reference) expected.push_back(c.indices);
      std::sort(expected.begin(), expected.end());
      std::sort(fast.begin(), fast.end());
      INFO(pts.size() << " points, tolerance " << tol);
      CHECK(!fast.empty());
      CHECK(fast == expected);
    }
  }
}

TEST_CASE("normals are PCL's") {
  for (const Points& pts : inputs("building", 0.6)) {
    const double radius = 1.2;
    const auto reference = pcl_normals(pts, radius);
    const auto fast = detail::estimate_normals(pts, radius);
    REQUIRE(fast.size() == reference.size());
    int finite = 0;
    for (std::size_t i = 0; i < fast.size(); ++i) {
      const Eigen::Vector3f r(reference[i].normal_x, reference[i].normal_y, reference[i].normal_z);
      REQUIRE(r.allFinite() == fast[i].allFinite());
      if (!r.allFinite()) continue;
      ++finite;
      CHECK(r.dot(fast[i]) > 0.9999f);
    }
    CHECK(finite > static_cast<int>(pts.size()) / 2);
  }
}

TEST_CASE("FPFH descriptors are PCL's") {
  for (const Points& pts : inputs("building", 0.6)) {
    const double normal_radius = 1.2, radius = 3.0;
    const auto normals = detail::estimate_normals(pts, normal_radius);
    std::vector<int> keypoints;
    for (int i = 0; i < static_cast<int>(pts.size()); i += 3) keypoints.push_back(i);
    const auto fast = detail::compute_fpfh(pts, normals, keypoints, radius);

    // PCL with the same normals, so that only the descriptor is compared.
    auto cloud = to_pcl(pts);
    pcl::PointCloud<pcl::Normal>::Ptr pn(new pcl::PointCloud<pcl::Normal>);
    for (const auto& n : normals) pn->push_back(pcl::Normal(n.x(), n.y(), n.z()));
    pcl::search::KdTree<pcl::PointXYZ>::Ptr tree(new pcl::search::KdTree<pcl::PointXYZ>);
    pcl::FPFHEstimation<pcl::PointXYZ, pcl::Normal, pcl::FPFHSignature33> fe;
    fe.setInputCloud(cloud);
    fe.setIndices(pcl::IndicesPtr(new std::vector<int>(keypoints)));
    fe.setInputNormals(pn);
    fe.setSearchMethod(tree);
    fe.setRadiusSearch(radius);
    pcl::PointCloud<pcl::FPFHSignature33> reference;
    fe.compute(reference);

    REQUIRE(reference.size() == fast.size());
    float worst = 0;
    for (std::size_t k = 0; k < fast.size(); ++k)
      for (int b = 0; b < 33; ++b) {
        const float r = reference[k].histogram[b], f = fast[k][static_cast<std::size_t>(b)];
        REQUIRE(std::isfinite(r) == std::isfinite(f));
        if (std::isfinite(r)) worst = std::max(worst, std::fabs(r - f));
      }
    INFO(pts.size() << " points: largest difference " << worst << " (bins of a third sum to 100)");
    CHECK(worst < 1e-3f);
  }
}
