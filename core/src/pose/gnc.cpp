#include "pagor/pose/gnc.hpp"

#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
#include <chrono>
#include <cmath>

namespace pagor {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Relative size of the second principal extent below which a point set counts as collinear.
constexpr double kCollinearRatio = 1e-3;

}  // namespace

double squared_residual(const Transform& T, const Eigen::Vector3d& p, const Eigen::Vector3d& q,
                        PoseModel model) {
  Eigen::Vector3d r = T.block<3, 3>(0, 0) * p + T.block<3, 1>(0, 3) - q;
  if (model == PoseModel::se2) r.z() = 0;
  return r.squaredNorm();
}

double rotation_angle_deg(const Eigen::Matrix3d& R) {
  const double c = std::clamp((R.trace() - 1.0) / 2.0, -1.0, 1.0);
  return std::acos(c) * 180.0 / kPi;
}

bool weighted_rigid_transform(const std::vector<Eigen::Vector3d>& src,
                              const std::vector<Eigen::Vector3d>& dst, const std::vector<double>& w,
                              PoseModel model, Transform& T) {
  // Rotation dimension: SE(3) (and `automatic` called directly) estimates a 3-D rotation; SE(2)
  // and 4-DoF only a yaw.
  const int dim = model == PoseModel::se3 || model == PoseModel::automatic ? 3 : 2;
  double wsum = 0;
  Eigen::Vector3d ps = Eigen::Vector3d::Zero(), qs = Eigen::Vector3d::Zero();
  int support = 0;
  for (std::size_t i = 0; i < src.size(); ++i) {
    if (w[i] <= 0) continue;
    wsum += w[i];
    ps += w[i] * src[i];
    qs += w[i] * dst[i];
    ++support;
  }
  if (support < dim || wsum <= 0) return false;
  ps /= wsum;
  qs /= wsum;
  Eigen::Matrix3d H = Eigen::Matrix3d::Zero(), S = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < src.size(); ++i) {
    if (w[i] <= 0) continue;
    Eigen::Vector3d a = src[i] - ps, b = dst[i] - qs;
    if (dim == 2) a.z() = b.z() = 0;
    H += w[i] * a * b.transpose();
    S += w[i] * a * a.transpose();
  }
  // Degeneracy: the weighted source spread must span a plane (a line in SE(2)).
  Eigen::JacobiSVD<Eigen::Matrix3d> spread(S);
  const Eigen::Vector3d sv = spread.singularValues();
  if (sv(0) <= 1e-12) return false;
  if (dim == 3 && sv(1) < kCollinearRatio * sv(0)) return false;

  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  if (dim == 3) {
    Eigen::JacobiSVD<Eigen::Matrix3d> svd(H, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Eigen::Matrix3d D = Eigen::Matrix3d::Identity();
    D(2, 2) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0 ? -1.0 : 1.0;
    R = svd.matrixV() * D * svd.matrixU().transpose();
  } else {
    // Planar: yaw = atan2(sum a x b, sum a . b) in the x-y plane.
    const double yaw = std::atan2(H(0, 1) - H(1, 0), H(0, 0) + H(1, 1));
    R.block<2, 2>(0, 0) << std::cos(yaw), -std::sin(yaw), std::sin(yaw), std::cos(yaw);
  }
  T = Transform::Identity();
  T.block<3, 3>(0, 0) = R;
  T.block<3, 1>(0, 3) = qs - R * ps;
  if (model == PoseModel::se2) T(2, 3) = 0.0;  // 4-DoF keeps the height offset
  return true;
}

namespace {

PoseEstimate gnc_one_model(const std::vector<Eigen::Vector3d>& src,
                           const std::vector<Eigen::Vector3d>& dst, const GncParams& p);

}  // namespace

PoseEstimate estimate_pose_gnc(const std::vector<Correspondence>& correspondences,
                               const std::vector<int>& members, const GncParams& params) {
  std::vector<Eigen::Vector3d> p, q;
  p.reserve(members.size());
  q.reserve(members.size());
  for (int v : members) {
    p.push_back(correspondences[static_cast<std::size_t>(v)].p);
    q.push_back(correspondences[static_cast<std::size_t>(v)].q);
  }
  PoseEstimate e = estimate_pose_gnc(p, q, params);
  for (int& i : e.inliers) i = members[static_cast<std::size_t>(i)];  // -> correspondence ids
  return e;
}

PoseEstimate estimate_pose_gnc(const std::vector<Eigen::Vector3d>& src,
                               const std::vector<Eigen::Vector3d>& dst, const GncParams& p) {
  if (p.model != PoseModel::automatic) return gnc_one_model(src, dst, p);
  // Both models; the simpler one where it explains the correspondences as well.
  const auto t0 = std::chrono::steady_clock::now();
  GncParams level = p;
  level.model = PoseModel::four_dof;
  PoseEstimate four = gnc_one_model(src, dst, level);
  if (src.size() >= static_cast<std::size_t>(minimal_sample_size(PoseModel::se3))) {
    GncParams full = p;
    full.model = PoseModel::se3;
    PoseEstimate se3 = gnc_one_model(src, dst, full);
    if (se3.valid && (!four.valid || se3.inliers.size() > four.inliers.size()))
      four = std::move(se3);
  }
  four.time_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return four;
}

namespace {

PoseEstimate gnc_one_model(const std::vector<Eigen::Vector3d>& src,
                           const std::vector<Eigen::Vector3d>& dst, const GncParams& p) {
  const auto t0 = std::chrono::steady_clock::now();
  auto finish = [&](PoseEstimate& e) {
    e.time_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    return e;
  };
  PoseEstimate est;
  est.model = p.model;
  const std::size_t n = src.size();
  const std::size_t needed = static_cast<std::size_t>(minimal_sample_size(p.model));
  if (n < needed || dst.size() != n) {
    est.failure = "needs at least " + std::to_string(needed) + " correspondences, got " +
                  std::to_string(std::min(n, dst.size()));
    return finish(est);
  }
  const double c2 = p.noise_bound * p.noise_bound;
  std::vector<double> w(n, 1.0), r2(n);
  Transform T;
  if (!weighted_rigid_transform(src, dst, w, p.model, T)) {
    est.failure = "degenerate correspondences (collinear or coincident)";
    return finish(est);
  }
  auto residuals = [&] {
    double worst = 0;
    for (std::size_t i = 0; i < n; ++i)
      worst = std::max(worst, r2[i] = squared_residual(T, src[i], dst[i], p.model));
    return worst;
  };
  const double r2_max = residuals();
  if (r2_max > c2) {
    // Continuation from a nearly convex surrogate (Yang et al., GNC-TLS).
    double mu = c2 / std::max(2 * r2_max - c2, 1e-12);
    double previous_cost = HUGE_VAL;
    for (int it = 0; it < p.max_iterations; ++it) {
      est.iterations = it + 1;
      const double lower = mu / (mu + 1) * c2, upper = (mu + 1) / mu * c2;
      for (std::size_t i = 0; i < n; ++i) {
        if (r2[i] >= upper)
          w[i] = 0;
        else if (r2[i] <= lower)
          w[i] = 1;
        else
          w[i] = std::sqrt(c2 * mu * (mu + 1) / r2[i]) - mu;
      }
      if (!weighted_rigid_transform(src, dst, w, p.model, T)) {
        est.failure = "degenerate inlier set during GNC (collinear or too few)";
        return finish(est);
      }
      residuals();
      double cost = 0;
      for (std::size_t i = 0; i < n; ++i) cost += w[i] * r2[i];
      if (std::abs(cost - previous_cost) < p.cost_tolerance) break;
      previous_cost = cost;
      mu *= p.mu_factor;
    }
  }
  for (std::size_t i = 0; i < n; ++i)
    if (r2[i] <= c2) est.inliers.push_back(static_cast<int>(i));
  // Refit on the inliers, and require them to be non-degenerate.
  std::vector<double> inlier_w(n, 0.0);
  for (int i : est.inliers) inlier_w[static_cast<std::size_t>(i)] = 1.0;
  if (est.inliers.size() < needed || !weighted_rigid_transform(src, dst, inlier_w, p.model, T)) {
    est.failure = "fewer than " + std::to_string(needed) + " non-degenerate inliers";
    est.inliers.clear();
    return finish(est);
  }
  est.valid = true;
  est.T_target_source = T;
  return finish(est);
}

}  // namespace

}  // namespace pagor
