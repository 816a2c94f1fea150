#include "front/point_features.hpp"

#include <pcl/common/centroid.h>
#include <pcl/features/normal_3d.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>

#include "util/voxel_grid.hpp"

namespace pagor::detail {
namespace {

constexpr int kBins = 11;  // per feature, as PCL's FPFH

// Where PCL puts the angle feature among the bins, before its floor: in [0, kBins] for an angle
// in [-pi, pi] (binnable_atan2 and bins_of below must agree on it).
double angle_bin_position(double angle) {
  const float d_pi = 1.0f / (2.0f * static_cast<float>(M_PI));
  return kBins * ((angle + M_PI) * d_pi);
}

}  // namespace

float binnable_atan2(float y, float x) {
  // atan on [0, 1] by the odd polynomial of Abramowitz and Stegun 4.4.47 (error below 1e-5 rad),
  // extended to the plane by the usual reflections.
  const float ax = std::fabs(x), ay = std::fabs(y);
  if (ax == 0 && ay == 0) return std::atan2(y, x);  // signed zeros give 0, +-pi
  const bool steep = ay > ax;
  const double r = steep ? double(ax) / ay : double(ay) / ax;
  const double r2 = r * r;
  double a =
      r * (0.9998660 + r2 * (-0.3302995 + r2 * (0.1801410 + r2 * (-0.0851330 + r2 * 0.0208351))));
  if (steep) a = M_PI / 2 - a;
  if (x < 0) a = M_PI - a;
  if (y < 0) a = -a;
  // Its position in FPFH's 11 bins, as PCL computes it (bins_of below); a bin edge closer than
  // 1e-3 of a bin (5.7e-4 rad, far above the polynomial's error) is decided by atan2 itself.
  const double bin = angle_bin_position(a);
  // (false for NaN); edge: the nearest
  if (bin > -0.5 && bin < kBins + 0.5) {
    const double edge = static_cast<double>(static_cast<int>(bin + 0.5));
    if (std::fabs(bin - edge) > 1e-3) return static_cast<float>(a);
  }
  return std::atan2(y, x);
}

namespace {

using Float4 = float __attribute__((vector_size(16)));  // GCC and Clang vector extension

// PCL's computePairFeatures (pcl/features/pfh_tools.h) on 4-vectors with w = 0, so that every
// operation is the one PCL performs. The order of the pair is decided as PCL does by comparing
// acos(|cos|) of the two normals with the line; as acos decreases, |cos| decides the same except
// within a few ulps. There (and for NaN normals) the test is PCL's, and `tie` is set: the pair
// seen from the other point may then differ, so the caller computes it again.
struct PairFeatures {
  float f1 = 0, f2 = 0, f3 = 0;
};
PairFeatures pair_features(const Eigen::Vector4f& p1, const Eigen::Vector4f& n1,
                           const Eigen::Vector4f& p2, const Eigen::Vector4f& n2, bool exact,
                           bool* tie) {
  PairFeatures f;
  Eigen::Vector4f dp2p1 = p2 - p1;
  dp2p1[3] = 0.0f;
  const float f4 = dp2p1.norm();
  if (f4 == 0.0f) return f;
  Eigen::Vector4f n1_copy = n1, n2_copy = n2;
  const float angle1 = n1_copy.dot(dp2p1) / f4;
  const float angle2 = n2_copy.dot(dp2p1) / f4;
  const float a1 = std::fabs(angle1), a2 = std::fabs(angle2);
  bool swap;
  if (exact || !(std::fabs(a1 - a2) > 1e-6f)) {  // also NaN normals: PCL's own test
    swap = std::acos(a1) > std::acos(a2);
    if (tie) *tie = true;
  } else {
    swap = a1 < a2;
  }
  if (swap) {
    n1_copy = n2;
    n2_copy = n1;
    dp2p1 *= -1;
    f.f3 = -angle2;
  } else {
    f.f3 = angle1;
  }
  Eigen::Vector4f v = dp2p1.cross3(n1_copy);
  v[3] = 0.0f;
  const float v_norm = v.norm();
  if (v_norm == 0.0f) return PairFeatures{};
  v /= v_norm;
  Eigen::Vector4f w = n1_copy.cross3(v);
  v[3] = 0.0f;
  f.f2 = v.dot(n2_copy);
  w[3] = 0.0f;
  f.f1 = binnable_atan2(w.dot(n2_copy), n1_copy.dot(n2_copy));
  return f;
}

// PCL's binning: floor, then clamped to [0, bins); NaN (a NaN normal) lands in bin 0, as the
// conversion of NaN to int (INT_MIN) does in PCL.
int bin_of(double x) {
  if (!(x >= 0.0)) return 0;
  return x < kBins ? static_cast<int>(x) : kBins - 1;  // truncation is floor here
}
std::array<int, 3> bins_of(const PairFeatures& f) {
  return {bin_of(angle_bin_position(f.f1)), kBins + bin_of(kBins * ((f.f2 + 1.0) * 0.5)),
          2 * kBins + bin_of(kBins * ((f.f3 + 1.0) * 0.5))};
}

Eigen::Vector4f point4(const Eigen::Vector3f& p) {
  return Eigen::Vector4f(p.x(), p.y(), p.z(), 1.0f);
}
Eigen::Vector4f normal4(const Eigen::Vector3f& n) {
  return Eigen::Vector4f(n.x(), n.y(), n.z(), 0.0f);
}

}  // namespace

std::vector<std::vector<int>> euclidean_clusters(const std::vector<Eigen::Vector3f>& points,
                                                 double tolerance, int min_size, int max_size) {
  std::vector<std::vector<int>> clusters;
  if (points.empty() || !(tolerance > 0)) return clusters;
  // Connected components of the pairs closer than the tolerance (union-find, each pair seen
  // once): the same components as PCL's breadth-first growth from every unvisited point.
  const RadiusGrid grid(points, tolerance);
  std::vector<int> parent(points.size());
  std::iota(parent.begin(), parent.end(), 0);
  const auto root = [&](int i) {
    while (parent[static_cast<std::size_t>(i)] != i) {
      parent[static_cast<std::size_t>(i)] =
          parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(i)])];
      i = parent[static_cast<std::size_t>(i)];
    }
    return i;
  };
  grid.for_each_pair_within(static_cast<float>(tolerance), [&](int i, int j, float) {
    const int a = root(i), b = root(j);
    if (a != b) parent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
  });
  // Components in order of their smallest member (the order growth finds them in), members
  // ascending; then the sizes kept, largest first (stable: ties by smallest member).
  std::vector<int> component(points.size(), -1);
  std::vector<std::vector<int>> all;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto r = static_cast<std::size_t>(root(static_cast<int>(i)));
    if (component[r] < 0) {
      component[r] = static_cast<int>(all.size());
      all.emplace_back();
    }
    all[static_cast<std::size_t>(component[r])].push_back(static_cast<int>(i));
  }
  for (auto& c : all) {
    const int size = static_cast<int>(c.size());
    if (size >= min_size && size <= max_size) clusters.push_back(std::move(c));
  }
  std::stable_sort(clusters.begin(), clusters.end(),
                   [](const auto& a, const auto& b) { return a.size() > b.size(); });
  return clusters;
}

std::vector<Eigen::Vector3f> estimate_normals(const std::vector<Eigen::Vector3f>& points,
                                              double radius) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<Eigen::Vector3f> normals(points.size(), Eigen::Vector3f::Constant(nan));
  if (points.empty()) return normals;
  pcl::PointCloud<pcl::PointXYZ> cloud;
  cloud.resize(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    cloud[i] = pcl::PointXYZ(points[i].x(), points[i].y(), points[i].z());
  // Every point's neighbours closer than the radius (itself included) from the grid's pairs,
  // counted in one pass and gathered in a second.
  const RadiusGrid grid(points, radius);
  const float r = static_cast<float>(radius);
  std::vector<std::size_t> start(points.size() + 1, 0);
  for (std::size_t i = 0; i < points.size(); ++i) start[i + 1] = 1;  // itself
  grid.for_each_pair_within(r, [&](int i, int j, float) {
    ++start[static_cast<std::size_t>(i) + 1];
    ++start[static_cast<std::size_t>(j) + 1];
  });
  for (std::size_t i = 0; i < points.size(); ++i) start[i + 1] += start[i];
  std::vector<std::pair<float, int>> near(start.back());
  std::vector<std::size_t> fill(start.begin(), start.end() - 1);
  for (std::size_t i = 0; i < points.size(); ++i) near[fill[i]++] = {0.0f, static_cast<int>(i)};
  grid.for_each_pair_within(r, [&](int i, int j, float d2) {
    near[fill[static_cast<std::size_t>(i)]++] = {d2, j};
    near[fill[static_cast<std::size_t>(j)]++] = {d2, i};
  });
  pcl::Indices found;
  for (std::size_t i = 0; i < points.size(); ++i) {
    // In FLANN's order (by distance, then index): the covariance sums in float, and a nearly
    // degenerate neighbourhood's normal depends on the order of the sum.
    const auto first = near.begin() + static_cast<std::ptrdiff_t>(start[i]);
    const auto last = near.begin() + static_cast<std::ptrdiff_t>(start[i + 1]);
    std::sort(first, last);
    found.clear();
    for (auto it = first; it != last; ++it) found.push_back(it->second);
    EIGEN_ALIGN16 Eigen::Matrix3f covariance;
    Eigen::Vector4f centroid;
    if (found.size() < 3 ||
        pcl::computeMeanAndCovarianceMatrix(cloud, found, covariance, centroid) == 0)
      continue;
    float nx, ny, nz, curvature;
    pcl::solvePlaneParameters(covariance, nx, ny, nz, curvature);
    pcl::flipNormalTowardsViewpoint(cloud[i], 0.0f, 0.0f, 0.0f, nx, ny, nz);
    normals[i] = Eigen::Vector3f(nx, ny, nz);
  }
  return normals;
}

std::vector<Fpfh> compute_fpfh(const std::vector<Eigen::Vector3f>& points,
                               const std::vector<Eigen::Vector3f>& normals,
                               const std::vector<int>& keypoints, double radius) {
  std::vector<Fpfh> out(keypoints.size());
  if (points.empty() || keypoints.empty()) return out;
  const RadiusGrid grid(points, radius);
  const float r = static_cast<float>(radius);
  // The keypoints' neighbourhoods; every point in one needs its SPFH (a row).
  std::vector<std::vector<int>> near(keypoints.size());
  std::vector<std::vector<float>> near_d2(keypoints.size());
  std::vector<int> row(points.size(), -1);
  for (std::size_t k = 0; k < keypoints.size(); ++k) {
    grid.within(points[static_cast<std::size_t>(keypoints[k])], r, near[k], near_d2[k]);
    for (int j : near[k]) row[static_cast<std::size_t>(j)] = 0;
  }
  int rows = 0;
  for (int& x : row)
    if (x == 0) x = rows++;
  // SPFH: bin counts, each pair's features computed once for both of its points when both need
  // them (they are symmetric), then scaled by 100 / (neighbours - 1) as PCL's increments.
  std::vector<float> hist(static_cast<std::size_t>(rows) * 33, 0.0f);
  std::vector<int> found;
  std::vector<float> d2;
  const auto add = [&](int p, const PairFeatures& f) {
    float* h = hist.data() + static_cast<std::size_t>(row[static_cast<std::size_t>(p)]) * 33;
    for (int b : bins_of(f)) h[b] += 1.0f;
  };
  std::vector<int> keypoint_of(points.size(), -1);  // keypoints' lists are searched already
  for (std::size_t k = 0; k < keypoints.size(); ++k)
    keypoint_of[static_cast<std::size_t>(keypoints[k])] = static_cast<int>(k);
  for (std::size_t p = 0; p < points.size(); ++p) {
    if (row[p] < 0) continue;
    const std::vector<int>* list = &found;
    if (keypoint_of[p] >= 0) {
      list = &near[static_cast<std::size_t>(keypoint_of[p])];
    } else {
      found.clear();
      d2.clear();
      grid.within(points[p], r, found, d2);
    }
    const Eigen::Vector4f pp = point4(points[p]), np = normal4(normals[p]);
    for (int q : *list) {
      const auto uq = static_cast<std::size_t>(q);
      if (uq == p || (row[uq] >= 0 && uq < p)) continue;  // itself, or done from q's side
      bool tie = false;
      const Eigen::Vector4f pq = point4(points[uq]), nq = normal4(normals[uq]);
      const PairFeatures f = pair_features(pp, np, pq, nq, false, &tie);
      add(static_cast<int>(p), f);
      if (row[uq] >= 0) add(q, tie ? pair_features(pq, nq, pp, np, true, nullptr) : f);
    }
    if (list->size() > 1) {
      const float incr = 100.0f / static_cast<float>(list->size() - 1);
      float* h = hist.data() + static_cast<std::size_t>(row[p]) * 33;
      for (int b = 0; b < 33; ++b) h[b] *= incr;
    }
  }
  // FPFH: the neighbours' SPFH weighted by 1 / squared distance, each third scaled to sum 100.
  for (std::size_t k = 0; k < keypoints.size(); ++k) {
    float fpfh[33] = {};
    for (std::size_t a = 0; a < near[k].size(); ++a) {
      if (near_d2[k][a] == 0) continue;
      const float weight = 1.0f / near_d2[k][a];
      const float* h =
          hist.data() + static_cast<std::size_t>(row[static_cast<std::size_t>(near[k][a])]) * 33;
      // Bin by bin as the plain loop, four bins at a time (each bin's sum in the same order).
      for (int b = 0; b < 32; b += 4) {
        Float4 acc, hb;
        std::memcpy(&acc, fpfh + b, sizeof acc);
        std::memcpy(&hb, h + b, sizeof hb);
        acc += hb * weight;
        std::memcpy(fpfh + b, &acc, sizeof acc);
      }
      fpfh[32] += h[32] * weight;
    }
    for (int t = 0; t < 3; ++t) {
      double sum = 0;
      for (int b = t * kBins; b < (t + 1) * kBins; ++b) sum += fpfh[b];
      if (sum != 0) sum = 100.0 / sum;
      for (int b = t * kBins; b < (t + 1) * kBins; ++b)
        out[k][static_cast<std::size_t>(b)] = static_cast<float>(fpfh[b] * sum);
    }
  }
  return out;
}

}  // namespace pagor::detail
