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
  s.neighbors.reserve(count);
  hint_huge_pages(s.neighbors);
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
  s.neighbors.reserve(rows);
  hint_huge_pages(s.neighbors);
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
  // Raw pointers in the loops: through the vectors, every store reloaded their data pointers.
  int* const core = d.core.data();
  int* const order = d.order.data();
  int* const position = d.position.data();
  const std::int64_t* const offsets = g.offsets.data();
  const int* const neighbors = g.neighbors.data();
  int max_deg = 0;
  for (int v = 0; v < n; ++v) {
    core[v] = static_cast<int>(offsets[v + 1] - offsets[v]);
    max_deg = std::max(max_deg, core[v]);
  }
  // Vertices sorted by degree in `order`, with bucket starts in `bin` (counting sort).
  std::vector<int> bins(static_cast<std::size_t>(max_deg) + 1, 0);
  int* const bin = bins.data();
  for (int v = 0; v < n; ++v) ++bin[core[v]];
  int start = 0;
  for (int k = 0; k <= max_deg; ++k) {
    const int c = bin[k];
    bin[k] = start;
    start += c;
  }
  for (int v = 0; v < n; ++v) {
    const int at = bin[core[v]]++;
    position[v] = at;
    order[at] = v;
  }
  for (int k = max_deg; k > 0; --k) bin[k] = bin[k - 1];
  bin[0] = 0;
  // Take vertices in order; each neighbour of higher current degree moves down one bucket (it
  // swaps places with the first vertex of its bucket, which may be itself).
  for (int i = 0; i < n; ++i) {
    const int v = order[i];
    const int cv = core[v];
    for (const int* p = neighbors + offsets[v], *last = neighbors + offsets[v + 1]; p != last;
         ++p) {
      const int u = *p;
      const int cu = core[u];
      if (cu <= cv) continue;
      const int pu = position[u];
      const int pw = bin[cu]++;
      const int w = order[pw];
      position[u] = pw;
      order[pu] = w;
      position[w] = pu;
      order[pw] = u;
      core[u] = cu - 1;
    }
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
