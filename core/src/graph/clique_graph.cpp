#include "graph/clique_graph.hpp"

#include <algorithm>
#include <numeric>

namespace pagor::detail {

LevelCsr level_csr(const PyramidGraph& g, int level) {
  LevelCsr s;
  const auto n = static_cast<std::size_t>(g.vertices);
  s.offsets.assign(n + 1, 0);
  std::size_t count = 0;
  for (std::size_t e = 0; e < g.level.size(); ++e) count += g.level[e] <= level;
  reserve_fresh(s.neighbors, count);
  s.neighbors.resize(count);
  std::size_t k = 0;
  for (std::size_t v = 0; v < n; ++v) {
    const auto first = static_cast<std::size_t>(g.offsets[v]);
    const auto last = static_cast<std::size_t>(g.offsets[v + 1]);
    for (std::size_t e = first; e < last; ++e)
      if (g.level[e] <= level) s.neighbors[k++] = g.neighbors[e];
    s.offsets[v + 1] = static_cast<std::int64_t>(k);
  }
  return s;
}

LevelCsr level_csr(const PyramidGraph& g, int level, const std::vector<int>& keep) {
  LevelCsr s;
  std::vector<int> local(static_cast<std::size_t>(g.vertices), -1);
  for (std::size_t i = 0; i < keep.size(); ++i)
    local[static_cast<std::size_t>(keep[i])] = static_cast<int>(i);
  s.offsets.assign(keep.size() + 1, 0);
  std::size_t rows = 0;  // room enough: the kept rows over all levels
  for (int v : keep)
    rows += static_cast<std::size_t>(g.offsets[static_cast<std::size_t>(v) + 1] -
                                     g.offsets[static_cast<std::size_t>(v)]);
  reserve_fresh(s.neighbors, rows);
  s.neighbors.resize(rows);
  int* out = s.neighbors.data();
  std::size_t k = 0;
  const auto lv = static_cast<std::uint8_t>(level);
  for (std::size_t i = 0; i < keep.size(); ++i) {
    const auto v = static_cast<std::size_t>(keep[i]);
    const auto last = static_cast<std::size_t>(g.offsets[v + 1]);
    for (auto e = static_cast<std::size_t>(g.offsets[v]); e < last; ++e) {
      const int w = local[static_cast<std::size_t>(g.neighbors[e])];
      out[k] = w;  // sorted: keep is
      k += (g.level[e] <= lv) & (w >= 0);
    }
    s.offsets[i + 1] = static_cast<std::int64_t>(k);
  }
  s.neighbors.resize(k);
  return s;
}

CoreDecomposition core_decomposition(const LevelCsr& g) {
  const int n = g.size();
  CoreDecomposition d;
  d.core.resize(static_cast<std::size_t>(n));
  d.order.resize(static_cast<std::size_t>(n));
  d.position.resize(static_cast<std::size_t>(n));
  const std::int64_t* const offsets = g.offsets.data();
  const int* const neighbors = g.neighbors.data();
  for (int v = 0; v < n; ++v)
    d.core[static_cast<std::size_t>(v)] = static_cast<int>(offsets[v + 1] - offsets[v]);
  DegreeBuckets buckets(d);
  const int* const core = d.core.data();
  for (int i = 0; i < n; ++i) {
    const int v = buckets.at(i);
    const int cv = core[v];
    for (const int *p = neighbors + offsets[v], *last = neighbors + offsets[v + 1]; p != last; ++p)
      buckets.lower_above(*p, cv);
  }
  for (int c : d.core) d.degeneracy = std::max(d.degeneracy, c);
  return d;
}

std::vector<int> level_degrees(const PyramidGraph& g, int level) {
  std::vector<int> deg(static_cast<std::size_t>(g.vertices), 0);
  for (std::size_t v = 0; v < deg.size(); ++v) {
    int d = 0;
    const auto last = static_cast<std::size_t>(g.offsets[v + 1]);
    for (auto e = static_cast<std::size_t>(g.offsets[v]); e < last; ++e) d += g.level[e] <= level;
    deg[v] = d;
  }
  return deg;
}

}  // namespace pagor::detail
