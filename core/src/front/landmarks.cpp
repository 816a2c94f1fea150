#include "pagor/front/landmarks.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <numeric>
#include <optional>

#include "front/point_features.hpp"
#include "pagor/errors.hpp"
#include "pagor/util/work_budget.hpp"
#include "util/voxel_grid.hpp"

namespace pagor {
namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// The points relative to a local origin: normals and FPFH accumulate in float, which loses a
// georeferenced cloud (300 km from the origin) to cancellation. The origin is the first point
// rounded to a multiple of 1024 m, so the subtraction is exact in float and clouds within 512 m
// of the origin are used as they are. Only relative positions are used from these points; the
// landmarks' centroids come from the input points themselves.
std::vector<Eigen::Vector3f> local_points(const std::vector<Eigen::Vector3f>& points) {
  std::vector<Eigen::Vector3f> out(points.size());
  Eigen::Vector3f origin = Eigen::Vector3f::Zero();
  if (!points.empty()) origin = (points.front() / 1024.0f).array().round().matrix() * 1024.0f;
  for (std::size_t i = 0; i < points.size(); ++i) out[i] = points[i] - origin;
  return out;
}

// For each class of `params`, the indices of the points whose semantic id is one of the class's
// ids. One pass over the labels with a table of the class of each id when every id is below
// kSmallIds and in one class at most (as in every built-in scheme); else a pass per class.
std::vector<std::vector<int>> points_of_classes(const PointCloud& cloud, const LabelScheme& scheme,
                                                const LandmarkParams& params) {
  constexpr std::uint32_t kSmallIds = 1024;
  const std::size_t classes = params.classes.size();
  std::vector<std::vector<int>> out(classes);
  std::vector<int> owner(kSmallIds, -1);
  bool one_pass = true;
  for (std::size_t c = 0; c < classes && one_pass; ++c)
    for (std::uint32_t id : scheme.ids_of(params.classes[c].name)) {
      if (id >= kSmallIds || (owner[id] >= 0 && owner[id] != static_cast<int>(c))) {
        one_pass = false;
        break;
      }
      owner[id] = static_cast<int>(c);
    }
  if (one_pass) {
    for (std::size_t i = 0; i < cloud.size(); ++i) {
      const std::uint32_t id = semantic_id(cloud.labels[i]);
      if (id < kSmallIds && owner[id] >= 0)
        out[static_cast<std::size_t>(owner[id])].push_back(static_cast<int>(i));
    }
    return out;
  }
  for (std::size_t c = 0; c < classes; ++c) {
    std::vector<std::uint32_t> ids = scheme.ids_of(params.classes[c].name);
    std::sort(ids.begin(), ids.end());
    for (std::size_t i = 0; i < cloud.size(); ++i)
      if (std::binary_search(ids.begin(), ids.end(), semantic_id(cloud.labels[i])))
        out[c].push_back(static_cast<int>(i));
  }
  return out;
}

// For each voxel, the input points (indices into the cloud) that fell into it, ascending: voxel
// v's are point[start[v], start[v + 1]) (one array, not a vector per voxel).
struct VoxelMembers {
  std::vector<int> start, point;
  const int* begin(std::size_t v) const { return point.data() + start[v]; }
  const int* end(std::size_t v) const { return point.data() + start[v + 1]; }
};
VoxelMembers members_of_voxels(const VoxelDownsample& ds, const std::vector<int>& subset) {
  VoxelMembers m;
  m.start.assign(ds.points.size() + 1, 0);
  for (std::size_t v = 0; v < ds.points.size(); ++v) m.start[v + 1] = m.start[v] + ds.counts[v];
  m.point.resize(subset.size());
  std::vector<int> fill(m.start.begin(), m.start.end() - 1);
  for (std::size_t i = 0; i < subset.size(); ++i)
    m.point[static_cast<std::size_t>(fill[static_cast<std::size_t>(ds.voxel_of[i])]++)] = subset[i];
  return m;
}

// Throws ConfigError naming landmarks.classes[class_index].`field` when searches of `radius` [m]
// over the class's voxels would pass the work budget (work_budget.hpp).
void check_class_radius(const VoxelDownsample& ds, int class_index, const ClassParams& p,
                        const char* field, double radius) {
  check_radius_work(ds.points, radius,
                    "landmarks.classes[" + std::to_string(class_index) + "]." + field,
                    "class '" + p.name + "'");
}

void add_clusters(int class_index, const ClassParams& p, const VoxelDownsample& ds,
                  const VoxelMembers& members, LandmarkSet& out) {
  check_class_radius(ds, class_index, p, "cluster_tolerance", p.cluster_tolerance);
  const auto clusters = detail::euclidean_clusters(local_points(ds.points), p.cluster_tolerance,
                                                   p.min_points, p.max_points);
  for (const std::vector<int>& c : clusters) {
    Landmark lm;
    lm.class_index = class_index;
    lm.kind = LandmarkKind::cluster;
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (int v : c) mean += ds.points[static_cast<std::size_t>(v)].cast<double>();
    mean /= static_cast<double>(c.size());
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (int v : c) {
      const Eigen::Vector3d d = ds.points[static_cast<std::size_t>(v)].cast<double>() - mean;
      cov += d * d.transpose();
    }
    lm.centroid = mean;
    lm.covariance = cov / static_cast<double>(c.size());
    for (int v : c)
      lm.point_indices.insert(lm.point_indices.end(), members.begin(static_cast<std::size_t>(v)),
                              members.end(static_cast<std::size_t>(v)));
    std::sort(lm.point_indices.begin(), lm.point_indices.end());
    lm.point_count = lm.point_indices.size();
    out.landmarks.push_back(std::move(lm));
    out.descriptors.emplace_back();
  }
}

// At most `budget` of the voxels, spread evenly: the voxel nearest the mean of each cell of a
// coarser grid, the grid growing until few enough cells remain. All voxels when they fit.
std::vector<int> spread_keypoints(const VoxelDownsample& ds, double voxel_size, int budget) {
  std::vector<int> keep;
  if (ds.points.size() <= static_cast<std::size_t>(budget)) {
    keep.resize(ds.points.size());
    std::iota(keep.begin(), keep.end(), 0);
    return keep;
  }
  constexpr double kGrowth = 1.25;
  double cell = std::max(voxel_size, 1e-3);
  VoxelDownsample coarse;
  do {
    cell *= kGrowth;
    coarse = voxel_downsample(ds.points, cell);
  } while (coarse.points.size() > static_cast<std::size_t>(budget));
  std::vector<int> best(coarse.points.size(), -1);
  std::vector<float> best_d2(coarse.points.size(), HUGE_VALF);
  for (std::size_t v = 0; v < ds.points.size(); ++v) {
    const auto c = static_cast<std::size_t>(coarse.voxel_of[v]);
    const float d2 = (ds.points[v] - coarse.points[c]).squaredNorm();
    if (d2 < best_d2[c]) best_d2[c] = d2, best[c] = static_cast<int>(v);
  }
  std::sort(best.begin(), best.end());
  return best;
}

// FPFH keypoints: normals and descriptors see every voxel of the class (the configured grid),
// descriptors are computed only at a budget of evenly spread keypoints.
void add_keypoints(int class_index, const ClassParams& p, const VoxelDownsample& ds,
                   const VoxelMembers& members, LandmarkSet& out) {
  check_class_radius(ds, class_index, p, "feature_radius", p.feature_radius);
  const std::vector<Eigen::Vector3f> local = local_points(ds.points);
  const std::vector<Eigen::Vector3f> normals = detail::estimate_normals(local, p.normal_radius);
  const std::vector<int> keypoints = spread_keypoints(ds, p.voxel_size, p.max_keypoints);
  const std::vector<detail::Fpfh> features =
      detail::compute_fpfh(local, normals, keypoints, p.feature_radius);
  for (std::size_t k = 0; k < keypoints.size(); ++k) {
    const auto v = static_cast<std::size_t>(keypoints[k]);
    const float* h = features[k].data();
    if (!normals[v].allFinite() ||
        !std::all_of(h, h + 33, [](float x) { return std::isfinite(x); }))
      continue;  // too few neighbours for a normal or a descriptor
    if (std::all_of(h, h + 33, [](float x) { return x == 0.0f; })) continue;
    Landmark lm;
    lm.class_index = class_index;
    lm.kind = LandmarkKind::keypoint;
    lm.centroid = ds.points[v].cast<double>();
    lm.point_indices.assign(members.begin(v), members.end(v));
    lm.point_count = lm.point_indices.size();
    out.landmarks.push_back(std::move(lm));
    out.descriptors.emplace_back(h, h + 33);
  }
}

// Landmarks of one class from the points `subset`, appended to `out` with a summary.
void extract_class(const PointCloud& cloud, const std::vector<int>& subset, int class_index,
                   const ClassParams& configured, const LandmarkParams& all, LandmarkSet& out) {
  const auto t0 = Clock::now();
  ClassSummary summary;
  summary.spacing = all.adapt_to_spacing ? estimate_spacing(cloud.points, &subset) : 0.0;
  const ClassParams p = params_for_spacing(configured, summary.spacing, all);
  summary.name = p.name;
  summary.method = p.method;
  summary.points = subset.size();
  const std::size_t before = out.landmarks.size();
  if (subset.empty()) {
    out.warnings.push_back("class '" + p.name + "': no points with this label");
  } else {
    const VoxelDownsample ds = voxel_downsample(cloud.points, p.voxel_size, &subset);
    summary.voxels = ds.points.size();
    const auto members = members_of_voxels(ds, subset);
    if (p.method == LandmarkMethod::cluster)
      add_clusters(class_index, p, ds, members, out);
    else
      add_keypoints(class_index, p, ds, members, out);
    if (out.landmarks.size() == before)
      out.warnings.push_back("class '" + p.name + "': " + std::to_string(subset.size()) +
                             " points but no landmark (check its clustering parameters)");
  }
  summary.landmarks = out.landmarks.size() - before;
  summary.voxel_size = p.voxel_size;
  summary.cluster_tolerance = p.cluster_tolerance;
  summary.min_points = p.min_points;
  summary.time_ms = ms_since(t0);
  out.classes.push_back(summary);
}

}  // namespace

double estimate_spacing(const std::vector<Eigen::Vector3f>& points,
                        const std::vector<int>* subset) {
  constexpr std::size_t kQueries = 1000, kTreePoints = 16384;
  const std::size_t n = subset ? subset->size() : points.size();
  if (n < 2) return 0.0;
  const std::size_t thin = std::max<std::size_t>(1, n / kTreePoints);
  std::vector<Eigen::Vector3f> sample;
  sample.reserve(n / thin + 1);
  for (std::size_t i = 0; i < n; i += thin)
    sample.push_back(points[subset ? static_cast<std::size_t>((*subset)[i]) : i]);
  if (sample.size() < 2) return 0.0;
  const std::size_t stride = std::max<std::size_t>(1, sample.size() / kQueries);
  // Each query's nearest neighbour within a radius that grows until more than half of the queries
  // have theirs within it: the others are farther, so the median is then exact. The first radius
  // is an eighth of the spacing of a square surface of the sample's extent. The grid's cells are
  // kRadii radii wide, so that the doublings rarely rebuild it: a nearest point within the radius
  // is the same at any cell at least as wide, and so is the median; cells of one radius cost
  // twice the time in building the grid's many small cells (KITTI's classes).
  constexpr double kRadii = 4;
  Eigen::Vector3f lo = sample[0], hi = lo;
  for (const auto& p : sample) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  double radius = std::max(1e-3, static_cast<double>((hi - lo).maxCoeff()) /
                                     std::sqrt(static_cast<double>(sample.size())) / 8);
  std::vector<float> d;
  std::optional<RadiusGrid> grid;
  for (;;) {
    if (!grid || static_cast<double>(grid->cell()) < radius) grid.emplace(sample, radius * kRadii);
    const auto r = static_cast<float>(radius);  // at most the cell, as nearest() asks
    d.clear();
    std::size_t found = 0;
    for (std::size_t i = 0; i < sample.size(); i += stride) {
      const auto [index, d2] = grid->nearest(sample[i], r, static_cast<int>(i));
      d.push_back(index >= 0 ? std::sqrt(d2) : HUGE_VALF);
      found += index >= 0;
    }
    if (found > d.size() / 2) break;
    radius *= 2;
  }
  std::nth_element(d.begin(), d.begin() + static_cast<long>(d.size() / 2), d.end());
  return d[d.size() / 2] / std::sqrt(static_cast<double>(thin));
}

float ground_layer_top(const std::vector<Eigen::Vector3f>& points, float thickness) {
  constexpr float kBin = 0.2f;  // height resolution of the ground search [m]
  if (points.empty()) return -HUGE_VALF;
  std::vector<float> z;
  z.reserve(points.size());
  for (const auto& p : points) z.push_back(p.z());
  std::nth_element(z.begin(), z.begin() + static_cast<long>(z.size() / 2), z.end());
  const float median = z[z.size() / 2];
  std::map<long, int> bins;
  for (const auto& p : points)
    if (p.z() <= median) ++bins[static_cast<long>(std::floor(p.z() / kBin))];
  long best = 0;
  int count = -1;
  for (const auto& [bin, n] : bins)
    if (n > count) best = bin, count = n;
  return static_cast<float>(best + 1) * kBin + thickness;
}

std::size_t cluster_landmark_count(const LandmarkSet& set) {
  return static_cast<std::size_t>(
      std::count_if(set.landmarks.begin(), set.landmarks.end(),
                    [](const Landmark& l) { return l.kind == LandmarkKind::cluster; }));
}

ClassParams params_for_spacing(const ClassParams& p, double spacing, const LandmarkParams& all) {
  if (!all.adapt_to_spacing || spacing <= p.voxel_size) return p;
  ClassParams q = p;
  q.voxel_size = spacing;
  q.cluster_tolerance = std::max(p.cluster_tolerance, all.tolerance_spacings * spacing);
  // Sizes count voxels of the configured size: keep the object's surface the same, so the count
  // shrinks with the square of the voxel ratio.
  const double ratio = p.voxel_size > 0 ? p.voxel_size / spacing : 0.0;
  const auto rescale = [&](int n) {
    return std::max(all.min_cluster_voxels, static_cast<int>(std::ceil(n * ratio * ratio)));
  };
  q.min_points = std::min(p.min_points, rescale(p.min_points));
  q.max_points = std::max(q.min_points, rescale(p.max_points));
  q.normal_radius = std::max(p.normal_radius, 2.0 * spacing);
  q.feature_radius = std::max(p.feature_radius, 2.0 * q.normal_radius);
  return q;
}

LandmarkSet extract_landmarks(const PointCloud& cloud, const LabelScheme& scheme,
                              const LandmarkParams& params) {
  const auto t_all = Clock::now();
  LandmarkSet out;
  out.labels = read_labels(cloud, scheme);
  const bool labelled = !out.labels.scheme.ignores_labels();
  if (!cloud.has_labels())
    out.warnings.push_back("no semantic labels: no semantic landmarks");
  else if (scheme.ignores_labels())
    out.warnings.push_back("labels not used (label_scheme none): no semantic landmarks");
  else if (!labelled)
    out.warnings.push_back("labels not used: " + out.labels.detection.reason +
                           ": no semantic landmarks");
  else if (!out.labels.mismatch.empty())
    out.warnings.push_back(out.labels.mismatch);
  const std::vector<std::vector<int>> subsets =
      labelled ? points_of_classes(cloud, out.labels.scheme, params)
               : std::vector<std::vector<int>>(params.classes.size());
  for (std::size_t ci = 0; ci < params.classes.size(); ++ci)
    extract_class(cloud, subsets[ci], static_cast<int>(ci), params.classes[ci], params, out);
  if (!labelled)  // one warning for the cloud, not one per class
    out.warnings.erase(out.warnings.begin() + 1, out.warnings.end());
  out.time_ms = ms_since(t_all);
  return out;
}

bool needs_fallback(const PointCloud& source, const PointCloud& target, const LandmarkSet& s,
                    const LandmarkSet& t, const FallbackParams& params) {
  switch (params.mode) {
    case FallbackMode::always:
      return true;
    case FallbackMode::never:
      return false;
    case FallbackMode::automatic:
      break;
  }
  const auto few = [&](const LandmarkSet& set) {
    return cluster_landmark_count(set) < static_cast<std::size_t>(params.class_poor_below);
  };
  const auto unlabelled = [](const PointCloud& cloud, const LandmarkSet& set) {
    return !cloud.has_labels() || set.labels.scheme.ignores_labels();
  };
  return unlabelled(source, s) || unlabelled(target, t) || few(s) || few(t);
}

void add_fallback_landmarks(const PointCloud& cloud, const LabelScheme& scheme,
                            const LandmarkParams& params, LandmarkSet& set) {
  const auto t0 = Clock::now();
  const FallbackParams& fb = params.fallback;
  const LabelScheme used =
      set.labels.scheme.name.empty() ? read_labels(cloud, scheme).scheme : set.labels.scheme;
  std::vector<int> subset;
  if (cloud.has_labels() && !used.ignores_labels()) {
    std::vector<char> ground(1u << 16, 0);  // over the 16-bit semantic ids
    for (const auto& name : fb.ground_classes)
      if (used.find(name) >= 0)
        for (std::uint32_t id : used.ids_of(name))
          if (id < ground.size()) ground[id] = 1;
    for (std::size_t i = 0; i < cloud.size(); ++i)
      if (!ground[semantic_id(cloud.labels[i])]) subset.push_back(static_cast<int>(i));
  } else if (!cloud.empty()) {
    const std::vector<char> ground =
        ground_points(cloud.points, {fb.ground_height, fb.ground_cell, fb.ground_slope});
    for (std::size_t i = 0; i < cloud.size(); ++i)
      if (!ground[i]) subset.push_back(static_cast<int>(i));
  }
  ClassParams keypoints = fb.keypoints;
  const bool unlabelled = !cloud.has_labels() || used.ignores_labels();
  if (unlabelled) keypoints.max_keypoints = fb.unlabelled_keypoints;
  extract_class(cloud, subset, static_cast<int>(set.classes.size()), keypoints, params, set);
  if (unlabelled) set.classes.back().one_way_matches = fb.unlabelled_matches;
  set.time_ms += ms_since(t0);
}

}  // namespace pagor
