// The landmark stage's neighbour search, clusters, normals and FPFH (core/src/point_features.hpp)
// against what they replace: a linear scan, and PCL's EuclideanClusterExtraction,
// NormalEstimation and FPFHEstimation over FLANN, on random points and on a real KITTI scan.

#include <pcl/features/fpfh.h>
#include <pcl/features/normal_3d.h>
#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/search/kdtree.h>
#include <pcl/segmentation/extract_clusters.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <limits>
#include <random>
#include <set>

#include "front/point_features.hpp"
#include "pagor/config.hpp"
#include "pagor/front/correspondences.hpp"
#include "pagor/front/landmarks.hpp"
#include "pagor/io/kitti.hpp"
#include "pagor/util/kdtree.hpp"
#include "support/test_util.hpp"
#include "util/voxel_grid.hpp"

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

TEST_CASE("the FPFH angle falls in atan2's bin, also beside every bin edge") {
  // PCL's binning of the first pair feature, atan2(y, x) in [-pi, pi] into 11 bins.
  const auto bin = [](float angle) {
    const float d_pi = 1.0f / (2.0f * static_cast<float>(M_PI));
    const double x = 11 * ((angle + M_PI) * d_pi);
    return x >= 0.0 ? std::min(10, static_cast<int>(std::floor(x))) : 0;
  };
  const auto same = [&](float y, float x) {
    const float fast = detail::binnable_atan2(y, x), exact = std::atan2(y, x);
    return bin(fast) == bin(exact) && std::isnan(fast) == std::isnan(exact);
  };
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> coordinate(-1.0f, 1.0f);
  int mismatches = 0;
  for (int i = 0; i < 1000000; ++i) {
    const float y = coordinate(rng), x = coordinate(rng);
    mismatches += !same(y, x);
  }
  // Directions within a few ulps to 1e-3 rad of each of the 12 bin edges, at several lengths.
  for (int edge = 0; edge <= 11; ++edge) {
    const double theta = -M_PI + edge * 2 * M_PI / 11;
    for (double offset : {-1e-3, -1e-4, -1e-6, -1e-7, 0.0, 1e-7, 1e-6, 1e-4, 1e-3})
      for (float length : {1e-3f, 0.5f, 1.0f, 7.0f}) {
        const float y = static_cast<float>(length * std::sin(theta + offset));
        const float x = static_cast<float>(length * std::cos(theta + offset));
        for (float dy : {-1, 0, 1})
          for (float dx : {-1, 0, 1}) {
            const float yy = dy == 0 ? y : std::nextafter(y, dy * HUGE_VALF);
            const float xx = dx == 0 ? x : std::nextafter(x, dx * HUGE_VALF);
            mismatches += !same(yy, xx);
          }
      }
  }
  CHECK(mismatches == 0);
  // Axes, signed zeros, infinities and NaN.
  const float inf = HUGE_VALF, nan = std::numeric_limits<float>::quiet_NaN();
  for (float y : {0.0f, -0.0f, 1.0f, -1.0f, inf, -inf, nan})
    for (float x : {0.0f, -0.0f, 1.0f, -1.0f, inf, -inf, nan}) {
      INFO("y " << y << " x " << x);
      CHECK(same(y, x));
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

TEST_CASE("the spacing estimate is the median nearest-neighbour distance of its queries") {
  // The definition, with a kd-tree: an even sample of at most 16384 points, 1000 evenly spaced
  // queries, the median distance scaled back by the square root of the thinning.
  const auto reference = [](const Points& pts) {
    const std::size_t thin = std::max<std::size_t>(1, pts.size() / 16384);
    Points sample;
    for (std::size_t i = 0; i < pts.size(); i += thin) sample.push_back(pts[i]);
    const KdTree3f tree(sample);
    std::vector<float> d;
    for (std::size_t i = 0; i < sample.size(); i += std::max<std::size_t>(1, sample.size() / 1000))
      d.push_back(std::sqrt(tree.nearest(sample[i], HUGE_VALF, static_cast<int>(i)).second));
    std::nth_element(d.begin(), d.begin() + static_cast<long>(d.size() / 2), d.end());
    return d[d.size() / 2] / std::sqrt(static_cast<double>(thin));
  };
  std::vector<Points> clouds = {random_scene(3, 500), random_scene(4, 40000)};
  Points line;  // a degenerate extent: points on a line
  for (int i = 0; i < 300; ++i) line.emplace_back(0.1f * static_cast<float>(i * i % 97), 0, 0);
  clouds.push_back(line);
  if (std::filesystem::exists(test::kitti_root() + "/sequences/00/velodyne/000000.bin"))
    clouds.push_back(KittiSequence(test::kitti_root(), "00").load_frame(0).cloud.points);
  for (const Points& pts : clouds) {
    INFO(pts.size() << " points");
    CHECK(estimate_spacing(pts) == Approx(reference(pts)).epsilon(1e-6));
  }
}

TEST_CASE("descriptor matching gives FLANN's mutual nearest neighbours, on one thread or more") {
  if (!std::filesystem::exists(test::kitti_root() + "/sequences/00/velodyne/000000.bin")) return;
  const KittiSequence seq(test::kitti_root(), "00");
  const Config config = default_config();
  const LandmarkSet s =
      extract_landmarks(seq.load_frame(0).cloud, config.label_scheme, config.landmarks);
  const LandmarkSet t =
      extract_landmarks(seq.load_frame(20).cloud, config.label_scheme, config.landmarks);
  const int building = static_cast<int>(config.landmarks.classes.size()) - 1;
  REQUIRE(config.landmarks.classes.back().method == LandmarkMethod::fpfh);
  // The reference: FLANN's exact kd-tree both ways, mutual matches, best 300 by distance.
  const auto cloud_of = [&](const LandmarkSet& set, std::vector<int>& idx) {
    pcl::PointCloud<pcl::FPFHSignature33>::Ptr c(new pcl::PointCloud<pcl::FPFHSignature33>);
    for (std::size_t i = 0; i < set.landmarks.size(); ++i)
      if (set.landmarks[i].class_index == building) {
        idx.push_back(static_cast<int>(i));
        pcl::FPFHSignature33 d;
        std::copy(set.descriptors[i].begin(), set.descriptors[i].end(), d.histogram);
        c->push_back(d);
      }
    return c;
  };
  std::vector<int> si, ti;
  const auto sc = cloud_of(s, si), tc = cloud_of(t, ti);
  pcl::KdTreeFLANN<pcl::FPFHSignature33> s_tree, t_tree;
  s_tree.setInputCloud(sc);
  t_tree.setInputCloud(tc);
  std::vector<int> k(1);
  std::vector<float> d(1);
  std::vector<std::pair<float, std::pair<int, int>>> expected;
  for (std::size_t a = 0; a < sc->size(); ++a) {
    t_tree.nearestKSearch((*sc)[a], 1, k, d);
    const int b = k[0];
    const float dist = d[0];
    s_tree.nearestKSearch((*tc)[static_cast<std::size_t>(b)], 1, k, d);
    if (k[0] == static_cast<int>(a))
      expected.push_back({dist, {si[a], ti[static_cast<std::size_t>(b)]}});
  }
  std::sort(expected.begin(), expected.end());
  expected.resize(
      std::min<std::size_t>(expected.size(), config.correspondences.fpfh_max_per_class));
  std::set<std::pair<int, int>> want, got;
  for (const auto& e : expected) want.insert(e.second);
  const CorrespondenceSet ours = match_landmarks(s, t, config.correspondences);
  for (const Correspondence& c : ours.items)
    if (c.class_index == building) got.insert({c.source, c.target});
  // The search split over threads (runs merged in order, the first of equal distances winning as
  // in one run) finds the same correspondences, in the same order.
  for (int threads : {2, 3}) {
    const CorrespondenceSet split = match_landmarks(s, t, config.correspondences, threads);
    INFO(threads << " threads");
    REQUIRE(split.items.size() == ours.items.size());
    for (std::size_t i = 0; i < ours.items.size(); ++i) {
      CHECK(split.items[i].source == ours.items[i].source);
      CHECK(split.items[i].target == ours.items[i].target);
      CHECK(split.items[i].score == ours.items[i].score);
    }
  }
  // Where two descriptors are identical (isolated points give the same degenerate histogram)
  // either match is exact; FLANN takes the one its tree visits first, we the lowest index.
  const auto same_descriptors = [](const LandmarkSet& set, int a, int b) {
    return set.descriptors[static_cast<std::size_t>(a)] ==
           set.descriptors[static_cast<std::size_t>(b)];
  };
  std::size_t ties = 0;
  for (const auto& [a, b] : want)
    if (!got.count({a, b}))
      for (const auto& [c, e] : got)
        if (!want.count({c, e}) &&
            ((a == c && same_descriptors(t, b, e)) || (b == e && same_descriptors(s, a, c)))) {
          got.erase({c, e});  // and leave the loop: the iterator is gone
          got.insert({a, b});
          ++ties;
          break;
        }
  INFO("FLANN " << want.size() << " matches, " << ties << " exact ties taken the other way");
  CHECK(want.size() > 100);
  CHECK(got == want);
}
