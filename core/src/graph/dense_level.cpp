#include "graph/dense_level.hpp"

#include <algorithm>

namespace pagor::detail {

bool dense_level(const PyramidGraph& g, int level) {
  if (g.vertices <= 0 || g.vertices > kMaxLevelBits || level < 0 ||
      static_cast<std::size_t>(level) >= g.edges_at_level.size())
    return false;
  const std::size_t words =
      static_cast<std::size_t>(g.vertices) * static_cast<std::size_t>(words_for(g.vertices));
  return words <= 2 * g.edges_at_level[static_cast<std::size_t>(level)];
}

BitGraph level_bits(const PyramidGraph& g, int level) {
  BitGraph b(g.vertices);
  const auto lv = static_cast<std::uint8_t>(level);
  const std::uint8_t* lev = g.level.data();
  const int* nb = g.neighbors.data();
  for (int v = 0; v < g.vertices; ++v) {
    Word* row = b.row(v);
    const auto last = g.offsets[static_cast<std::size_t>(v) + 1];
    for (auto e = g.offsets[static_cast<std::size_t>(v)]; e < last; ++e)  // branch-free
      row[nb[e] >> 6] |= Word(lev[e] <= lv) << (nb[e] & 63);
  }
  return b;
}

std::vector<BitGraph> levels_bits(const PyramidGraph& g, int first) {
  const int levels = g.levels();
  std::vector<BitGraph> out(static_cast<std::size_t>(std::max(levels, 0)));
  if (first < 0 || first >= levels) return {};
  for (int l = first; l < levels; ++l) out[static_cast<std::size_t>(l)] = BitGraph(g.vertices);
  const std::uint8_t* lev = g.level.data();
  const int* nb = g.neighbors.data();
  for (int v = 0; v < g.vertices; ++v) {
    Word* rows[GraphParams::kMaxLevels];
    for (int l = first; l < levels; ++l) rows[l] = out[static_cast<std::size_t>(l)].row(v);
    const auto last = g.offsets[static_cast<std::size_t>(v) + 1];
    for (auto e = g.offsets[static_cast<std::size_t>(v)]; e < last; ++e)
      set_bit(rows[std::max<int>(lev[e], first)], nb[e]);
  }
  const std::size_t words =
      static_cast<std::size_t>(g.vertices) * static_cast<std::size_t>(words_for(g.vertices));
  for (int l = first + 1; l < levels && words > 0; ++l) {
    Word* to = out[static_cast<std::size_t>(l)].row(0);
    const Word* from = out[static_cast<std::size_t>(l) - 1].row(0);
    for (std::size_t k = 0; k < words; ++k) to[k] |= from[k];
  }
  return out;
}

PAGOR_POPCOUNT_CLONES std::vector<int> degrees(const BitGraph& g) {
  std::vector<int> deg(static_cast<std::size_t>(g.size()));
  for (int v = 0; v < g.size(); ++v) {
    const Word* r = g.row(v);
    int d = 0;
    for (int k = 0; k < g.words(); ++k) d += __builtin_popcountll(r[k]);
    deg[static_cast<std::size_t>(v)] = d;
  }
  return deg;
}

std::vector<int> extend_clique(const BitGraph& g, std::vector<int> clique,
                               const std::vector<int>& priority, int min_priority, Marks&) {
  if (clique.empty()) return clique;
  const int w = g.words();
  // Candidates: adjacent to every member (no row holds its own vertex, so no member is one).
  std::vector<Word> cand(g.row(clique[0]), g.row(clique[0]) + w);
  for (std::size_t i = 1; i < clique.size(); ++i) {
    const Word* r = g.row(clique[i]);
    for (int k = 0; k < w; ++k) cand[static_cast<std::size_t>(k)] &= r[k];
  }
  std::vector<int> order;
  for_each_bit(cand.data(), w, [&](int v) {
    if (priority[static_cast<std::size_t>(v)] >= min_priority) order.push_back(v);
  });
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return priority[static_cast<std::size_t>(a)] > priority[static_cast<std::size_t>(b)];
  });
  // The best candidate still adjacent to every member taken so far joins, in that order.
  for (int v : order) {
    if (!test_bit(cand.data(), v)) continue;
    clique.push_back(v);
    const Word* r = g.row(v);
    for (int k = 0; k < w; ++k) cand[static_cast<std::size_t>(k)] &= r[k];
  }
  std::sort(clique.begin(), clique.end());
  return clique;
}

bool is_clique(const BitGraph& g, const std::vector<int>& vertices, Marks&) {
  const int w = g.words();
  std::vector<Word> members(static_cast<std::size_t>(w), 0);
  for (int v : vertices) set_bit(members.data(), v);
  for (int v : vertices) {
    const Word* r = g.row(v);
    for (int k = 0; k < w; ++k) {
      Word missing = members[static_cast<std::size_t>(k)] & ~r[k];
      if (k == (v >> 6)) missing &= ~(Word(1) << (v & 63));  // v itself
      if (missing) return false;
    }
  }
  return true;
}

std::vector<int> k_core(const BitGraph& g, std::vector<int> deg, int k) {
  const int n = g.size(), w = g.words();
  std::vector<Word> alive(static_cast<std::size_t>(w), 0);
  std::vector<int> stack;
  for (int v = 0; v < n; ++v) {
    if (deg[static_cast<std::size_t>(v)] < k)
      stack.push_back(v);
    else
      set_bit(alive.data(), v);
  }
  while (!stack.empty()) {
    const int v = stack.back();
    stack.pop_back();
    const Word* r = g.row(v);
    for (int t = 0; t < w; ++t)
      for (Word x = r[t] & alive[static_cast<std::size_t>(t)]; x; x &= x - 1) {
        const int u = t * 64 + __builtin_ctzll(x);
        if (--deg[static_cast<std::size_t>(u)] < k) {
          clear_bit(alive.data(), u);
          stack.push_back(u);
        }
      }
  }
  std::vector<int> keep;
  for_each_bit(alive.data(), w, [&](int v) { keep.push_back(v); });
  return keep;
}

PAGOR_POPCOUNT_CLONES bool colouring_from_clique_proves(const BitGraph& g,
                                                        const std::vector<int>& keep,
                                                        const std::vector<int>& clique) {
  const int size = static_cast<int>(clique.size());
  if (size == 0) return keep.empty();
  const int w = g.words();
  const auto words = static_cast<std::size_t>(w);
  std::vector<Word> core(words, 0);
  for (int v : keep) set_bit(core.data(), v);
  std::vector<Word> left = core, q(words), u(words);
  for (int v : clique) clear_bit(left.data(), v);
  int remaining = count_bits(left.data(), w);
  for (int c = 0; c < size && remaining > 0; ++c) {
    const Word* seed = g.row(clique[static_cast<std::size_t>(c)]);
    for (std::size_t t = 0; t < words; ++t) q[t] = left[t] & ~seed[t];
    remaining -= take_class(g, left.data(), q.data(), 0, w);
  }
  if (remaining == 0) return true;
  if (remaining > kMaxLeftOver) return false;
  // Every clique larger than `clique` holds a vertex left uncoloured (the classes hold one member
  // of it each at most), and lies in that vertex's row. A left vertex v whose neighbours in the
  // core take no more than size - 1 greedy colours is in no such clique, and leaves the core for
  // the next one's check.
  bool proven = true;
  for_each_bit(left.data(), w, [&](int v) {
    if (!proven) return;
    const Word* rv = g.row(v);
    for (std::size_t t = 0; t < words; ++t) u[t] = rv[t] & core[t];
    proven = colour_greedily(g, u.data(), q.data(), w, count_bits(u.data(), w), size - 1) == 0;
    clear_bit(core.data(), v);
  });
  return proven;
}

CoreView::CoreView(const BitGraph& g, const std::vector<int>& keep)
    : g_(g),
      keep_(keep),
      mask_(static_cast<std::size_t>(g.words()), 0),
      local_(static_cast<std::size_t>(g.size()), -1) {
  for (std::size_t i = 0; i < keep.size(); ++i) {
    set_bit(mask_.data(), keep[i]);
    local_[static_cast<std::size_t>(keep[i])] = static_cast<int>(i);
  }
}

PAGOR_POPCOUNT_CLONES CoreDecomposition core_decomposition(const CoreView& g) {
  const int n = g.size(), w = g.words();
  CoreDecomposition d;
  d.core.resize(static_cast<std::size_t>(n));
  d.order.resize(static_cast<std::size_t>(n));
  d.position.resize(static_cast<std::size_t>(n));
  std::vector<Word> alive = g.mask();  // kept vertices not yet removed, as pyramid ids
  for (int v = 0; v < n; ++v)
    d.core[static_cast<std::size_t>(v)] = count_and_inline(g.row(v), alive.data(), w);
  DegreeBuckets buckets(d);
  const int* const core = d.core.data();
  // As on a CSR, but a removed neighbour (whose core number is no higher than v's, so the CSR's
  // loop passes it by) is not visited at all; the others come in the same (increasing) order.
  for (int i = 0; i < n; ++i) {
    const int v = buckets.at(i);
    const int cv = core[v];
    clear_bit(alive.data(), g.id(v));
    const Word* r = g.row(v);
    for (int t = 0; t < w; ++t)
      for (Word x = r[t] & alive[static_cast<std::size_t>(t)]; x; x &= x - 1)
        buckets.lower_above(g.local(t * 64 + __builtin_ctzll(x)), cv);
  }
  for (int c : d.core) d.degeneracy = std::max(d.degeneracy, c);
  return d;
}

}  // namespace pagor::detail
