#include "pagor/pose/gravity.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace pagor {
namespace {

constexpr std::size_t kMaxPoints = 20000;   // sampled points
constexpr std::size_t kScorePoints = 2000;  // of those, the ones a RANSAC plane is scored on
constexpr int kIterations = 200;            // RANSAC planes tried
constexpr unsigned kSeed = 7;               // RANSAC's fixed seed: the same cloud, the same plane
constexpr double kPlaneDistance = 0.15;     // points this close to the plane are on it [m]
constexpr double kMinShare = 0.05;          // least fraction of points on a ground plane

// Normal of the points' least-spread direction, through their mean.
bool fit_plane(const std::vector<Eigen::Vector3d>& pts, Eigen::Vector3d& mean,
               Eigen::Vector3d& normal) {
  if (pts.size() < 3) return false;
  mean.setZero();
  for (const auto& p : pts) mean += p;
  mean /= static_cast<double>(pts.size());
  Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
  for (const auto& p : pts) C += (p - mean) * (p - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(C);
  normal = es.eigenvectors().col(0);  // eigenvalues increase
  return es.eigenvalues()(1) > 0;
}

}  // namespace

GroundPlane ground_plane(const PointCloud& cloud) {
  GroundPlane g;
  const std::size_t stride = cloud.size() / kMaxPoints + 1;
  std::vector<Eigen::Vector3d> pts;
  for (std::size_t i = 0; i < cloud.size(); i += stride) {
    const Eigen::Vector3d p = cloud.points[i].cast<double>();
    if (p.allFinite()) pts.push_back(p);
  }
  if (pts.size() < 3) return g;
  // The dominant plane by RANSAC (planes through three sampled points, each scored on a fixed
  // subset), in any orientation, so that a tilted scan's ground is found tilted.
  const std::size_t score_stride = pts.size() / kScorePoints + 1;
  std::mt19937 rng(kSeed);
  std::uniform_int_distribution<std::size_t> pick(0, pts.size() - 1);
  std::size_t best_count = 0;
  Eigen::Vector3d best_point, best_normal;
  for (int it = 0; it < kIterations; ++it) {
    const Eigen::Vector3d a = pts[pick(rng)], b = pts[pick(rng)], c = pts[pick(rng)];
    Eigen::Vector3d n = (b - a).cross(c - a);
    if (n.norm() < 1e-6) continue;
    n.normalize();
    std::size_t count = 0;
    for (std::size_t i = 0; i < pts.size(); i += score_stride)
      count += std::abs((pts[i] - a).dot(n)) < kPlaneDistance;
    if (count > best_count) best_count = count, best_point = a, best_normal = n;
  }
  if (best_count == 0) return g;
  // Refit on every point near it (principal axes), twice.
  Eigen::Vector3d mean = best_point, normal = best_normal;
  std::vector<Eigen::Vector3d> near;
  for (int pass = 0; pass < 2; ++pass) {
    near.clear();
    for (const auto& p : pts)
      if (std::abs((p - mean).dot(normal)) < kPlaneDistance) near.push_back(p);
    if (!fit_plane(near, mean, normal)) return g;
  }
  std::size_t on = 0;
  for (const auto& p : pts) on += std::abs((p - mean).dot(normal)) < kPlaneDistance;
  g.share = static_cast<double>(on) / static_cast<double>(pts.size());
  g.found = g.share >= kMinShare;
  g.normal = normal.z() < 0 ? Eigen::Vector3d(-normal) : normal;
  g.tilt_deg = std::acos(std::min(1.0, g.normal.z())) * 180.0 / M_PI;
  return g;
}

bool gravity_aligned(const GroundPlane& s, const GroundPlane& t, double tolerance_deg) {
  const double apart = std::acos(std::min(1.0, s.normal.dot(t.normal))) * 180.0 / M_PI;
  return s.found && t.found && s.tilt_deg <= tolerance_deg && t.tilt_deg <= tolerance_deg &&
         apart <= tolerance_deg;
}

}  // namespace pagor
