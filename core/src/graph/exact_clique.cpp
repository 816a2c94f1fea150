// Exact maximum clique: branch and bound on bitsets with greedy-colouring bounds (as in MCQ/MCS
// and San Segundo's BBMC), over subproblems taken in a core-based order (as in PMC).
//
// A clique larger than the best one so far lies in the |best|-core, and its vertex that comes
// first in the degeneracy order has all other members among its later neighbours. So each vertex
// v of that core is one subproblem: v and its later neighbours, pruned to the local core that can
// hold a larger clique, solved exactly on a bit-matrix. The degeneracy bounds each subproblem's
// size, which keeps the bit-matrices small even on large sparse graphs. Before any subproblem, a
// greedy colouring of that core that needs no more colours than |best| proves best maximum.

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <type_traits>
#if defined(__x86_64__)
#include <immintrin.h>
#endif

#include "graph/bit_graph.hpp"
#include "graph/clique_graph.hpp"
#include "graph/dense_level.hpp"
#include "pagor/graph/densest_clique.hpp"

namespace pagor {
namespace {

// The subproblem of v: v's later neighbours in the degeneracy order that could be in a clique
// larger than `best`, pruned to the local (|best| - 1)-core. Returns the clique found (with v),
// or empty. When the budget stops it, `complete` becomes false and `bound` at least the bound on
// cliques through v it reached.
std::vector<int> solve_subproblem(const detail::LevelCsr& g, const detail::CoreDecomposition& cd,
                                  int v, int best, detail::SearchBudget& budget, bool& complete,
                                  int& bound, std::vector<int>& local) {
  std::vector<int> cand;
  const int pv = cd.position[static_cast<std::size_t>(v)];
  for (const int* w = g.begin(v); w != g.end(v); ++w)
    if (cd.position[static_cast<std::size_t>(*w)] > pv &&
        cd.core[static_cast<std::size_t>(*w)] >= best)
      cand.push_back(*w);
  // A clique with v larger than `best` needs `best` of these, each adjacent to best - 1 others.
  for (std::size_t before = 0; before != cand.size() && static_cast<int>(cand.size()) >= best;) {
    before = cand.size();
    for (std::size_t i = 0; i < cand.size(); ++i) local[static_cast<std::size_t>(cand[i])] = 1;
    std::vector<int> kept;
    for (int a : cand) {
      int d = 0;
      for (const int* w = g.begin(a); w != g.end(a); ++w)
        d += local[static_cast<std::size_t>(*w)] == 1;
      if (d >= best - 1) kept.push_back(a);
    }
    for (int a : cand) local[static_cast<std::size_t>(a)] = -1;
    cand.swap(kept);
  }
  if (static_cast<int>(cand.size()) < best) return {};
  // Local order: by core number, highest first (vertices coloured first get the low colours).
  std::stable_sort(cand.begin(), cand.end(), [&](int a, int b) {
    return cd.core[static_cast<std::size_t>(a)] > cd.core[static_cast<std::size_t>(b)];
  });
  const int n = static_cast<int>(cand.size());
  for (int i = 0; i < n; ++i)
    local[static_cast<std::size_t>(cand[static_cast<std::size_t>(i)])] = i;
  // The subproblem as bits (a near-complete one is searched on its sparse complement).
  detail::BitGraph local_graph(n);
  for (int i = 0; i < n; ++i)
    for (const int* w = g.begin(cand[static_cast<std::size_t>(i)]);
         w != g.end(cand[static_cast<std::size_t>(i)]); ++w) {
      const int j = local[static_cast<std::size_t>(*w)];
      if (j > i) local_graph.connect(i, j);
    }
  for (int a : cand) local[static_cast<std::size_t>(a)] = -1;
  bool finished = true;
  int sub_bound = 0;
  const std::vector<int> found =  // with v: larger than best
      detail::max_clique_bits(local_graph, best - 1, budget, finished, sub_bound);
  if (!finished) {
    complete = false;
    bound = std::max(bound, sub_bound + 1);
  }
  if (found.empty()) return {};
  std::vector<int> clique{v};
  for (int i : found) clique.push_back(cand[static_cast<std::size_t>(i)]);
  return clique;
}

// The vertices that could be in a clique larger than some size (those whose core number is at
// least that size: a suffix of the degeneracy order, from position `first` on), as bit rows,
// numbered from the end of the order: local vertex i is the vertex at position n - 1 - i. A
// subproblem's candidates (a vertex's later neighbours) are then a row's lower bits, already in
// the order the colouring wants (highest core first), and its peeling counts neighbours a word at
// a time.
constexpr int kMaxSuffixBits = 1 << 14;  // bit rows up to this many vertices (32 MB)

detail::BitGraph suffix_bits(const detail::LevelCsr& g, const detail::CoreDecomposition& cd,
                             int first) {
  const int n = g.size() - first;
  detail::BitGraph b(n);
  b.ids.resize(static_cast<std::size_t>(n));  // local -> vertex
  const int last = g.size() - 1;
  for (int i = 0; i < n; ++i) {
    const int v = cd.order[static_cast<std::size_t>(last - i)];
    b.ids[static_cast<std::size_t>(i)] = v;
    detail::Word* row = b.row(i);
    g.for_each_neighbor(v, [&](int w) {
      const int j = last - cd.position[static_cast<std::size_t>(w)];
      if (j < n) detail::set_bit(row, j);
    });
  }
  return b;
}

// The same from a view: each row is the level's row masked to the suffix's vertices, whose bits
// are moved to their places (one lookup per neighbour, where the CSR's form takes two and a test).
detail::BitGraph suffix_bits(const detail::CoreView& g, const detail::CoreDecomposition& cd,
                             int first) {
  const int n = g.size() - first, w = g.words();
  detail::BitGraph b(n);
  b.ids.resize(static_cast<std::size_t>(n));                            // local -> vertex
  std::vector<detail::Word> in_suffix(static_cast<std::size_t>(w), 0);  // as pyramid ids
  detail::UninitVector<int> place(static_cast<std::size_t>(w) * 64);    // pyramid id -> local
  const int last = g.size() - 1;
  for (int i = 0; i < n; ++i) {
    const int v = cd.order[static_cast<std::size_t>(last - i)];
    b.ids[static_cast<std::size_t>(i)] = v;
    detail::set_bit(in_suffix.data(), g.id(v));
    place[static_cast<std::size_t>(g.id(v))] = i;
  }
  for (int i = 0; i < n; ++i) {
    const detail::Word* r = g.row(b.ids[static_cast<std::size_t>(i)]);
    detail::Word* row = b.row(i);
    for (int t = 0; t < w; ++t)
      for (detail::Word x = r[t] & in_suffix[static_cast<std::size_t>(t)]; x; x &= x - 1)
        detail::set_bit(row, place[static_cast<std::size_t>(t * 64 + __builtin_ctzll(x))]);
  }
  return b;
}

// Packs the bits of x selected by `mask` into the low bits, in order: BMI2's pext where the CPU
// has it (chosen at run time), else a loop.
#if defined(__x86_64__)
__attribute__((target("bmi2"))) detail::Word pack_bmi2(detail::Word x, detail::Word mask) {
  return _pext_u64(x, mask);
}
#endif
detail::Word pack_portable(detail::Word x, detail::Word mask) {
  detail::Word out = 0;
  int k = 0;
  for (; mask; mask &= mask - 1, ++k)
    if (x & mask & (~mask + 1)) out |= detail::Word(1) << k;
  return out;
}

// The subgraph of `b` induced by the set bits of `c` (words [0, span)), local vertex k being the
// k-th set bit: each row packed word by word.
detail::BitGraph induced(const detail::BitGraph& b, const detail::Word* c, int span, int n) {
#if defined(__x86_64__)
  static const bool bmi2 = __builtin_cpu_supports("bmi2");
  const auto pack = [](detail::Word x, detail::Word mask) {
    return bmi2 ? pack_bmi2(x, mask) : pack_portable(x, mask);
  };
#else
  const auto pack = pack_portable;
#endif
  detail::BitGraph sub(n);
  std::vector<int> offset(static_cast<std::size_t>(span) + 1, 0);
  for (int t = 0; t < span; ++t)
    offset[static_cast<std::size_t>(t) + 1] =
        offset[static_cast<std::size_t>(t)] + __builtin_popcountll(c[t]);
  int k = 0;
  for (int t = 0; t < span; ++t)
    for (detail::Word x = c[t]; x; x &= x - 1, ++k) {
      const detail::Word* ra = b.row(t * 64 + __builtin_ctzll(x));
      detail::Word* out = sub.row(k);
      for (int u = 0; u < span; ++u) {
        if (!c[u]) continue;
        const detail::Word packed = pack(ra[u], c[u]);
        if (!packed) continue;
        const int at = offset[static_cast<std::size_t>(u)];
        out[at >> 6] |= packed << (at & 63);
        if ((at & 63) != 0 && (at >> 6) + 1 < sub.words())
          out[(at >> 6) + 1] |= packed >> (64 - (at & 63));
      }
    }
  return sub;
}

// The subproblem of local vertex i of `b` (as solve_subproblem, on bits): i's later neighbours
// (the lower local ids), peeled to those with at least best - 1 neighbours among them, searched for
// a clique of more than best - 1. Returns the clique with i (local ids), or empty.
PAGOR_POPCOUNT_CLONES std::vector<int> solve_subproblem_bits(const detail::BitGraph& b, int i,
                                                             int best, detail::SearchBudget& budget,
                                                             bool& complete, int& bound,
                                                             std::vector<detail::Word>& C,
                                                             std::vector<detail::Word>& scratch_u,
                                                             std::vector<detail::Word>& scratch_q) {
  using detail::Word;
  if (i < best) return {};      // fewer later vertices than a larger clique needs
  const int span = i / 64 + 1;  // no later vertex beyond word i / 64
  const Word* r = b.row(i);
  Word* c = C.data();
  for (int k = 0; k < span; ++k) c[k] = r[k];
  c[span - 1] &= (Word(1) << (i % 64)) - 1;  // i and earlier vertices out
  int count = detail::count_bits(c, span);
  // A clique with i larger than `best` needs `best` of these, each adjacent to best - 1 others.
  // Done as soon as too few are left.
  for (bool changed = true; changed && count >= best;) {
    changed = false;
    for (int k = 0; k < span; ++k)
      for (Word x = c[k]; x; x &= x - 1) {
        const int a = k * 64 + __builtin_ctzll(x);
        if (detail::count_and_inline(b.row(a), c, span) < best - 1) {
          detail::clear_bit(c, a);
          if (--count < best) return {};
          changed = true;
        }
      }
  }
  if (count < best) return {};
  // A greedy colouring of the survivors with best - 1 colours proves that no best of them are
  // pairwise adjacent; most subproblems end here, before their graph is extracted.
  // (U and Q are scratch: this runs once per subproblem, and allocating them was a twentieth of
  // the clique step.)
  std::copy(c, c + span, scratch_u.data());
  if (detail::colour_greedily(b, scratch_u.data(), scratch_q.data(), span, count, best - 1) == 0)
    return {};
  // The survivors as a small bit graph, in local order: highest core first, so that the vertices
  // coloured first get the low colours.
  std::vector<int> cand;
  cand.reserve(static_cast<std::size_t>(count));
  detail::for_each_bit(c, span, [&](int a) { cand.push_back(a); });
  const detail::BitGraph sub = induced(b, c, span, count);
  bool finished = true;
  int sub_bound = 0;
  const std::vector<int> found =
      detail::max_clique_bits(sub, best - 1, budget, finished, sub_bound);
  if (!finished) {
    complete = false;
    bound = std::max(bound, sub_bound + 1);
  }
  if (found.empty()) return {};
  std::vector<int> clique{i};
  for (int k : found) clique.push_back(cand[static_cast<std::size_t>(k)]);
  return clique;
}

// Whether a greedy colouring of the vertices that could be in a clique larger than `size` (core
// number at least `size`), taken from the end of the degeneracy order, needs no more than `size`
// colours: then every clique among them has at most `size` vertices, and none is larger.
template <typename Graph>
bool colouring_proves(const Graph& g, const detail::CoreDecomposition& cd, int size) {
  const int n = g.size();
  std::vector<int> colour(static_cast<std::size_t>(n), -1),
      taken_by(static_cast<std::size_t>(n) + 1, -1);
  for (int i = n - 1; i >= 0; --i) {
    const int v = cd.order[static_cast<std::size_t>(i)];
    if (cd.core[static_cast<std::size_t>(v)] < size) continue;
    g.for_each_neighbor(v, [&](int w) {
      if (colour[static_cast<std::size_t>(w)] >= 0)
        taken_by[static_cast<std::size_t>(colour[static_cast<std::size_t>(w)])] = v;
    });
    int c = 0;
    while (taken_by[static_cast<std::size_t>(c)] == v) ++c;
    if (c >= size) return false;  // a colour beyond `size`
    colour[static_cast<std::size_t>(v)] = c;
  }
  return true;
}

// The exact search from the clique `best`: one subproblem per vertex that could be in a larger
// one, from the end of the degeneracy order (the densest part first, where large cliques are).
// When the budget runs out, `proven` is false and `bound` an upper bound on the clique number:
// the largest bound of an interrupted subproblem or core number + 1 of a vertex not searched.
// Graph: a detail::LevelCsr, or a detail::CoreView (at most kMaxLevelBits vertices: always on
// bits).
template <typename Graph>
std::vector<int> search_from(const Graph& csr, const detail::CoreDecomposition& cd,
                             std::vector<int> best, detail::SearchBudget& budget, bool& proven,
                             int& bound) {
  proven = true;
  bound = 0;
  constexpr bool view = !std::is_same_v<Graph, detail::LevelCsr>;
  const auto maximum = [&] {
    std::sort(best.begin(), best.end());
    bound = static_cast<int>(best.size());
    return std::move(best);
  };
  // On a CSR, the colouring's proof comes first: a sparse level's suffix may be large, and is
  // built only when the proof fails.
  if constexpr (!view)
    if (!best.empty() && colouring_proves(csr, cd, static_cast<int>(best.size()))) return maximum();
  int i = csr.size() - 1;
  // Cores grow along the degeneracy order: the vertices that could be in a larger clique are a
  // suffix of it, searched on bit rows when it is not too large.
  int first = 0;
  while (first < csr.size() &&
         cd.core[static_cast<std::size_t>(cd.order[static_cast<std::size_t>(first)])] <
             static_cast<int>(best.size()))
    ++first;
  static_assert(detail::kMaxLevelBits <= kMaxSuffixBits, "a CoreView's suffix fits in bits");
  if (view || csr.size() - first <= kMaxSuffixBits) {
    const detail::BitGraph s = suffix_bits(csr, cd, first);
    std::vector<detail::Word> C(static_cast<std::size_t>(s.words())), U(C.size()), Q(C.size());
    if (view && !best.empty()) {
      // On a view, the same colouring on the suffix's rows (a colour class at a time, a word per
      // neighbour set, where colouring_proves visits every neighbour through its view).
      for (int k = 0; k < s.size(); ++k) detail::set_bit(U.data(), k);  // U starts empty
      if (detail::colour_greedily(s, U.data(), Q.data(), s.words(), s.size(),
                                  static_cast<int>(best.size())) == 0)
        return maximum();
    }
    for (; i >= first && !budget.exhausted() && ((i & 15) != 0 || budget.in_time()); --i) {
      const int size = static_cast<int>(best.size());
      if (cd.core[static_cast<std::size_t>(cd.order[static_cast<std::size_t>(i)])] < size) {
        i = first - 1;  // every earlier vertex has a core number this low too
        break;
      }
      std::vector<int> c =
          solve_subproblem_bits(s, csr.size() - 1 - i, size, budget, proven, bound, C, U, Q);
      if (c.size() > best.size()) {
        best.clear();
        for (int k : c) best.push_back(s.ids[static_cast<std::size_t>(k)]);
      }
    }
  } else if constexpr (std::is_same_v<Graph, detail::LevelCsr>) {
    std::vector<int> local(static_cast<std::size_t>(csr.size()), -1);
    for (; i >= 0 && !budget.exhausted(); --i) {
      const int v = cd.order[static_cast<std::size_t>(i)];
      const int size = static_cast<int>(best.size());
      if (cd.core[static_cast<std::size_t>(v)] < size) continue;  // in no clique larger than best
      std::vector<int> c = solve_subproblem(csr, cd, v, size, budget, proven, bound, local);
      if (c.size() > best.size()) best = std::move(c);
    }
  }
  for (; i >= 0; --i) {  // not searched: a clique through v has at most core(v) + 1 vertices
    const int c = cd.core[static_cast<std::size_t>(cd.order[static_cast<std::size_t>(i)])];
    if (c >= static_cast<int>(best.size())) {
      proven = false;
      bound = std::max(bound, c + 1);
    }
  }
  bound = std::max(bound, static_cast<int>(best.size()));
  std::sort(best.begin(), best.end());
  return best;
}

}  // namespace

std::vector<int> detail::larger_clique(const PyramidGraph& g, int level, std::vector<int> best,
                                       long max_nodes, bool& proven, int* bound, Deadline deadline,
                                       bool* out_of_time) {
  // Every member of a larger clique has at least |best| neighbours in the |best|-core: the search
  // runs on that core alone (often empty on the sparse levels, which proves best maximum at once;
  // always empty on a graph without vertices).
  const detail::PyramidLevel view{g, level};
  const std::vector<int> keep =
      detail::k_core(view, detail::level_degrees(g, level), static_cast<int>(best.size()),
                     [&](int v) { return view.row_length(v); });
  return larger_clique_in(keep.empty() ? detail::LevelCsr{} : detail::level_csr(g, level, keep),
                          keep, std::move(best), max_nodes, proven, bound, deadline, out_of_time);
}

namespace {

// larger_clique_in's search, on either form of the core (`ids`: local -> pyramid id).
template <typename Graph, typename Ids>
std::vector<int> search_core(const Graph& core, Ids ids, std::vector<int> best, long max_nodes,
                             bool& proven, int* bound, Deadline deadline, bool* out_of_time) {
  proven = true;
  if (bound) *bound = static_cast<int>(best.size());
  std::sort(best.begin(), best.end());
  if (core.size() == 0) return best;
  detail::SearchBudget budget;
  budget.max_nodes = max_nodes > 0 ? max_nodes : -1;
  if (max_nodes <= 0) budget.out_of_nodes = true;  // no search: only the colouring's proof
  budget.deadline = deadline;
  int reached = 0;
  // search_from only reads best's size; what it returns is best itself or a larger clique in the
  // core's local ids.
  std::vector<int> found =
      search_from(core, detail::core_decomposition(core), best, budget, proven, reached);
  if (bound) *bound = reached;
  if (out_of_time) *out_of_time = budget.out_of_time;
  if (found.size() <= best.size()) return best;
  for (int& v : found) v = ids(v);
  std::sort(found.begin(), found.end());
  return found;
}

}  // namespace

std::vector<int> detail::larger_clique_in(const LevelCsr& csr, const std::vector<int>& keep,
                                          std::vector<int> best, long max_nodes, bool& proven,
                                          int* bound, Deadline deadline, bool* out_of_time) {
  return search_core(
      csr, [&](int v) { return keep[static_cast<std::size_t>(v)]; }, std::move(best), max_nodes,
      proven, bound, deadline, out_of_time);
}

std::vector<int> detail::larger_clique_in(const CoreView& core, std::vector<int> best,
                                          long max_nodes, bool& proven, int* bound,
                                          Deadline deadline, bool* out_of_time) {
  return search_core(
      core, [&](int v) { return core.id(v); }, std::move(best), max_nodes, proven, bound, deadline,
      out_of_time);
}

CliqueResult detail::exact_level(const PyramidGraph& g, int level, const CliqueParams& p,
                                 SearchBudget& budget, const std::vector<int>& seed) {
  const auto t0 = std::chrono::steady_clock::now();
  CliqueResult r;
  r.level = level;
  r.proven = true;
  if (g.vertices > 0) {
    const detail::LevelCsr csr = detail::level_csr(g, level);
    const detail::CoreDecomposition cd = detail::core_decomposition(csr);
    detail::Marks marks(g.vertices);
    std::vector<int> start = detail::greedy_clique(csr, cd.core, p.greedy_starts * 8, marks);
    if (seed.size() > start.size() && detail::is_clique(csr, seed, marks)) start = seed;
    r.vertices = search_from(csr, cd, std::move(start), budget, r.proven, r.clique_number_bound);
  }
  r.budget = r.proven             ? CliqueBudget::none
             : budget.out_of_time ? CliqueBudget::time
                                  : CliqueBudget::nodes;
  r.time_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

CliqueResult exact_max_clique(const PyramidGraph& g, int level, const CliqueParams& p) {
  detail::SearchBudget budget;
  budget.max_nodes = p.exact_max_nodes;
  if (p.exact_time_budget_ms > 0)
    budget.deadline = detail::SearchBudget::Clock::now() +
                      std::chrono::microseconds(static_cast<long>(p.exact_time_budget_ms * 1000));
  return detail::exact_level(g, level, p, budget);
}

}  // namespace pagor
