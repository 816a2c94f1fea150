#include "pagor/pyramid_graph.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

#include "pagor/trim.hpp"

namespace pagor {
namespace {

struct Edge {
  int i, j;
  float trim;
  std::uint8_t level;
};

// Edges (i, j), i < j, for i in [begin, end), in increasing (i, j) order.
void collect_edges(const std::vector<Correspondence>& c, const GraphParams& params, int begin,
                   int end, std::vector<Edge>& out) {
  const auto& eps = params.thresholds;
  const double largest = eps.back();
  const int m = static_cast<int>(c.size());
  for (int i = begin; i < end; ++i) {
    const Correspondence& ci = c[static_cast<std::size_t>(i)];
    for (int j = i + 1; j < m; ++j) {
      const Correspondence& cj = c[static_cast<std::size_t>(j)];
      if (ci.source == cj.source || ci.target == cj.target) continue;  // one landmark, two roles
      const double a = (ci.p - cj.p).norm();
      const double b = (ci.q - cj.q).norm();
      if (a < params.min_length || b < params.min_length) continue;
      const double t = trim_value(params.trim, a, b);
      if (!(t <= largest)) continue;
      const auto level = std::lower_bound(eps.begin(), eps.end(), t) - eps.begin();
      out.push_back({i, j, static_cast<float>(t), static_cast<std::uint8_t>(level)});
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
    for (auto e = offsets[static_cast<std::size_t>(v)]; e < offsets[static_cast<std::size_t>(v) + 1]; ++e)
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
  threads = std::max(1, std::min(threads, m / 64 + 1));
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
  if (threads == 1) {
    collect_edges(c, params, 0, m, parts[0]);
  } else {
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t)
      pool.emplace_back(collect_edges, std::cref(c), std::cref(params), bounds[t], bounds[t + 1],
                        std::ref(parts[static_cast<std::size_t>(t)]));
    for (auto& th : pool) th.join();
  }

  // Symmetric CSR with sorted neighbour lists: count, prefix-sum, fill.
  for (const auto& part : parts)
    for (const Edge& e : part) {
      ++g.offsets[static_cast<std::size_t>(e.i) + 1];
      ++g.offsets[static_cast<std::size_t>(e.j) + 1];
      ++g.edges_at_level[e.level];
    }
  for (std::size_t l = 1; l < g.edges_at_level.size(); ++l) g.edges_at_level[l] += g.edges_at_level[l - 1];
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
  g.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return g;
}

}  // namespace pagor
