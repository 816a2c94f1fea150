#include "pagor/verify/refinement.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include "pagor/pose/gnc.hpp"
#include "pagor/util/work_budget.hpp"
#include "util/voxel_grid.hpp"

namespace pagor {
namespace {

constexpr int kMinNeighbours = 5;  // fewer points do not define a plane

// Unit normal of the neighbourhood's best-fit plane; false when the neighbourhood is not planar
// enough to define one (the smallest spread is not clearly below the middle one).
bool plane_normal(const std::vector<Eigen::Vector3f>& points, const std::vector<int>& nb,
                  Eigen::Vector3f& normal) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (int i : nb) mean += points[static_cast<std::size_t>(i)].cast<double>();
  mean /= static_cast<double>(nb.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (int i : nb) {
    const Eigen::Vector3d d = points[static_cast<std::size_t>(i)].cast<double>() - mean;
    cov += d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  const Eigen::Vector3d values = eig.eigenvalues();  // ascending
  if (!(values(1) > 0) || values(0) > 0.5 * values(1)) return false;
  normal = eig.eigenvectors().col(0).cast<float>();
  return true;
}

template <class... A>
std::string format(const char* fmt, A... args) {
  char buf[128];
  std::snprintf(buf, sizeof(buf), fmt, args...);
  return buf;
}

// Which of the six twist coordinates (rx, ry, rz, tx, ty, tz) a pose model may change.
std::vector<int> free_coordinates(PoseModel model) {
  switch (model) {
    case PoseModel::se3:
    case PoseModel::automatic:  // the pipeline passes the model GNC kept; any rotation otherwise
      return {0, 1, 2, 3, 4, 5};
    case PoseModel::four_dof:
      return {2, 3, 4, 5};
    case PoseModel::se2:
      return {2, 3, 4};
  }
  return {};
}

// The twist (rx, ry, rz, tx, ty, tz) applied on the left of T.
Transform apply_twist(const Eigen::Matrix<double, 6, 1>& x, const Transform& T) {
  const Eigen::Vector3d w = x.head<3>();
  Transform D = Transform::Identity();
  if (w.norm() > 0) D.block<3, 3>(0, 0) = Eigen::AngleAxisd(w.norm(), w.normalized()).matrix();
  D.block<3, 1>(0, 3) = x.tail<3>();
  return D * T;
}

}  // namespace

struct Refiner::Impl {
  const Verifier* verifier = nullptr;
  double radius = 0.0;
  RadiusGrid cells;  // the target points, for the normals' neighbourhoods
  // Normals are estimated on demand: ICP pairs only the target points near the source.
  std::vector<Eigen::Vector3f> normals;
  std::vector<std::int8_t> state;  // 0 not yet estimated, 1 has a normal, -1 has none
  std::vector<int> neighbours;
  std::vector<float> distance_sq;

  Impl(const Verifier& v, double r)
      : verifier(&v),
        radius((check_radius_work(v.target_points(), r, "refinement.normal_radius",
                                  "the target's verification points"),
                r)),
        cells(v.target_points(), r),
        normals(v.target_points().size()),
        state(v.target_points().size(), 0) {}

  // The normal of target point i, or nullptr when its neighbourhood is not a plane.
  const Eigen::Vector3f* normal(std::size_t i) {
    if (state[i] == 0) {
      const std::vector<Eigen::Vector3f>& target = verifier->target_points();
      neighbours.clear();
      distance_sq.clear();
      cells.within(target[i], static_cast<float>(radius), neighbours, distance_sq);
      const bool ok = static_cast<int>(neighbours.size()) >= kMinNeighbours &&
                      plane_normal(target, neighbours, normals[i]);
      state[i] = ok ? 1 : -1;
    }
    return state[i] > 0 ? &normals[i] : nullptr;
  }
};

Refiner::Refiner(const Verifier& verifier, double normal_radius)
    : impl_(std::make_unique<Impl>(verifier, normal_radius)) {}

Refiner::~Refiner() = default;
Refiner::Refiner(Refiner&&) noexcept = default;
Refiner& Refiner::operator=(Refiner&&) noexcept = default;

std::size_t Refiner::normals_estimated() const {
  return static_cast<std::size_t>(
      std::count_if(impl_->state.begin(), impl_->state.end(), [](std::int8_t s) { return s > 0; }));
}
double Refiner::normal_radius() const {
  return impl_->radius;
}

RefinementResult Refiner::refine(const Transform& T0, double score, PoseModel model,
                                 const RefinementParams& params, const VerificationParams& scoring,
                                 int threads) {
  RefinementResult r;
  r.ran = true;
  r.T_before = r.T_after = T0;
  const std::vector<Eigen::Vector3f>& source = impl_->verifier->source_points();
  const std::vector<Eigen::Vector3f>& target = impl_->verifier->target_points();
  const std::size_t stride =
      std::max<std::size_t>(1, source.size() / static_cast<std::size_t>(params.max_points));
  const std::vector<int> free = free_coordinates(
      model == PoseModel::four_dof && params.free_roll_pitch ? PoseModel::se3 : model);
  const int n = static_cast<int>(free.size());

  Transform T = T0;
  for (int it = 0; it < params.max_iterations; ++it) {
    // Pairing distance: from max_distance down to min_distance over the first half.
    const double f = std::min(1.0, 2.0 * it / std::max(1, params.max_iterations));
    const double pairing = params.max_distance + f * (params.min_distance - params.max_distance);
    const float bound_sq = static_cast<float>(pairing * pairing);
    const Eigen::Matrix3f R = T.block<3, 3>(0, 0).cast<float>();
    const Eigen::Vector3f t = T.block<3, 1>(0, 3).cast<float>();

    // Gauss-Newton on sum w_i (n_i . (p_i' - q_i))^2 with Cauchy weights, in the free twist
    // coordinates only: d/d(w) of n . (w x p') is p' x n, d/d(t) is n.
    // At most 6 free coordinates: fixed-capacity storage, no allocation per point.
    using Vec = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 6, 1>;
    using Mat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 6, 6>;
    Mat H = Mat::Zero(n, n);
    Vec g = Vec::Zero(n);
    int pairs = 0;
    for (std::size_t i = 0; i < source.size(); i += stride) {
      const Eigen::Vector3f p = R * source[i] + t;
      const auto [j, d2] = impl_->verifier->nearest_target(p, bound_sq);
      if (j < 0) continue;
      const Eigen::Vector3f* normal = impl_->normal(static_cast<std::size_t>(j));
      if (!normal) continue;
      const Eigen::Vector3d nq = normal->cast<double>();
      const Eigen::Vector3d pd = p.cast<double>();
      const double res = nq.dot(pd - target[static_cast<std::size_t>(j)].cast<double>());
      Eigen::Matrix<double, 6, 1> full;
      full << pd.cross(nq), nq;
      Vec J(n);
      for (int k = 0; k < n; ++k) J(k) = full(free[static_cast<std::size_t>(k)]);
      const double s = res / params.robust_scale;
      const double w = 1.0 / (1.0 + s * s);
      H.noalias() += w * J * J.transpose();
      g.noalias() += w * res * J;
      ++pairs;
    }
    r.iterations = it + 1;
    r.pairs = pairs;
    if (pairs < 2 * n) {
      r.reason = format("too few point pairs within %.2f m", pairing);
      break;
    }
    // A little damping keeps directions the scene does not constrain (a corridor) in place.
    H.diagonal().array() += 1e-6 * H.diagonal().maxCoeff();
    const Vec step = -H.ldlt().solve(g);
    Eigen::Matrix<double, 6, 1> x = Eigen::Matrix<double, 6, 1>::Zero();
    for (int k = 0; k < n; ++k) x(free[static_cast<std::size_t>(k)]) = step(k);
    T = apply_twist(x, T);
    if (f >= 1.0 && x.head<3>().norm() < 1e-5 && x.tail<3>().norm() < 1e-4) break;
  }

  const auto kind = scoring.score;
  r.score_before = score;
  r.score_after = impl_->verifier->score(T, scoring.mu, kind, threads, &r.distances_after);
  r.correction_translation = (T.block<3, 1>(0, 3) - T0.block<3, 1>(0, 3)).norm();
  r.correction_rotation =
      rotation_angle_deg(T.block<3, 3>(0, 0) * T0.block<3, 3>(0, 0).transpose());
  if (!r.reason.empty()) {
    // too few pairs: the selection stands
  } else if (r.correction_translation > params.max_translation) {
    r.reason = format("moved the pose %.2f m (bound %.2f m)", r.correction_translation,
                      params.max_translation);
  } else if (r.correction_rotation > params.max_rotation) {
    r.reason = format("turned the pose %.2f deg (bound %.2f deg)", r.correction_rotation,
                      params.max_rotation);
  } else if (!(r.score_after < r.score_before)) {
    r.reason = "did not lower D";
  }
  r.applied = r.reason.empty();
  if (r.applied)
    r.T_after = T;
  else
    r.distances_after.clear();
  return r;
}

}  // namespace pagor
