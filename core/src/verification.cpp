#include "pagor/verification.hpp"

#include <chrono>
#include <cmath>
#include <thread>

#include "pagor/kdtree.hpp"
#include "pagor/voxel_grid.hpp"

namespace pagor {

struct Verifier::Impl {
  std::vector<Eigen::Vector3f> source, target;
  KdTree3f tree;
  double build_ms = 0.0;

  // Distance from every source point with index in [begin, end), moved by T, to its nearest
  // target point; +inf when none is closer than `bound` [m] (the search is pruned by it).
  void nearest(const Transform& T, std::size_t begin, std::size_t end, float bound,
               float* out) const {
    const Eigen::Matrix3f R = T.block<3, 3>(0, 0).cast<float>();
    const Eigen::Vector3f t = T.block<3, 1>(0, 3).cast<float>();
    const float bound_sq = bound * bound;
    for (std::size_t i = begin; i < end; ++i) {
      const auto [index, d2] = tree.nearest(R * source[i] + t, bound_sq);
      out[i] = index >= 0 ? std::sqrt(d2) : HUGE_VALF;
    }
  }
};

Verifier::Verifier(const PointCloud& source, const PointCloud& target, double voxel_size)
    : impl_(std::make_unique<Impl>()) {
  const auto t0 = std::chrono::steady_clock::now();
  impl_->source = voxel_downsample(source.points, voxel_size).points;
  impl_->target = voxel_downsample(target.points, voxel_size).points;
  impl_->tree = KdTree3f(impl_->target);
  impl_->build_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

Verifier::~Verifier() = default;
Verifier::Verifier(Verifier&&) noexcept = default;
Verifier& Verifier::operator=(Verifier&&) noexcept = default;

std::pair<int, float> Verifier::nearest_target(const Eigen::Vector3f& q,
                                               float max_distance_sq) const {
  return impl_->tree.nearest(q, max_distance_sq);
}

const std::vector<Eigen::Vector3f>& Verifier::source_points() const {
  return impl_->source;
}
const std::vector<Eigen::Vector3f>& Verifier::target_points() const {
  return impl_->target;
}
double Verifier::build_time_ms() const {
  return impl_->build_ms;
}

std::vector<float> Verifier::distances(const Transform& T, float bound) const {
  std::vector<float> d(impl_->source.size(), HUGE_VALF);
  if (!impl_->target.empty()) impl_->nearest(T, 0, d.size(), bound, d.data());
  return d;
}

double Verifier::score(const Transform& T, double mu, ScoreKind kind, int threads) const {
  const std::size_t n = impl_->source.size();
  std::vector<float> d(n, HUGE_VALF);
  // Truncated and trimmed scores only need neighbours closer than mu.
  const float bound = kind == ScoreKind::nearest ? HUGE_VALF : static_cast<float>(mu);
  if (!impl_->target.empty()) {
    threads = std::max(1, std::min<int>(threads, static_cast<int>(n / 1024) + 1));
    if (threads == 1) {
      impl_->nearest(T, 0, n, bound, d.data());
    } else {
      std::vector<std::thread> pool;
      for (int k = 0; k < threads; ++k)
        pool.emplace_back([&, k] {
          impl_->nearest(T, n * static_cast<std::size_t>(k) / static_cast<std::size_t>(threads),
                         n * static_cast<std::size_t>(k + 1) / static_cast<std::size_t>(threads),
                         bound, d.data());
        });
      for (auto& t : pool) t.join();
    }
  }
  double D = 0.0;
  for (float x : d) {
    switch (kind) {
      case ScoreKind::truncated:
        D += std::min<double>(x, mu);
        break;
      case ScoreKind::trimmed:
        D += x < mu ? x : 0.0;
        break;
      case ScoreKind::nearest:
        D += x;
        break;
    }
  }
  return D;
}

VerificationResult verify_candidates(const Verifier& verifier,
                                     const std::vector<PoseEstimate>& candidates,
                                     const VerificationParams& params, int threads) {
  const auto t0 = std::chrono::steady_clock::now();
  VerificationResult r;
  r.scores.assign(candidates.size(), HUGE_VAL);
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (!candidates[i].valid) continue;
    r.scores[i] = verifier.score(candidates[i].T_target_source, params.mu, params.score, threads);
    if (r.selected < 0) {
      r.selected = static_cast<int>(i);
      continue;
    }
    const double best = r.scores[static_cast<std::size_t>(r.selected)];
    const bool same = std::abs(r.scores[i] - best) <= 1e-9 * std::max(1.0, std::abs(best));
    if (same) {
      r.tie = true;
      if (candidates[i].inliers.size() >
          candidates[static_cast<std::size_t>(r.selected)].inliers.size())
        r.selected = static_cast<int>(i);
    } else if (r.scores[i] < best) {
      r.selected = static_cast<int>(i);
      r.tie = false;
    }
  }
  r.time_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace pagor
