#include "pagor/front/correspondences.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/StdVector>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>

#include "pagor/errors.hpp"
#include "pagor/util/work_budget.hpp"
#include "util/parallel.hpp"

namespace pagor {
namespace {

using Clock = std::chrono::steady_clock;

// Square roots of the sorted covariance eigenvalues: the extents of a cluster [m].
Eigen::Vector3d extents(const Eigen::Matrix3d& cov) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cov, Eigen::EigenvaluesOnly);
  return es.eigenvalues().cwiseMax(0.0).cwiseSqrt();
}

std::vector<int> indices_of_class(const LandmarkSet& set, int class_index) {
  std::vector<int> out;
  for (std::size_t i = 0; i < set.landmarks.size(); ++i)
    if (set.landmarks[i].class_index == class_index) out.push_back(static_cast<int>(i));
  return out;
}

Correspondence make(const LandmarkSet& s, const LandmarkSet& t, int i, int j, double score) {
  Correspondence c;
  c.class_index = s.landmarks[static_cast<std::size_t>(i)].class_index;
  c.source = i;
  c.target = j;
  c.p = s.landmarks[static_cast<std::size_t>(i)].centroid;
  c.q = t.landmarks[static_cast<std::size_t>(j)].centroid;
  c.score = score;
  return c;
}

void all_to_all(const LandmarkSet& s, const LandmarkSet& t, const std::vector<int>& si,
                const std::vector<int>& ti, double shape_scale, std::vector<Correspondence>& out) {
  std::vector<Eigen::Vector3d> te(ti.size());
  for (std::size_t b = 0; b < ti.size(); ++b)
    te[b] = extents(t.landmarks[static_cast<std::size_t>(ti[b])].covariance);
  for (int i : si) {
    const Eigen::Vector3d se = extents(s.landmarks[static_cast<std::size_t>(i)].covariance);
    for (std::size_t b = 0; b < ti.size(); ++b)
      out.push_back(make(s, t, i, ti[b], std::exp(-(se - te[b]).norm() / shape_scale)));
  }
}

// Descriptors of the landmarks `idx`, padded to kStride floats (zeros) for vector arithmetic.
constexpr int kStride = 36;
using Padded = Eigen::Matrix<float, kStride, 1>;
std::vector<Padded, Eigen::aligned_allocator<Padded>> padded(const LandmarkSet& set,
                                                             const std::vector<int>& idx) {
  std::vector<Padded, Eigen::aligned_allocator<Padded>> out(idx.size(), Padded::Zero());
  for (std::size_t k = 0; k < idx.size(); ++k) {
    const auto& d = set.descriptors[static_cast<std::size_t>(idx[k])];
    std::copy(d.begin(), d.begin() + std::min<std::size_t>(d.size(), kStride), out[k].data());
  }
  return out;
}

// Exact nearest neighbours both ways in one pass over all pairs (the 33-D descriptors defeat a
// kd-tree; a linear scan is what FLANN's exact search amounts to): for each source descriptor
// its nearest target (index, squared distance), and for each target its nearest source. Of equal
// distances (identical descriptors) the first wins, where FLANN's tree order decides.
struct NearestBothWays {
  std::vector<std::pair<int, float>> forward, backward;
  std::vector<float> forward_second;  ///< each source's second-nearest squared distance
};
// `threads` > 1 splits the source descriptors into consecutive runs, each with its own nearest
// sources of the targets, merged in run order (the first of equal distances still wins).
NearestBothWays nearest_both_ways(const LandmarkSet& s, const std::vector<int>& si,
                                  const LandmarkSet& t, const std::vector<int>& ti, int threads) {
  const auto a = padded(s, si), b = padded(t, ti);
  NearestBothWays out;
  out.forward.assign(a.size(), {-1, HUGE_VALF});
  out.forward_second.assign(a.size(), HUGE_VALF);
  // A run is worth a thread from ~250k descriptor pairs on (a thread costs ~0.1 ms to start).
  const std::size_t rows = std::max<std::size_t>(1, 250000 / std::max<std::size_t>(1, b.size()));
  const std::size_t runs =
      std::max<std::size_t>(1, std::min<std::size_t>(std::max(threads, 1), a.size() / rows));
  std::vector<std::vector<std::pair<int, float>>> backward(
      runs, std::vector<std::pair<int, float>>(b.size(), {-1, HUGE_VALF}));
  parallel_ranges(static_cast<int>(runs), runs, 1, [&](std::size_t first, std::size_t last) {
    for (std::size_t r = first; r < last; ++r) {
      auto& back = backward[r];
      for (std::size_t i = a.size() * r / runs; i < a.size() * (r + 1) / runs; ++i) {
        auto& f = out.forward[i];
        float& second = out.forward_second[i];
        for (std::size_t j = 0; j < b.size(); ++j) {
          const float d2 = (a[i] - b[j]).squaredNorm();
          if (d2 < f.second) {
            second = f.second;
            f = {static_cast<int>(j), d2};
          } else if (d2 < second) {
            second = d2;
          }
          auto& g = back[j];
          if (d2 < g.second) g = {static_cast<int>(i), d2};
        }
      }
    }
  });
  out.backward = std::move(backward[0]);
  for (std::size_t r = 1; r < runs; ++r)
    for (std::size_t j = 0; j < b.size(); ++j)
      if (backward[r][j].second < out.backward[j].second) out.backward[j] = backward[r][j];
  return out;
}

void fpfh_matches(const LandmarkSet& s, const LandmarkSet& t, const std::vector<int>& si,
                  const std::vector<int>& ti, CorrespondenceParams params, int threads,
                  std::vector<Correspondence>& out) {
  if (si.empty() || ti.empty()) return;
  // A cloud without labels asks for one-way matches of its class-agnostic keypoints.
  const auto c = static_cast<std::size_t>(s.landmarks[static_cast<std::size_t>(si[0])].class_index);
  const int one_way = std::max(c < s.classes.size() ? s.classes[c].one_way_matches : 0,
                               c < t.classes.size() ? t.classes[c].one_way_matches : 0);
  if (one_way > 0) {
    params.fpfh_mutual = false;
    params.fpfh_max_per_class = one_way;
  }
  const auto [forward, backward, second] = nearest_both_ways(s, si, t, ti, threads);
  const double ratio_sq = params.fpfh_ratio * params.fpfh_ratio;
  std::vector<std::pair<float, std::pair<int, int>>> matches;  // (distance, (source k, target k))
  for (std::size_t a = 0; a < forward.size(); ++a) {
    const int b = forward[a].first;
    if (b < 0) continue;
    if (params.fpfh_mutual && backward[static_cast<std::size_t>(b)].first != static_cast<int>(a))
      continue;
    if (params.fpfh_ratio < 1.0 && forward[a].second > ratio_sq * second[a]) continue;
    matches.push_back({std::sqrt(forward[a].second), {static_cast<int>(a), b}});
  }
  std::sort(matches.begin(), matches.end());
  if (matches.size() > static_cast<std::size_t>(params.fpfh_max_per_class))
    matches.resize(static_cast<std::size_t>(params.fpfh_max_per_class));
  if (matches.empty()) return;
  // Score relative to the median distance of the kept matches, so it is comparable across scans.
  const double median = std::max(1e-9, static_cast<double>(matches[matches.size() / 2].first));
  for (const auto& [dist, ab] : matches)
    out.push_back(make(s, t, si[static_cast<std::size_t>(ab.first)],
                       ti[static_cast<std::size_t>(ab.second)], std::exp(-dist / median)));
}

}  // namespace

CorrespondenceSet match_landmarks(const LandmarkSet& source, const LandmarkSet& target,
                                  const CorrespondenceParams& params, int threads) {
  const auto t0 = Clock::now();
  CorrespondenceSet out;
  const int classes = static_cast<int>(std::min(source.classes.size(), target.classes.size()));
  std::vector<Correspondence> all;
  std::size_t candidates = 0;  // all-to-all pairs, counted before any is made
  for (int c = 0; c < classes; ++c) {
    if (source.classes[static_cast<std::size_t>(c)].method == LandmarkMethod::fpfh) continue;
    const double pairs = static_cast<double>(indices_of_class(source, c).size()) *
                         static_cast<double>(indices_of_class(target, c).size());
    candidates += pairs > 1e18 ? static_cast<std::size_t>(1e18) : static_cast<std::size_t>(pairs);
  }
  if (candidates > kMaxCandidateCorrespondences)
    throw ConfigError("landmarks.classes: all-to-all matching of these landmarks would make " +
                      std::to_string(candidates) + " candidate correspondences (budget " +
                      std::to_string(kMaxCandidateCorrespondences) +
                      "); raise min_points or voxel_size so that classes have fewer landmarks");
  for (int c = 0; c < classes; ++c) {
    const std::vector<int> si = indices_of_class(source, c);
    const std::vector<int> ti = indices_of_class(target, c);
    const std::size_t before = all.size();
    if (source.classes[static_cast<std::size_t>(c)].method == LandmarkMethod::fpfh)
      fpfh_matches(source, target, si, ti, params, threads, all);
    else
      all_to_all(source, target, si, ti, params.shape_scale, all);
    if (all.size() == before && (!si.empty() || !ti.empty()))
      out.warnings.push_back("class '" + source.classes[static_cast<std::size_t>(c)].name +
                             "': no correspondences (" + std::to_string(si.size()) + " source, " +
                             std::to_string(ti.size()) + " target landmarks)");
  }
  out.candidates = all.size();
  const std::size_t cap = static_cast<std::size_t>(params.max_correspondences);
  if (cap > 0 && all.size() > cap) {
    std::stable_sort(all.begin(), all.end(), [](const Correspondence& a, const Correspondence& b) {
      return a.score > b.score;
    });
    all.resize(cap);
    out.capped = true;
    out.warnings.push_back("kept the " + std::to_string(cap) + " best-scored of " +
                           std::to_string(out.candidates) +
                           " correspondences (correspondences.max_correspondences)");
  }
  if (all.size() > kMaxGraphCorrespondences)
    throw ConfigError("correspondences.max_correspondences: " + std::to_string(all.size()) +
                      " correspondences are more than the consistency graph's budget of " +
                      std::to_string(kMaxGraphCorrespondences) + "; set a cap at most that");
  // Group by class, best first within a class.
  std::stable_sort(all.begin(), all.end(), [](const Correspondence& a, const Correspondence& b) {
    return a.class_index != b.class_index ? a.class_index < b.class_index : a.score > b.score;
  });
  out.per_class.assign(static_cast<std::size_t>(std::max(classes, 0)), 0);
  for (const auto& c : all) ++out.per_class[static_cast<std::size_t>(c.class_index)];
  out.items = std::move(all);
  out.time_ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
  return out;
}

}  // namespace pagor

namespace pagor {

std::string correspondence_class_name(const Correspondence& c, const LandmarkSet& source) {
  if (c.origin == CorrespondenceOrigin::matcher) return "matcher";
  const auto k = static_cast<std::size_t>(c.class_index);
  return c.class_index >= 0 && k < source.classes.size() ? source.classes[k].name : "?";
}

namespace {
void count(const Correspondence& c, OriginCounts& n) {
  ++(c.origin == CorrespondenceOrigin::matcher ? n.matcher : n.landmark);
}
}  // namespace

OriginCounts count_by_origin(const std::vector<Correspondence>& items) {
  OriginCounts n;
  for (const Correspondence& c : items) count(c, n);
  return n;
}

OriginCounts count_by_origin(const std::vector<Correspondence>& items,
                             const std::vector<int>& indices) {
  OriginCounts n;
  for (int i : indices)
    if (i >= 0 && static_cast<std::size_t>(i) < items.size())
      count(items[static_cast<std::size_t>(i)], n);
  return n;
}

CorrespondenceSet with_matches(std::vector<Correspondence> matches, CorrespondenceSet out,
                               int source_ids, int target_ids) {
  const auto t0 = Clock::now();
  const std::size_t total = out.items.size() + matches.size();
  if (total > kMaxGraphCorrespondences)
    throw InputError(std::to_string(total) +
                     " correspondences are more than the consistency graph's budget of " +
                     std::to_string(kMaxGraphCorrespondences));
  for (std::size_t i = 0; i < matches.size(); ++i) {
    Correspondence& c = matches[i];
    c.class_index = -1;
    c.origin = CorrespondenceOrigin::matcher;
    if (c.source < 0) c.source = static_cast<int>(i);
    if (c.target < 0) c.target = static_cast<int>(i);
    c.source += source_ids;
    c.target += target_ids;
  }
  out.candidates += matches.size();
  out.matches = matches.size();
  out.items.insert(out.items.end(), matches.begin(), matches.end());
  out.time_ms += std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
  return out;
}

}  // namespace pagor
