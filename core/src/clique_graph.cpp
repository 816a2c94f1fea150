#include "clique_graph.hpp"

#include <algorithm>
#include <numeric>

namespace pagor::detail {

LevelCsr level_csr(const PyramidGraph& g, int level) {
  LevelCsr s;
  const auto n = static_cast<std::size_t>(g.vertices);
  s.offsets.assign(n + 1, 0);
  std::size_t count = 0;
  for (std::size_t e = 0; e < g.level.size(); ++e) count += g.level[e] <= level;
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

CoreDecomposition core_decomposition(const LevelCsr& g) {
  const int n = g.size();
  CoreDecomposition d;
  d.core.resize(static_cast<std::size_t>(n));
  int max_deg = 0;
  for (int v = 0; v < n; ++v) {
    d.core[static_cast<std::size_t>(v)] = g.degree(v);
    max_deg = std::max(max_deg, g.degree(v));
  }
  // Vertices sorted by degree in `vert`, with bucket starts in `bin` (counting sort).
  std::vector<int> bin(static_cast<std::size_t>(max_deg) + 1, 0);
  for (int v = 0; v < n; ++v) ++bin[static_cast<std::size_t>(d.core[static_cast<std::size_t>(v)])];
  int start = 0;
  for (int& b : bin) {
    const int c = b;
    b = start;
    start += c;
  }
  d.order.resize(static_cast<std::size_t>(n));
  d.position.resize(static_cast<std::size_t>(n));
  for (int v = 0; v < n; ++v) {
    auto& b = bin[static_cast<std::size_t>(d.core[static_cast<std::size_t>(v)])];
    d.position[static_cast<std::size_t>(v)] = b;
    d.order[static_cast<std::size_t>(b)] = v;
    ++b;
  }
  for (int k = max_deg; k > 0; --k)
    bin[static_cast<std::size_t>(k)] = bin[static_cast<std::size_t>(k) - 1];
  if (!bin.empty()) bin[0] = 0;
  // Take vertices in order; each neighbour of higher current degree moves down one bucket.
  for (int i = 0; i < n; ++i) {
    const int v = d.order[static_cast<std::size_t>(i)];
    const int cv = d.core[static_cast<std::size_t>(v)];
    for (const int* p = g.begin(v); p != g.end(v); ++p) {
      const int u = *p;
      auto& cu = d.core[static_cast<std::size_t>(u)];
      if (cu > cv) {
        const int pu = d.position[static_cast<std::size_t>(u)];
        const int pw = bin[static_cast<std::size_t>(cu)];
        const int w = d.order[static_cast<std::size_t>(pw)];
        if (u != w) {
          d.position[static_cast<std::size_t>(u)] = pw;
          d.order[static_cast<std::size_t>(pu)] = w;
          d.position[static_cast<std::size_t>(w)] = pu;
          d.order[static_cast<std::size_t>(pw)] = u;
        }
        ++bin[static_cast<std::size_t>(cu)];
        --cu;
      }
    }
  }
  for (int c : d.core) d.degeneracy = std::max(d.degeneracy, c);
  return d;
}

std::vector<int> greedy_clique(const LevelCsr& g, const CoreDecomposition& cores, int starts,
                               Marks& marks) {
  std::vector<int> best;
  const int n = g.size();
  // The last vertices of the degeneracy order have the largest core numbers.
  for (int i = n - 1, tried = 0; i >= 0 && tried < starts; --i) {
    const int v = cores.order[static_cast<std::size_t>(i)];
    if (cores.core[static_cast<std::size_t>(v)] + 1 <= static_cast<int>(best.size())) break;
    if (std::binary_search(best.begin(), best.end(), v)) continue;  // would grow much the same
    ++tried;
    // Members of a clique larger than `best` have a core number of at least |best|.
    std::vector<int> c = extend_clique(g, {v}, cores.core, static_cast<int>(best.size()), marks);
    if (c.size() > best.size()) best = std::move(c);
  }
  return best;
}

std::vector<int> k_core(const LevelCsr& g, int k) {
  const int n = g.size();
  std::vector<int> deg(static_cast<std::size_t>(n));
  std::vector<char> removed(static_cast<std::size_t>(n), 0);
  std::vector<int> stack;
  for (int v = 0; v < n; ++v) {
    deg[static_cast<std::size_t>(v)] = g.degree(v);
    if (deg[static_cast<std::size_t>(v)] < k) {
      removed[static_cast<std::size_t>(v)] = 1;
      stack.push_back(v);
    }
  }
  while (!stack.empty()) {
    const int v = stack.back();
    stack.pop_back();
    for (const int* p = g.begin(v); p != g.end(v); ++p) {
      const auto w = static_cast<std::size_t>(*p);
      if (!removed[w] && --deg[w] < k) {
        removed[w] = 1;
        stack.push_back(*p);
      }
    }
  }
  std::vector<int> keep;
  for (int v = 0; v < n; ++v)
    if (!removed[static_cast<std::size_t>(v)]) keep.push_back(v);
  return keep;
}

bool is_clique(const LevelCsr& g, const std::vector<int>& vertices, Marks& marks) {
  for (std::size_t a = 0; a < vertices.size(); ++a) {
    marks.mark_neighbours(g, vertices[a]);
    for (std::size_t b = 0; b < vertices.size(); ++b)
      if (a != b && !marks.has(vertices[b])) return false;
  }
  return true;
}

}  // namespace pagor::detail
