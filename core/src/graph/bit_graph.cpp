// Bit rows, their induced subgraphs, and the exact search on them: MCQ/BBMC-style branch and bound
// with greedy-colouring bounds, or a maximum independent set of the complement for near-complete
// graphs (where colouring bounds cannot prove anything).

#include "graph/bit_graph.hpp"

#include <algorithm>

namespace pagor::detail {

PAGOR_POPCOUNT_CLONES int count_and(const Word* a, const Word* b, int words) {
  int n = 0;
  for (int i = 0; i < words; ++i) n += __builtin_popcountll(a[i] & b[i]);
  return n;
}

PAGOR_POPCOUNT_CLONES int count_bits(const Word* a, int words) {
  int n = 0;
  for (int i = 0; i < words; ++i) n += __builtin_popcountll(a[i]);
  return n;
}

std::vector<Word> BitGraph::all() const {
  std::vector<Word> out(static_cast<std::size_t>(w_), 0);
  for (int v = 0; v < n_; ++v) set_bit(out.data(), v);
  return out;
}

BitGraph induce_bits(const PyramidGraph& g, int level, const std::vector<int>& vertices,
                     std::vector<int>& local) {
  BitGraph b(static_cast<int>(vertices.size()));
  b.ids = vertices;
  for (std::size_t i = 0; i < vertices.size(); ++i)
    local[static_cast<std::size_t>(vertices[i])] = static_cast<int>(i);
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const auto v = static_cast<std::size_t>(vertices[i]);
    Word* row = b.row(static_cast<int>(i));
    const auto last = static_cast<std::size_t>(g.offsets[v + 1]);
    for (auto e = static_cast<std::size_t>(g.offsets[v]); e < last; ++e) {
      if (g.level[e] > level) continue;
      const int j = local[static_cast<std::size_t>(g.neighbors[e])];
      if (j >= 0) set_bit(row, j);
    }
  }
  for (int v : vertices) local[static_cast<std::size_t>(v)] = -1;
  return b;
}

namespace {

// Branch and bound on bits: greedy colouring of the candidates in vertex order, branching from the
// highest colour down, only on colours that could beat the best (MCQ with BBMC's bit sets).
class ColourSearch {
 public:
  ColourSearch(const BitGraph& g, SearchBudget& budget) : g_(g), w_(g.words()), budget_(budget) {}
  std::vector<int> solve(int lower, bool& complete, int& upper_bound) {
    best_size_ = lower;
    root_colours_ = g_.size();  // until the root is coloured: every vertex
    levels_.assign(static_cast<std::size_t>(g_.size()) + 2, {});
    expand(g_.all(), 0);
    complete = !budget_.exhausted();
    upper_bound = complete ? std::max(lower, static_cast<int>(best_.size()))
                           : std::max(root_colours_, static_cast<int>(best_.size()));
    return best_;
  }

 private:
  struct Level {
    std::vector<Word> P, U, Q;
    std::vector<int> order, colour;
  };

  // Colours the candidates P greedily into L; keeps those of colour > need (with their colour).
  int colour(Level& L, int need) {
    int k = 0;
    for (bool any = true; any;) {
      any = false;
      ++k;
      L.Q = L.U;
      for (int i = 0; i < w_; ++i) {
        while (L.Q[static_cast<std::size_t>(i)]) {
          const int v = i * 64 + __builtin_ctzll(L.Q[static_cast<std::size_t>(i)]);
          any = true;
          clear_bit(L.U.data(), v);
          const Word* nv = g_.row(v);
          for (int j = i; j < w_; ++j) L.Q[static_cast<std::size_t>(j)] &= ~nv[j];
          clear_bit(L.Q.data(), v);
          if (k > need) {
            L.order.push_back(v);
            L.colour.push_back(k);
          }
        }
      }
    }
    return k - 1;
  }

  void expand(const std::vector<Word>& P_in, int depth) {
    if (!budget_.spend()) return;
    Level& L = levels_[static_cast<std::size_t>(depth)];
    L.P = P_in;
    L.U = P_in;
    L.order.clear();
    L.colour.clear();
    const int colours = colour(L, best_size_ - static_cast<int>(current_.size()));
    if (depth == 0) root_colours_ = colours;
    std::vector<Word> next(static_cast<std::size_t>(w_));
    for (int idx = static_cast<int>(L.order.size()) - 1; idx >= 0; --idx) {
      if (static_cast<int>(current_.size()) + L.colour[static_cast<std::size_t>(idx)] <= best_size_)
        return;
      const int v = L.order[static_cast<std::size_t>(idx)];
      const Word* nv = g_.row(v);
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
      if (budget_.exhausted()) return;
      clear_bit(L.P.data(), v);
    }
  }

  const BitGraph& g_;
  int w_;
  SearchBudget& budget_;
  int best_size_ = 0, root_colours_ = 0;
  std::vector<int> best_, current_;
  std::vector<Level> levels_;
};

// Maximum independent set on bit rows (the complement of a near-complete graph). Reductions:
// a vertex without neighbours is taken; a vertex with one neighbour is taken and its neighbour
// dropped; a vertex whose closed neighbourhood contains another's is dropped (domination: an
// independent set through it can swap it for the other). The bound is the count taken plus the
// cliques of a greedy clique cover (an independent set keeps at most one vertex of each);
// branching takes or drops a vertex of largest degree.
class IndependentSearch {
 public:
  IndependentSearch(const BitGraph& g, SearchBudget& budget)
      : g_(g), w_(g.words()), budget_(budget) {}
  std::vector<int> solve(int lower, bool& complete, int& upper_bound) {
    best_size_ = lower;
    root_bound_ = g_.size();  // until the root's bound is computed: every vertex
    search(g_.all(), true);
    complete = !budget_.exhausted();
    upper_bound = complete ? std::max(lower, static_cast<int>(best_.size()))
                           : std::max(root_bound_, static_cast<int>(best_.size()));
    return best_;
  }

 private:
  int degree(int v, const std::vector<Word>& P) {
    words_ += w_;
    return count_and(g_.row(v), P.data(), w_);
  }
  int first_neighbour(int v, const std::vector<Word>& P) const {
    const Word* r = g_.row(v);
    for (int i = 0; i < w_; ++i)
      if (const Word x = r[i] & P[static_cast<std::size_t>(i)]) return i * 64 + __builtin_ctzll(x);
    return -1;
  }
  // Whether N[v] is inside N[u] within P (u a neighbour of v).
  bool inside(int v, int u, const std::vector<Word>& P) {
    words_ += w_;
    const Word *rv = g_.row(v), *ru = g_.row(u);
    for (int i = 0; i < w_; ++i) {
      Word nv = rv[i] & P[static_cast<std::size_t>(i)], nu = ru[i] & P[static_cast<std::size_t>(i)];
      if (i == (u >> 6)) nv &= ~(Word(1) << (u & 63));  // u is in N[u]
      if (i == (v >> 6)) nu |= Word(1) << (v & 63);     // v is in N(u)
      if (nv & ~nu) return false;
    }
    return true;
  }

  // Degree-0, degree-1 and domination reductions; taken vertices go to current_.
  void reduce(std::vector<Word>& P) {
    for (bool changed = true; changed;) {
      changed = false;
      for_each_bit(std::vector<Word>(P).data(), w_, [&](int v) {
        if (!test_bit(P.data(), v)) return;
        const int d = degree(v, P);
        if (d > 1) {
          // Neighbours u with N[v] inside N[u] are dominated by v.
          const Word* r = g_.row(v);
          for (int i = 0; i < w_; ++i)
            for (Word x = r[i] & P[static_cast<std::size_t>(i)]; x; x &= x - 1) {
              const int u = i * 64 + __builtin_ctzll(x);
              if (inside(v, u, P)) {
                clear_bit(P.data(), u);
                changed = true;
              }
            }
          return;
        }
        if (d == 1) clear_bit(P.data(), first_neighbour(v, P));
        clear_bit(P.data(), v);
        current_.push_back(v);
        changed = true;
      });
    }
  }

  void search(std::vector<Word> P, bool root) {
    if (!budget_.spend()) return;
    const std::size_t mark = current_.size();
    // The reductions' work beyond one pass over P's rows counts as further nodes: on a subproblem
    // of hundreds of vertices they repeat until nothing changes, and a node cost 13 times a
    // colouring node (gen-16 of bench/peer), so that the node budget did not bound the time.
    const long pass = (count_bits(P.data(), w_) + 1L) * w_;
    words_ = 0;
    reduce(P);
    // Charged now, acted on after the node's bound (the root's is the search's upper bound) and
    // any solution the reductions completed are recorded.
    const bool spent = words_ > pass && !budget_.spend(words_ / pass - 1);
    int remaining = 0, cliques = 0, pick = -1, pick_degree = -1;
    std::vector<Word> Q = P, K(static_cast<std::size_t>(w_));
    for_each_bit(P.data(), w_, [&](int v) {
      ++remaining;
      const int d = degree(v, P);
      if (d > pick_degree) pick_degree = d, pick = v;
      if (!test_bit(Q.data(), v)) return;
      // A clique of the cover: v and, greedily, uncovered vertices adjacent to all its members.
      ++cliques;
      clear_bit(Q.data(), v);
      const Word* r = g_.row(v);
      bool any = false;
      for (int i = 0; i < w_; ++i) {
        K[static_cast<std::size_t>(i)] = r[i] & Q[static_cast<std::size_t>(i)];
        any = any || K[static_cast<std::size_t>(i)];
      }
      while (any) {
        const int u = first_neighbour(v, K);  // any member of K
        const Word* ru = g_.row(u);
        clear_bit(Q.data(), u);
        any = false;
        for (int i = 0; i < w_; ++i) {
          K[static_cast<std::size_t>(i)] &= ru[i];
          any = any || K[static_cast<std::size_t>(i)];
        }
      }
    });
    const int size = static_cast<int>(current_.size());
    if (root) root_bound_ = size + cliques;
    if (remaining == 0) {
      if (size > best_size_) best_size_ = size, best_ = current_;
    } else if (!spent && size + cliques > best_size_) {
      std::vector<Word> without = P;
      clear_bit(without.data(), pick);
      const Word* r = g_.row(pick);  // take `pick`: its neighbours go
      for (int i = 0; i < w_; ++i) P[static_cast<std::size_t>(i)] &= ~r[i];
      clear_bit(P.data(), pick);
      current_.push_back(pick);
      search(std::move(P), false);
      current_.pop_back();
      if (!budget_.exhausted()) search(std::move(without), false);
    }
    current_.resize(mark);
  }

  const BitGraph& g_;
  int w_;
  SearchBudget& budget_;
  int best_size_ = 0, root_bound_ = 0;
  long words_ = 0;  // word operations of the node's reductions
  std::vector<int> best_, current_;
};

constexpr int kDenseMinSize = 32;       // complement search from this many vertices
constexpr double kDenseFraction = 0.9;  // and this edge density

}  // namespace

std::vector<int> max_clique_bits(const BitGraph& g, int lower, SearchBudget& budget, bool& complete,
                                 int& upper_bound) {
  const int n = g.size();
  std::size_t edges = 0;
  for (int v = 0; v < n; ++v) edges += static_cast<std::size_t>(g.degree(v));
  edges /= 2;
  if (n >= kDenseMinSize && edges >= kDenseFraction * 0.5 * n * (n - 1.0)) {
    BitGraph complement(n);
    const std::vector<Word> all = g.all();
    for (int a = 0; a < n; ++a) {
      const Word* r = g.row(a);
      Word* c = complement.row(a);
      for (int i = 0; i < g.words(); ++i) c[i] = ~r[i] & all[static_cast<std::size_t>(i)];
      clear_bit(c, a);
    }
    std::vector<int> c = IndependentSearch(complement, budget).solve(lower, complete, upper_bound);
    std::sort(c.begin(), c.end());
    return c;
  }
  std::vector<int> c = ColourSearch(g, budget).solve(lower, complete, upper_bound);
  std::sort(c.begin(), c.end());
  return c;
}

std::vector<int> greedy_clique_bits(const BitGraph& g, int starts) {
  const int n = g.size(), w = g.words();
  std::vector<int> order(static_cast<std::size_t>(n)), degree(static_cast<std::size_t>(n));
  for (int v = 0; v < n; ++v) {
    order[static_cast<std::size_t>(v)] = v;
    degree[static_cast<std::size_t>(v)] = g.degree(v);
  }
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return degree[static_cast<std::size_t>(a)] > degree[static_cast<std::size_t>(b)];
  });
  std::vector<int> best, clique;
  std::vector<Word> P(static_cast<std::size_t>(w));
  for (int s = 0; s < std::min(starts, n); ++s) {
    const int v = order[static_cast<std::size_t>(s)];
    if (degree[static_cast<std::size_t>(v)] + 1 <= static_cast<int>(best.size())) break;
    clique.assign(1, v);
    std::copy(g.row(v), g.row(v) + w, P.begin());
    while (true) {
      int pick = -1, pick_degree = -1;
      for_each_bit(P.data(), w, [&](int c) {
        const int d = count_and(g.row(c), P.data(), w);
        if (d > pick_degree) pick_degree = d, pick = c;
      });
      if (pick < 0) break;
      clique.push_back(pick);
      const Word* r = g.row(pick);
      for (int i = 0; i < w; ++i) P[static_cast<std::size_t>(i)] &= r[i];
    }
    if (clique.size() > best.size()) best = clique;
  }
  std::sort(best.begin(), best.end());
  return best;
}

}  // namespace pagor::detail
