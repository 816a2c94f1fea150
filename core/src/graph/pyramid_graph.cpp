#include "pagor/graph/pyramid_graph.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

#include "pagor/graph/trim.hpp"

namespace pagor {
namespace {

struct Edge {
  int i, j;
  float trim;
  std::uint8_t level;
};

// Coordinates and ids in flat arrays, read in the hot loop.
struct Packed {
  std::vector<double> px, py, pz, qx, qy, qz;
  std::vector<int> source, target;
  explicit Packed(const std::vector<Correspondence>& c) {
    for (const auto& x : c) {
      px.push_back(x.p.x());
      py.push_back(x.p.y());
      pz.push_back(x.p.z());
      qx.push_back(x.q.x());
      qy.push_back(x.q.y());
      qz.push_back(x.q.z());
      source.push_back(x.source);
      target.push_back(x.target);
    }
  }
};

// Edges (i, j), i < j, for i in [begin, end), in increasing (i, j) order. Most pairs are rejected
// on squared lengths alone; square roots are taken only for the survivors.
void collect_edges(const Packed& c, const GraphParams& params, int begin, int end,
                   std::vector<Edge>& out) {
  const auto& eps = params.thresholds;
  const double largest = eps.back();
  const double min_sq = params.min_length * params.min_length;
  const bool ratio = params.trim == TrimKind::ratio;
  const double ratio_sq = (1.0 + largest) * (1.0 + largest);  // ratio: hi^2 <= (1 + eps)^2 lo^2
  const int m = static_cast<int>(c.px.size());
  for (int i = begin; i < end; ++i) {
    const auto si = static_cast<std::size_t>(i);
    const double pxi = c.px[si], pyi = c.py[si], pzi = c.pz[si];
    const double qxi = c.qx[si], qyi = c.qy[si], qzi = c.qz[si];
    const int s = c.source[si], t = c.target[si];
    for (int j = i + 1; j < m; ++j) {
      const auto sj = static_cast<std::size_t>(j);
      const double dpx = pxi - c.px[sj], dpy = pyi - c.py[sj], dpz = pzi - c.pz[sj];
      const double dqx = qxi - c.qx[sj], dqy = qyi - c.qy[sj], dqz = qzi - c.qz[sj];
      const double a2 = dpx * dpx + dpy * dpy + dpz * dpz;
      const double b2 = dqx * dqx + dqy * dqy + dqz * dqz;
      if (a2 < min_sq || b2 < min_sq) continue;
      if (ratio ? std::max(a2, b2) > ratio_sq * std::min(a2, b2) : false) continue;
      if (s == c.source[sj] || t == c.target[sj]) continue;  // one landmark, two roles
      const double tv = trim_value(params.trim, std::sqrt(a2), std::sqrt(b2));
      if (!(tv <= largest)) continue;
      const auto level = std::lower_bound(eps.begin(), eps.end(), tv) - eps.begin();
      out.push_back({i, j, static_cast<float>(tv), static_cast<std::uint8_t>(level)});
    }
  }
}

}  // namespace

double PyramidGraph::weight(std::size_t e, int l) const {
  if (level[e] > l) return 0.0;
  if (affinity == AffinityKind::binary) return 1.0;
  const double sigma = sigma_ratio * thresholds[static_cast<std::size_t>(l)];
  return std::exp(-double(trim[e]) * trim[e] / (2 * sigma * sigma));
}

bool PyramidGraph::adjacent(int u, int v, int l) const {
  const auto first = neighbors.begin() + offsets[static_cast<std::size_t>(u)];
  const auto last = neighbors.begin() + offsets[static_cast<std::size_t>(u) + 1];
  const auto it = std::lower_bound(first, last, v);
  return it != last && *it == v && level[static_cast<std::size_t>(it - neighbors.begin())] <= l;
}

std::size_t PyramidGraph::active_vertices(int l) const {
  std::size_t n = 0;
  for (int v = 0; v < vertices; ++v)
    for (auto e = offsets[static_cast<std::size_t>(v)];
         e < offsets[static_cast<std::size_t>(v) + 1]; ++e)
      if (level[static_cast<std::size_t>(e)] <= l) {
        ++n;
        break;
      }
  return n;
}

PyramidGraph build_pyramid_graph(const std::vector<Correspondence>& c, const GraphParams& params,
                                 int threads) {
  const auto t0 = std::chrono::steady_clock::now();
  PyramidGraph g;
  g.vertices = static_cast<int>(c.size());
  g.thresholds = params.thresholds;
  g.affinity = params.affinity;
  g.sigma_ratio = params.sigma_ratio;
  g.edges_at_level.assign(params.thresholds.size(), 0);
  g.offsets.assign(c.size() + 1, 0);

  // Rows are split so that each thread gets about the same number of pairs.
  const int m = g.vertices;
  threads = std::max(1, std::min(threads, m / 256 + 1));  // a thread pays off from ~30k pairs on
  std::vector<std::vector<Edge>> parts(static_cast<std::size_t>(threads));
  std::vector<int> bounds{0};
  const double pairs = 0.5 * m * (m - 1.0);
  for (int t = 1; t < threads; ++t) {
    // Rows [0, r) hold r*m - r*(r+1)/2 pairs; solve for the t-th share.
    const double share = pairs * t / threads;
    const double r = (2.0 * m - 1 - std::sqrt((2.0 * m - 1) * (2.0 * m - 1) - 8 * share)) / 2;
    bounds.push_back(std::clamp(static_cast<int>(r), bounds.back(), m));
  }
  bounds.push_back(m);
  const Packed packed(c);
  if (threads == 1) {
    collect_edges(packed, params, 0, m, parts[0]);
  } else {
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t)
      pool.emplace_back(collect_edges, std::cref(packed), std::cref(params), bounds[t],
                        bounds[t + 1], std::ref(parts[static_cast<std::size_t>(t)]));
    for (auto& th : pool) th.join();
  }

  // Symmetric CSR with sorted neighbour lists: count, prefix-sum, fill.
  for (const auto& part : parts)
    for (const Edge& e : part) {
      ++g.offsets[static_cast<std::size_t>(e.i) + 1];
      ++g.offsets[static_cast<std::size_t>(e.j) + 1];
      ++g.edges_at_level[e.level];
    }
  for (std::size_t l = 1; l < g.edges_at_level.size(); ++l)
    g.edges_at_level[l] += g.edges_at_level[l - 1];
  for (std::size_t v = 0; v < c.size(); ++v) g.offsets[v + 1] += g.offsets[v];
  const std::size_t directed = static_cast<std::size_t>(g.offsets.back());
  g.neighbors.resize(directed);
  g.level.resize(directed);
  g.trim.resize(directed);
  std::vector<std::int64_t> fill(g.offsets.begin(), g.offsets.end() - 1);
  // Edges arrive ordered by (i, j). Row v first receives its lower neighbours (as j, from rows
  // i < v, in increasing i) and then its higher ones (as i, increasing j), so rows come out sorted
  // when the (j, i) copies are placed in a first pass and the (i, j) copies in a second.
  auto place = [&](int row, int other, const Edge& e) {
    const auto k = static_cast<std::size_t>(fill[static_cast<std::size_t>(row)]++);
    g.neighbors[k] = other;
    g.level[k] = e.level;
    g.trim[k] = e.trim;
  };
  for (const auto& part : parts)
    for (const Edge& e : part) place(e.j, e.i, e);
  for (const auto& part : parts)
    for (const Edge& e : part) place(e.i, e.j, e);
  g.time_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return g;
}

}  // namespace pagor
