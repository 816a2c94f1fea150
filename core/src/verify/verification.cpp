#include "pagor/verify/verification.hpp"

#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>
#include <string>

#include "pagor/errors.hpp"
#include "pagor/util/kdtree.hpp"
#include "util/parallel.hpp"
#include "util/voxel_grid.hpp"

namespace pagor {

struct Verifier::Impl {
  std::vector<Eigen::Vector3f> source, target;
  std::vector<std::uint32_t> source_labels;
  double build_ms = 0.0;

  // Unbounded searches (ScoreKind::nearest) go to a kd-tree, built on first use.
  std::once_flag tree_once;
  KdTree3f tree_storage;
  const KdTree3f& tree() {
    std::call_once(tree_once, [this] { tree_storage = KdTree3f(target); });
    return tree_storage;
  }

  // Bounded searches go to a hashed grid of cells as large as the bound (1.5x faster than the
  // tree on KITTI scans, bench section 4), built on first use and whenever a larger bound comes;
  // grids are kept until the verifier dies, as another thread may still search an older one.
  // A bound so large that a cell holds more than kMaxCellPoints points on average (mu = 1000 m
  // puts the whole cloud in one cell: every search a linear scan, 7 s a candidate) goes to the
  // tree, which the bound still prunes; so does every larger bound after it. The grid is faster
  // up to ~100 points a cell (synthetic scene: 33 vs 40 ms at mu = 6 m, 71 vs 45 at 12 m); the
  // defaults give ~3.
  static constexpr std::size_t kMaxCellPoints = 128;
  std::mutex grid_mutex;
  std::vector<std::unique_ptr<RadiusGrid>> grids;
  std::atomic<const RadiusGrid*> grid{nullptr};
  std::atomic<float> tree_from{HUGE_VALF};  // bounds at least this large use the tree

  const RadiusGrid* grid_for(float bound) {
    if (!(bound > 0.0f) || !std::isfinite(bound) || target.empty()) return nullptr;
    if (bound >= tree_from.load(std::memory_order_acquire)) return nullptr;
    const RadiusGrid* g = grid.load(std::memory_order_acquire);
    if (g && g->cell() >= bound) return g;
    std::lock_guard<std::mutex> lock(grid_mutex);
    if (bound >= tree_from.load(std::memory_order_acquire)) return nullptr;
    g = grid.load(std::memory_order_acquire);
    if (g && g->cell() >= bound) return g;
    auto built = std::make_unique<RadiusGrid>(target, bound);
    if (target.size() > kMaxCellPoints * built->cell_count()) {
      tree_from.store(bound, std::memory_order_release);
      return nullptr;
    }
    grids.push_back(std::move(built));
    grid.store(grids.back().get(), std::memory_order_release);
    return grids.back().get();
  }

  // Nearest target point strictly closer than `bound` [m], on the grid when there is one.
  std::pair<int, float> nearest_one(const RadiusGrid* g, const Eigen::Vector3f& q, float bound) {
    return g ? g->nearest(q, bound) : tree().nearest(q, bound * bound);
  }

  // Distance from every source point with index in [begin, end), moved by T, to its nearest
  // target point; +inf when none is closer than `bound` [m] (the search is pruned by it).
  // (Points with only[i] == 0 are skipped, when `only` is given.)
  void nearest(const Transform& T, std::size_t begin, std::size_t end, float bound,
               const RadiusGrid* g, float* out, const char* only = nullptr) {
    const Eigen::Matrix3f R = T.block<3, 3>(0, 0).cast<float>();
    const Eigen::Vector3f t = T.block<3, 1>(0, 3).cast<float>();
    for (std::size_t i = begin; i < end; ++i) {
      if (only && !only[i]) continue;
      const auto [index, d2] = nearest_one(g, R * source[i] + t, bound);
      out[i] = index >= 0 ? std::sqrt(d2) : HUGE_VALF;
    }
  }
};

Verifier::Verifier(const PointCloud& source, const PointCloud& target, double voxel_size,
                   int threads)
    : impl_(std::make_unique<Impl>()) {
  const auto t0 = std::chrono::steady_clock::now();
  const auto downsampled = [voxel_size](const PointCloud& cloud) {
    return voxel_downsample(cloud.points, voxel_size, nullptr, /*with_voxel_of=*/false).points;
  };
  // A labelled source keeps, per voxel, the label all its points share (0 where they differ).
  const auto source_with_labels = [&] {
    if (!source.has_labels() || source.labels.size() != source.size()) {
      impl_->source = downsampled(source);
      return;
    }
    VoxelDownsample d = voxel_downsample(source.points, voxel_size);
    impl_->source = std::move(d.points);
    constexpr std::uint32_t kUnset = 0xFFFFFFFFu;
    impl_->source_labels.assign(impl_->source.size(), kUnset);
    for (std::size_t i = 0; i < d.voxel_of.size(); ++i) {
      std::uint32_t& l = impl_->source_labels[static_cast<std::size_t>(d.voxel_of[i])];
      const std::uint32_t mine = semantic_id(source.labels[i]);
      l = l == kUnset || l == mine ? mine : 0;
    }
  };
  parallel_pair(threads, source_with_labels, [&] { impl_->target = downsampled(target); });
  impl_->build_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

Verifier::~Verifier() = default;
Verifier::Verifier(Verifier&&) noexcept = default;
Verifier& Verifier::operator=(Verifier&&) noexcept = default;

std::pair<int, float> Verifier::nearest_target(const Eigen::Vector3f& q,
                                               float max_distance_sq) const {
  const float bound = std::sqrt(max_distance_sq);
  return impl_->nearest_one(impl_->grid_for(bound), q, bound);
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

const std::vector<std::uint32_t>& Verifier::source_labels() const {
  return impl_->source_labels;
}

std::vector<float> Verifier::distances(const Transform& T, float bound) const {
  std::vector<float> d(impl_->source.size(), HUGE_VALF);
  if (!impl_->target.empty())
    impl_->nearest(T, 0, d.size(), bound, impl_->grid_for(bound), d.data());
  return d;
}

std::vector<float> Verifier::distances(const Transform& T, float bound,
                                       const std::vector<char>& only) const {
  if (only.size() != impl_->source.size())
    throw InputError("Verifier::distances: " + std::to_string(only.size()) + " flags for " +
                     std::to_string(impl_->source.size()) + " source points");
  std::vector<float> d(impl_->source.size(), HUGE_VALF);
  if (!impl_->target.empty())
    impl_->nearest(T, 0, d.size(), bound, impl_->grid_for(bound), d.data(), only.data());
  return d;
}

std::size_t Verifier::count_within(const Transform& T, float radius, const std::vector<char>& only,
                                   int threads) const {
  const std::size_t n = impl_->source.size();
  if (only.size() != n)
    throw InputError("Verifier::count_within: " + std::to_string(only.size()) + " flags for " +
                     std::to_string(n) + " source points");
  if (impl_->target.empty() || !(radius > 0.0f)) return 0;
  const RadiusGrid* grid = impl_->grid_for(radius);
  const Eigen::Matrix3f R = T.block<3, 3>(0, 0).cast<float>();
  const Eigen::Vector3f t = T.block<3, 1>(0, 3).cast<float>();
  std::atomic<std::size_t> total{0};
  parallel_ranges(threads, n, 1024, [&](std::size_t begin, std::size_t end) {
    std::size_t count = 0;
    for (std::size_t i = begin; i < end; ++i) {
      if (!only[i]) continue;
      const Eigen::Vector3f q = R * impl_->source[i] + t;
      count +=
          grid ? grid->any_within(q, radius) : impl_->tree().nearest(q, radius * radius).first >= 0;
    }
    total += count;
  });
  return total;
}

double Verifier::score(const Transform& T, double mu, ScoreKind kind, int threads,
                       std::vector<float>* distances) const {
  const std::size_t n = impl_->source.size();
  std::vector<float> local;
  std::vector<float>& d = distances ? *distances : local;
  d.assign(n, HUGE_VALF);
  // Truncated and trimmed scores only need neighbours closer than mu.
  const float bound = kind == ScoreKind::nearest ? HUGE_VALF : static_cast<float>(mu);
  if (!impl_->target.empty()) {
    const RadiusGrid* grid = impl_->grid_for(bound);
    parallel_ranges(threads, n, 1024, [&](std::size_t begin, std::size_t end) {
      impl_->nearest(T, begin, end, bound, grid, d.data());
    });
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
  r.distance_bound = params.score == ScoreKind::nearest ? HUGE_VALF : static_cast<float>(params.mu);
  std::vector<float> d;
  const Transform* kept = nullptr;  // the pose whose distances r.selected_distances holds
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (!candidates[i].valid) continue;
    // Levels that kept the same clique give the same pose: score it once.
    const Transform& T = candidates[i].T_target_source;
    std::size_t same = 0;
    while (same < i && !(candidates[same].valid && candidates[same].T_target_source == T)) ++same;
    const bool scored = same == i;
    r.scores[i] = scored ? verifier.score(T, params.mu, params.score, threads, &d) : r.scores[same];
    if (r.selected < 0) {
      r.selected = static_cast<int>(i);
    } else {
      const double best = r.scores[static_cast<std::size_t>(r.selected)];
      const bool tie = std::abs(r.scores[i] - best) <= 1e-9 * std::max(1.0, std::abs(best));
      if (tie) {
        r.tie = true;
        if (candidates[i].inliers.size() >
            candidates[static_cast<std::size_t>(r.selected)].inliers.size())
          r.selected = static_cast<int>(i);
      } else if (r.scores[i] < best) {
        r.selected = static_cast<int>(i);
        r.tie = false;
      }
    }
    if (r.selected == static_cast<int>(i) && scored) {
      r.selected_distances.swap(d);
      kept = &T;
    }
  }
  if (r.selected >= 0) {
    const Transform& T = candidates[static_cast<std::size_t>(r.selected)].T_target_source;
    if (!kept || !(*kept == T))
      verifier.score(T, params.mu, params.score, threads, &r.selected_distances);
  }
  r.time_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace pagor
