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

#include "graph/clique_graph.hpp"
#include "pagor/graph/densest_clique.hpp"

namespace pagor {
namespace {

using Word = std::uint64_t;

// Subproblems of at least this many vertices and this edge density are solved as maximum
// independent set on the complement.
constexpr int kDenseMinSize = 32;
constexpr double kDenseFraction = 0.9;

int words_for(int n) {
  return (n + 63) / 64;
}

// A local graph of n vertices as rows of bits (row v: the neighbours of v).
class BitRows {
 public:
  explicit BitRows(int n)
      : n_(n),
        w_(words_for(n)),
        bits_(static_cast<std::size_t>(n) * static_cast<std::size_t>(w_), 0) {}
  void connect(int a, int b) {
    row(a)[b >> 6] |= Word(1) << (b & 63);
    row(b)[a >> 6] |= Word(1) << (a & 63);
  }
  Word* row(int v) {
    return bits_.data() + static_cast<std::size_t>(v) * static_cast<std::size_t>(w_);
  }
  int size() const { return n_; }
  int words() const { return w_; }
  // Every vertex, as a row of bits.
  std::vector<Word> all() const {
    std::vector<Word> out(static_cast<std::size_t>(w_), 0);
    for (int v = 0; v < n_; ++v) out[static_cast<std::size_t>(v >> 6)] |= Word(1) << (v & 63);
    return out;
  }

 private:
  int n_, w_;
  std::vector<Word> bits_;
};

// One subproblem: a local graph as rows of bits, searched by colouring bounds.
class BitSearch {
 public:
  BitSearch(BitRows& g, long budget, long& nodes)
      : n_(g.size()), w_(g.words()), g_(g), budget_(budget), nodes_(nodes) {}
  // Largest clique of the local graph if it has more than `lower` vertices; else empty.
  // Sets `complete` false when the node budget ran out.
  std::vector<int> solve(int lower, bool& complete) {
    best_size_ = lower;
    best_.clear();
    current_.clear();
    const std::vector<Word> all = g_.all();
    levels_.assign(static_cast<std::size_t>(n_) + 2, {});
    expand(all, 0);
    complete = complete && nodes_ <= budget_;
    return best_;
  }

 private:
  Word* row(int v) { return g_.row(v); }

  struct Level {
    std::vector<Word> P, U, Q;
    std::vector<int> order, colour;
  };

  // Candidates P (by value in levels_[depth]); current_ is the clique so far.
  void expand(const std::vector<Word>& P_in, int depth) {
    if (++nodes_ > budget_) return;
    Level& L = levels_[static_cast<std::size_t>(depth)];
    L.P = P_in;
    L.U = P_in;
    L.order.clear();
    L.colour.clear();
    // Greedy colouring in vertex order; only colours that could beat the best are branched on.
    const int need = best_size_ - static_cast<int>(current_.size());  // colours needed to beat
    int k = 0;
    for (bool any = true; any;) {
      any = false;
      ++k;
      L.Q = L.U;
      for (int i = 0; i < w_; ++i) {
        while (L.Q[static_cast<std::size_t>(i)]) {
          const int v = i * 64 + __builtin_ctzll(L.Q[static_cast<std::size_t>(i)]);
          any = true;
          L.U[static_cast<std::size_t>(i)] &= ~(Word(1) << (v & 63));
          const Word* nv = row(v);
          for (int j = i; j < w_; ++j) L.Q[static_cast<std::size_t>(j)] &= ~nv[j];
          L.Q[static_cast<std::size_t>(i)] &= ~(Word(1) << (v & 63));
          if (k > need) {
            L.order.push_back(v);
            L.colour.push_back(k);
          }
        }
      }
    }
    std::vector<Word> next(static_cast<std::size_t>(w_));
    for (int idx = static_cast<int>(L.order.size()) - 1; idx >= 0; --idx) {
      if (static_cast<int>(current_.size()) + L.colour[static_cast<std::size_t>(idx)] <= best_size_)
        return;
      const int v = L.order[static_cast<std::size_t>(idx)];
      const Word* nv = row(v);
      bool empty = true;
      for (int j = 0; j < w_; ++j) {
        next[static_cast<std::size_t>(j)] = L.P[static_cast<std::size_t>(j)] & nv[j];
        empty = empty && next[static_cast<std::size_t>(j)] == 0;
      }
      current_.push_back(v);
      if (empty) {
        if (static_cast<int>(current_.size()) > best_size_) {
          best_size_ = static_cast<int>(current_.size());
          best_ = current_;
        }
      } else {
        expand(next, depth + 1);
      }
      current_.pop_back();
      if (nodes_ > budget_) return;
      L.P[static_cast<std::size_t>(v >> 6)] &= ~(Word(1) << (v & 63));
    }
  }

  int n_, w_;
  BitRows& g_;
  long budget_;
  long& nodes_;
  int best_size_ = 0;
  std::vector<int> best_, current_;
  std::vector<Level> levels_;
};

// Maximum independent set on bit rows, for the complement of a near-complete subproblem (a clique
// of the subproblem is an independent set of its sparse complement). Vertices without neighbours
// are taken, a vertex with one neighbour is taken and its neighbour dropped; the bound is the
// remaining count minus a greedy matching (each matched edge keeps at most one end); branching
// takes or drops a vertex of largest degree.
class MisSearch {
 public:
  MisSearch(BitRows& g, long budget, long& nodes)
      : n_(g.size()), w_(g.words()), g_(g), budget_(budget), nodes_(nodes) {}
  // Largest independent set if it has more than `lower` vertices; else empty.
  std::vector<int> solve(int lower, bool& complete) {
    best_size_ = lower;
    const std::vector<Word> all = g_.all();
    search(all);
    complete = complete && nodes_ <= budget_;
    return best_;
  }

 private:
  Word* row(int v) { return g_.row(v); }
  int degree(int v, const std::vector<Word>& P) {
    const Word* r = row(v);
    int d = 0;
    for (int i = 0; i < w_; ++i) d += __builtin_popcountll(r[i] & P[static_cast<std::size_t>(i)]);
    return d;
  }
  static void drop(std::vector<Word>& P, int v) {
    P[static_cast<std::size_t>(v >> 6)] &= ~(Word(1) << (v & 63));
  }
  static bool has(const std::vector<Word>& P, int v) {
    return (P[static_cast<std::size_t>(v >> 6)] >> (v & 63)) & 1;
  }
  template <typename F>
  void for_each(const std::vector<Word>& P, F&& f) {
    for (int i = 0; i < w_; ++i)
      for (Word x = P[static_cast<std::size_t>(i)]; x; x &= x - 1) f(i * 64 + __builtin_ctzll(x));
  }
  int first_neighbour(int v, const std::vector<Word>& P) {
    const Word* r = row(v);
    for (int i = 0; i < w_; ++i)
      if (const Word x = r[i] & P[static_cast<std::size_t>(i)]) return i * 64 + __builtin_ctzll(x);
    return -1;
  }

  void search(std::vector<Word> P) {
    if (++nodes_ > budget_) return;
    const std::size_t mark = current_.size();
    for (bool changed = true; changed;) {  // degree-0 and degree-1 reductions
      changed = false;
      for_each(P, [&](int v) {
        if (!has(P, v)) return;
        const int d = degree(v, P);
        if (d > 1) return;
        if (d == 1) drop(P, first_neighbour(v, P));
        drop(P, v);
        current_.push_back(v);
        changed = true;
      });
    }
    int remaining = 0, matched = 0, pick = -1, pick_degree = -1;
    std::vector<Word> Q = P;
    for_each(P, [&](int v) {
      ++remaining;
      const int d = degree(v, P);
      if (d > pick_degree) {
        pick_degree = d;
        pick = v;
      }
      if (!has(Q, v)) return;
      drop(Q, v);
      const int u = first_neighbour(v, Q);
      if (u >= 0) {
        drop(Q, u);
        ++matched;
      }
    });
    const int size = static_cast<int>(current_.size());
    if (remaining == 0) {
      if (size > best_size_) {
        best_size_ = size;
        best_ = current_;
      }
    } else if (size + remaining - matched > best_size_) {
      std::vector<Word> without = P;
      drop(without, pick);
      // Take `pick`: its neighbours go.
      const Word* r = row(pick);
      for (int i = 0; i < w_; ++i) P[static_cast<std::size_t>(i)] &= ~r[i];
      drop(P, pick);
      current_.push_back(pick);
      search(std::move(P));
      current_.pop_back();
      if (nodes_ <= budget_) search(std::move(without));
    }
    current_.resize(mark);
  }

  int n_, w_;
  BitRows& g_;
  long budget_;
  long& nodes_;
  int best_size_ = 0;
  std::vector<int> best_, current_;
};

// The subproblem of v: v's later neighbours in the degeneracy order that could be in a clique
// larger than `best`, pruned to the local (|best| - 1)-core. Returns the clique found (with v),
// or empty.
std::vector<int> solve_subproblem(const detail::LevelCsr& g, const detail::CoreDecomposition& cd,
                                  int v, int best, long budget, long& nodes, bool& complete,
                                  std::vector<int>& local) {
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
  // Local edges; a near-complete subproblem is solved on its sparse complement.
  std::size_t edges = 0;
  for (int i = 0; i < n; ++i)
    for (const int* w = g.begin(cand[static_cast<std::size_t>(i)]);
         w != g.end(cand[static_cast<std::size_t>(i)]); ++w)
      edges += local[static_cast<std::size_t>(*w)] > i;
  const bool dense = n >= kDenseMinSize && edges >= kDenseFraction * 0.5 * n * (n - 1.0);
  std::vector<int> found;
  if (dense) {
    BitRows complement(n);
    std::vector<char> row(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
      std::fill(row.begin(), row.end(), 0);
      for (const int* w = g.begin(cand[static_cast<std::size_t>(i)]);
           w != g.end(cand[static_cast<std::size_t>(i)]); ++w) {
        const int j = local[static_cast<std::size_t>(*w)];
        if (j >= 0) row[static_cast<std::size_t>(j)] = 1;
      }
      for (int j = i + 1; j < n; ++j)
        if (!row[static_cast<std::size_t>(j)]) complement.connect(i, j);
    }
    for (int a : cand) local[static_cast<std::size_t>(a)] = -1;
    found = MisSearch(complement, budget, nodes).solve(best - 1, complete);  // with v: > best
  } else {
    BitRows local_graph(n);
    for (int i = 0; i < n; ++i)
      for (const int* w = g.begin(cand[static_cast<std::size_t>(i)]);
           w != g.end(cand[static_cast<std::size_t>(i)]); ++w) {
        const int j = local[static_cast<std::size_t>(*w)];
        if (j > i) local_graph.connect(i, j);
      }
    for (int a : cand) local[static_cast<std::size_t>(a)] = -1;
    found = BitSearch(local_graph, budget, nodes).solve(best - 1, complete);  // with v: > best
  }
  if (found.empty()) return {};
  std::vector<int> clique{v};
  for (int i : found) clique.push_back(cand[static_cast<std::size_t>(i)]);
  return clique;
}

// Whether a greedy colouring of the vertices that could be in a clique larger than `size` (core
// number at least `size`), taken from the end of the degeneracy order, needs no more than `size`
// colours: then every clique among them has at most `size` vertices, and none is larger.
bool colouring_proves(const detail::LevelCsr& g, const detail::CoreDecomposition& cd, int size) {
  const int n = g.size();
  std::vector<int> colour(static_cast<std::size_t>(n), -1),
      taken_by(static_cast<std::size_t>(n) + 1, -1);
  for (int i = n - 1; i >= 0; --i) {
    const int v = cd.order[static_cast<std::size_t>(i)];
    if (cd.core[static_cast<std::size_t>(v)] < size) continue;
    for (const int* w = g.begin(v); w != g.end(v); ++w)
      if (colour[static_cast<std::size_t>(*w)] >= 0)
        taken_by[static_cast<std::size_t>(colour[static_cast<std::size_t>(*w)])] = v;
    int c = 0;
    while (taken_by[static_cast<std::size_t>(c)] == v) ++c;
    if (c >= size) return false;  // a colour beyond `size`
    colour[static_cast<std::size_t>(v)] = c;
  }
  return true;
}

// The exact search from the clique `best`: one subproblem per vertex that could be in a larger
// one, from the end of the degeneracy order (the densest part first, where large cliques are).
std::vector<int> search_from(const detail::LevelCsr& csr, const detail::CoreDecomposition& cd,
                             std::vector<int> best, long max_nodes, bool& optimal) {
  optimal = true;
  if (!best.empty() && colouring_proves(csr, cd, static_cast<int>(best.size()))) {
    std::sort(best.begin(), best.end());
    return best;
  }
  std::vector<int> local(static_cast<std::size_t>(csr.size()), -1);
  long nodes = 0;
  for (int i = csr.size() - 1; i >= 0 && optimal; --i) {
    const int v = cd.order[static_cast<std::size_t>(i)];
    const int size = static_cast<int>(best.size());
    if (cd.core[static_cast<std::size_t>(v)] < size) continue;  // in no clique larger than best
    std::vector<int> c = solve_subproblem(csr, cd, v, size, max_nodes, nodes, optimal, local);
    if (c.size() > best.size()) best = std::move(c);
  }
  std::sort(best.begin(), best.end());
  return best;
}

}  // namespace

std::vector<int> detail::larger_clique(const PyramidGraph& g, int level, std::vector<int> best,
                                       long max_nodes, bool& optimal) {
  optimal = true;
  if (g.vertices == 0) return best;
  const detail::LevelCsr csr = detail::level_csr(g, level);
  return search_from(csr, detail::core_decomposition(csr), std::move(best), max_nodes, optimal);
}

CliqueResult exact_max_clique(const PyramidGraph& g, int level, const CliqueParams& p) {
  const auto t0 = std::chrono::steady_clock::now();
  CliqueResult r;
  r.level = level;
  r.optimal = true;
  if (g.vertices > 0) {
    const detail::LevelCsr csr = detail::level_csr(g, level);
    const detail::CoreDecomposition cd = detail::core_decomposition(csr);
    detail::Marks marks(g.vertices);
    r.vertices = search_from(csr, cd, detail::greedy_clique(csr, cd.core, 32, marks),
                             p.exact_max_nodes, r.optimal);
  }
  r.time_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace pagor
