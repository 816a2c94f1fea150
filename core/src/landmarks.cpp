#include "pagor/landmarks.hpp"

#include <pcl/features/fpfh.h>
#include <pcl/features/normal_3d.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/search/kdtree.h>
#include <pcl/segmentation/extract_clusters.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <unordered_set>

#include "pagor/errors.hpp"
#include "pagor/voxel_grid.hpp"
#include "pagor/work_budget.hpp"

namespace pagor {
namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// The points relative to a local origin: PCL's normals and FPFH accumulate in float, which loses
// a georeferenced cloud (300 km from the origin) to cancellation. The origin is the first point
// rounded to a multiple of 1024 m, so the subtraction is exact in float and clouds within 512 m
// of the origin are passed as they are. Only relative positions are used from the PCL cloud; the
// landmarks' centroids come from `points` themselves.
pcl::PointCloud<pcl::PointXYZ>::Ptr to_pcl(const std::vector<Eigen::Vector3f>& points) {
  pcl::PointCloud<pcl::PointXYZ>::Ptr out(new pcl::PointCloud<pcl::PointXYZ>);
  out->resize(points.size());
  Eigen::Vector3f origin = Eigen::Vector3f::Zero();
  if (!points.empty()) origin = (points.front() / 1024.0f).array().round().matrix() * 1024.0f;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3f p = points[i] - origin;
    (*out)[i] = pcl::PointXYZ(p.x(), p.y(), p.z());
  }
  return out;
}

// Indices of the points whose semantic id is one of `ids`.
std::vector<int> points_of_class(const PointCloud& cloud, const std::vector<std::uint32_t>& ids) {
  std::unordered_set<std::uint32_t> wanted(ids.begin(), ids.end());
  std::vector<int> out;
  for (std::size_t i = 0; i < cloud.size(); ++i)
    if (wanted.count(semantic_id(cloud.labels[i]))) out.push_back(static_cast<int>(i));
  return out;
}

// For each voxel, the input points (indices into the cloud) that fell into it.
std::vector<std::vector<int>> members_of_voxels(const VoxelDownsample& ds,
                                                const std::vector<int>& subset) {
  std::vector<std::vector<int>> members(ds.points.size());
  for (std::size_t i = 0; i < subset.size(); ++i)
    members[static_cast<std::size_t>(ds.voxel_of[i])].push_back(subset[i]);
  return members;
}

void add_clusters(int class_index, const ClassParams& p, const VoxelDownsample& ds,
                  const std::vector<std::vector<int>>& members, LandmarkSet& out) {
  check_radius_work(ds.points, p.cluster_tolerance,
                    "landmarks.classes[" + std::to_string(class_index) + "].cluster_tolerance",
                    "class '" + p.name + "'");
  auto cloud = to_pcl(ds.points);
  pcl::search::KdTree<pcl::PointXYZ>::Ptr tree(new pcl::search::KdTree<pcl::PointXYZ>);
  tree->setInputCloud(cloud);
  pcl::EuclideanClusterExtraction<pcl::PointXYZ> ec;
  ec.setClusterTolerance(p.cluster_tolerance);
  ec.setMinClusterSize(p.min_points);
  ec.setMaxClusterSize(p.max_points);
  ec.setSearchMethod(tree);
  ec.setInputCloud(cloud);
  std::vector<pcl::PointIndices> clusters;
  ec.extract(clusters);

  for (const auto& c : clusters) {
    Landmark lm;
    lm.class_index = class_index;
    lm.kind = LandmarkKind::cluster;
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (int v : c.indices) mean += ds.points[static_cast<std::size_t>(v)].cast<double>();
    mean /= static_cast<double>(c.indices.size());
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (int v : c.indices) {
      const Eigen::Vector3d d = ds.points[static_cast<std::size_t>(v)].cast<double>() - mean;
      cov += d * d.transpose();
    }
    lm.centroid = mean;
    lm.covariance = cov / static_cast<double>(c.indices.size());
    for (int v : c.indices) {
      const auto& m = members[static_cast<std::size_t>(v)];
      lm.point_indices.insert(lm.point_indices.end(), m.begin(), m.end());
    }
    std::sort(lm.point_indices.begin(), lm.point_indices.end());
    lm.point_count = lm.point_indices.size();
    out.landmarks.push_back(std::move(lm));
    out.descriptors.emplace_back();
  }
}

void add_keypoints(int class_index, const ClassParams& p, const VoxelDownsample& ds,
                   const std::vector<std::vector<int>>& members, LandmarkSet& out) {
  check_radius_work(ds.points, p.feature_radius,
                    "landmarks.classes[" + std::to_string(class_index) + "].feature_radius",
                    "class '" + p.name + "'");
  auto cloud = to_pcl(ds.points);
  pcl::search::KdTree<pcl::PointXYZ>::Ptr tree(new pcl::search::KdTree<pcl::PointXYZ>);
  tree->setInputCloud(cloud);
  pcl::PointCloud<pcl::Normal>::Ptr normals(new pcl::PointCloud<pcl::Normal>);
  pcl::NormalEstimation<pcl::PointXYZ, pcl::Normal> ne;
  ne.setInputCloud(cloud);
  ne.setSearchMethod(tree);
  ne.setRadiusSearch(p.normal_radius);
  ne.compute(*normals);

  pcl::PointCloud<pcl::FPFHSignature33> features;
  pcl::FPFHEstimation<pcl::PointXYZ, pcl::Normal, pcl::FPFHSignature33> fe;
  fe.setInputCloud(cloud);
  fe.setInputNormals(normals);
  fe.setSearchMethod(tree);
  fe.setRadiusSearch(p.feature_radius);
  fe.compute(features);

  for (std::size_t v = 0; v < ds.points.size(); ++v) {
    const auto& n = (*normals)[v];
    const float* h = features[v].histogram;
    if (!std::isfinite(n.normal_x) ||
        !std::all_of(h, h + 33, [](float x) { return std::isfinite(x); }))
      continue;  // too few neighbours for a normal or a descriptor
    if (std::all_of(h, h + 33, [](float x) { return x == 0.0f; })) continue;
    Landmark lm;
    lm.class_index = class_index;
    lm.kind = LandmarkKind::keypoint;
    lm.centroid = ds.points[v].cast<double>();
    lm.point_indices = members[v];
    lm.point_count = lm.point_indices.size();
    out.landmarks.push_back(std::move(lm));
    out.descriptors.emplace_back(h, h + 33);
  }
}

}  // namespace

LandmarkSet extract_landmarks(const PointCloud& cloud, const LabelScheme& scheme,
                              const LandmarkParams& params) {
  const auto t_all = Clock::now();
  if (!cloud.has_labels())
    throw InputError("the cloud has no semantic labels; landmarks need a label per point");
  LandmarkSet out;
  for (std::size_t ci = 0; ci < params.classes.size(); ++ci) {
    const auto t0 = Clock::now();
    const ClassParams& p = params.classes[ci];
    ClassSummary summary;
    summary.name = p.name;
    summary.method = p.method;
    const std::vector<int> subset = points_of_class(cloud, scheme.ids_of(p.name));
    summary.points = subset.size();
    const std::size_t before = out.landmarks.size();
    if (subset.empty()) {
      out.warnings.push_back("class '" + p.name + "': no points with this label");
    } else {
      const VoxelDownsample ds = voxel_downsample(cloud.points, p.voxel_size, &subset);
      summary.voxels = ds.points.size();
      const auto members = members_of_voxels(ds, subset);
      if (p.method == LandmarkMethod::cluster)
        add_clusters(static_cast<int>(ci), p, ds, members, out);
      else
        add_keypoints(static_cast<int>(ci), p, ds, members, out);
      if (out.landmarks.size() == before)
        out.warnings.push_back("class '" + p.name + "': " + std::to_string(subset.size()) +
                               " points but no landmark (check its clustering parameters)");
    }
    summary.landmarks = out.landmarks.size() - before;
    summary.time_ms = ms_since(t0);
    out.classes.push_back(summary);
  }
  out.time_ms = ms_since(t_all);
  return out;
}

}  // namespace pagor
