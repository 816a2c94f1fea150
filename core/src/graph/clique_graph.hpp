#pragma once
// Internal to the clique solvers: one level of the pyramid as a plain CSR, its k-core
// decomposition, and greedy cliques grown with neighbour marks (no adjacency look-ups).

#include <algorithm>
#include <cstdint>
#include <vector>

#include "pagor/graph/densest_clique.hpp"
#include "pagor/graph/pyramid_graph.hpp"
#include "util/big_buffers.hpp"

namespace pagor::detail {

/// Level l of a pyramid graph over all its vertices; neighbour lists sorted.
struct LevelCsr {
  std::vector<std::int64_t> offsets;  // vertex v's neighbours are [offsets[v], offsets[v+1])
  UninitVector<int> neighbors;

  int size() const { return offsets.empty() ? 0 : static_cast<int>(offsets.size()) - 1; }
  int degree(int v) const {
    return static_cast<int>(offsets[static_cast<std::size_t>(v) + 1] -
                            offsets[static_cast<std::size_t>(v)]);
  }
  const int* begin(int v) const { return neighbors.data() + offsets[static_cast<std::size_t>(v)]; }
  const int* end(int v) const {
    return neighbors.data() + offsets[static_cast<std::size_t>(v) + 1];
  }
  template <typename F>
  void for_each_neighbor(int v, F&& f) const {
    for (const int* w = begin(v); w != end(v); ++w) f(*w);
  }
};

/// Level l of a pyramid graph read in place: the edges of higher levels are skipped on the fly.
/// Cheaper than a LevelCsr when only a few rows are walked.
struct PyramidLevel {
  const PyramidGraph& g;
  int level;

  int size() const { return g.vertices; }
  /// Entries of v's row over all levels: the cost of walking it.
  std::size_t row_length(int v) const {
    return static_cast<std::size_t>(g.offsets[static_cast<std::size_t>(v) + 1] -
                                    g.offsets[static_cast<std::size_t>(v)]);
  }
  template <typename F>
  void for_each_neighbor(int v, F&& f) const {
    const auto last = static_cast<std::size_t>(g.offsets[static_cast<std::size_t>(v) + 1]);
    for (auto e = static_cast<std::size_t>(g.offsets[static_cast<std::size_t>(v)]); e < last; ++e)
      if (g.level[e] <= level) f(g.neighbors[e]);
  }
};

/// Degree of every vertex at level l.
std::vector<int> level_degrees(const PyramidGraph& g, int level);

/// The edges of level `level` (those whose lowest level is at most `level`).
LevelCsr level_csr(const PyramidGraph& g, int level);
/// The same, induced by `keep` (sorted pyramid ids; local vertex i is keep[i]).
LevelCsr level_csr(const PyramidGraph& g, int level, const std::vector<int>& keep);

/// Core numbers (Batagelj and Zaversnik's bucket algorithm, O(V + E)) and the degeneracy order:
/// `order[i]` is the i-th vertex removed (lowest core first), `position` its inverse.
struct CoreDecomposition {
  std::vector<int> core, order, position;
  int degeneracy = 0;  // largest core number
};
CoreDecomposition core_decomposition(const LevelCsr& g);

/// The buckets of that algorithm, shared by its two forms (on a CSR and on a dense level's bit
/// rows, which differ only in how they find a vertex's neighbours): `order` holds the vertices
/// sorted by current degree (their core numbers so far, in `core`), `bin[k]` where degree k starts.
class DegreeBuckets {
 public:
  /// Sorts the vertices by the degrees in d.core (counting sort).
  explicit DegreeBuckets(CoreDecomposition& d)
      : core_(d.core.data()), order_(d.order.data()), position_(d.position.data()) {
    const int n = static_cast<int>(d.core.size());
    int max_deg = 0;
    for (int v = 0; v < n; ++v) max_deg = std::max(max_deg, core_[v]);
    bins_.assign(static_cast<std::size_t>(max_deg) + 1, 0);
    bin_ = bins_.data();
    for (int v = 0; v < n; ++v) ++bin_[core_[v]];
    int start = 0;
    for (int k = 0; k <= max_deg; ++k) {
      const int c = bin_[k];
      bin_[k] = start;
      start += c;
    }
    for (int v = 0; v < n; ++v) {
      const int at = bin_[core_[v]]++;
      position_[v] = at;
      order_[at] = v;
    }
    for (int k = max_deg; k > 0; --k) bin_[k] = bin_[k - 1];
    bin_[0] = 0;
  }
  /// The i-th vertex to remove (read when the i-th removal starts: lowering moves vertices).
  int at(int i) const { return order_[i]; }
  /// Vertex u, a neighbour of removed vertex v, loses an edge when its degree is above v's core
  /// number (a removed neighbour's never is): it moves down one bucket, swapping places with the
  /// first vertex of its bucket (which may be itself).
  void lower_above(int u, int cv) {
    const int cu = core_[u];
    if (cu <= cv) return;
    const int pu = position_[u];
    const int pw = bin_[cu]++;
    const int w = order_[pw];
    position_[u] = pw;
    order_[pu] = w;
    position_[w] = pu;
    order_[pw] = u;
    core_[u] = cu - 1;
  }

 private:
  // Raw pointers: through the vectors, every store reloaded their data pointers.
  int* core_;
  int* order_;
  int* position_;
  std::vector<int> bins_;
  int* bin_ = nullptr;
};

/// Scratch marks for neighbourhood intersections: mark a set, then test membership in O(1).
class Marks {
 public:
  explicit Marks(int n) : stamp_(static_cast<std::size_t>(n), 0) {}
  void next() { ++tick_; }
  void set(int v) { stamp_[static_cast<std::size_t>(v)] = tick_; }
  bool has(int v) const { return stamp_[static_cast<std::size_t>(v)] == tick_; }
  template <typename Graph>
  void mark_neighbours(const Graph& g, int v) {
    next();
    g.for_each_neighbor(v, [this](int w) { set(w); });
  }

 private:
  std::vector<std::uint32_t> stamp_;
  std::uint32_t tick_ = 0;
};

/// Grows `clique` (a clique of g) into a maximal one, taking among the vertices adjacent to all
/// members the one with the largest `priority` first (ties: lower id). Only vertices with
/// `priority[v] >= min_priority` are considered. Returns the grown clique, sorted.
template <typename Graph, typename T>
std::vector<int> extend_clique(const Graph& g, std::vector<int> clique,
                               const std::vector<T>& priority, T min_priority, Marks& marks) {
  if (clique.empty()) return clique;
  std::vector<int> cand;
  // Candidates: neighbours of the first member that are adjacent to every other member.
  g.for_each_neighbor(clique[0], [&](int w) {
    if (priority[static_cast<std::size_t>(w)] >= min_priority) cand.push_back(w);
  });
  for (std::size_t i = 1; i < clique.size() && !cand.empty(); ++i) {
    marks.mark_neighbours(g, clique[i]);
    std::size_t k = 0;
    for (int w : cand)
      if (marks.has(w)) cand[k++] = w;
    cand.resize(k);
  }
  std::stable_sort(cand.begin(), cand.end(), [&](int a, int b) {
    return priority[static_cast<std::size_t>(a)] > priority[static_cast<std::size_t>(b)];
  });
  // Take the best candidate and keep those adjacent to it (filtering keeps the order).
  while (!cand.empty()) {
    const int c = cand.front();
    clique.push_back(c);
    marks.mark_neighbours(g, c);
    std::size_t k = 0;
    for (std::size_t i = 1; i < cand.size(); ++i)
      if (marks.has(cand[i])) cand[k++] = cand[i];
    cand.resize(k);
  }
  std::sort(clique.begin(), clique.end());
  return clique;
}

/// A lower bound: greedy cliques (members by `priority`) grown from up to `starts` vertices of
/// largest priority that are not in the best clique so far (initially `best`, sorted, if given);
/// the largest kept, sorted. With core
/// numbers or degrees as priority, a start whose priority + 1 cannot beat the best ends the search.
template <typename Graph>
std::vector<int> greedy_clique(const Graph& g, const std::vector<int>& priority, int starts,
                               Marks& marks, std::vector<int> best = {}) {
  std::vector<int> order(static_cast<std::size_t>(g.size()));
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return priority[static_cast<std::size_t>(a)] > priority[static_cast<std::size_t>(b)];
  });
  int tried = 0;
  for (int v : order) {
    if (tried >= starts) break;
    const int size = static_cast<int>(best.size());
    if (priority[static_cast<std::size_t>(v)] + 1 <= size) break;
    if (std::binary_search(best.begin(), best.end(), v)) continue;  // would grow much the same
    ++tried;
    // Members of a clique larger than `best` have a degree (core number) of at least |best|.
    std::vector<int> c = extend_clique(g, {v}, priority, size, marks);
    if (c.size() > best.size()) best = std::move(c);
  }
  return best;
}

/// Local search on a maximal clique (sorted): while some member x can be swapped for two
/// adjacent vertices that miss only x, do so and grow the result to a maximal clique again, at
/// most `max_swaps` times. Each swap grows the clique by at least one. Returns it sorted.
template <typename Graph>
std::vector<int> improve_by_swaps(const Graph& g, std::vector<int> clique, Marks& marks,
                                  int max_swaps) {
  const auto n = static_cast<std::size_t>(g.size());
  std::vector<int> hits(n, 0);          // members adjacent to w
  std::vector<long long> id_sum(n, 0);  // sum of the ids of those members
  std::vector<char> member(n, 0);
  std::vector<int> touched;
  for (int swaps = 0; swaps < max_swaps && !clique.empty(); ++swaps) {
    long long total = 0;
    for (int x : clique) {
      member[static_cast<std::size_t>(x)] = 1;
      total += x;
      g.for_each_neighbor(x, [&](int w) {
        const auto sw = static_cast<std::size_t>(w);
        if (hits[sw]++ == 0) touched.push_back(w);
        id_sum[sw] += x;
      });
    }
    // Vertices missing exactly one member, grouped by that member (sorted by it, then by id).
    std::vector<std::pair<int, int>> one_off;  // (missing member, vertex)
    const int need = static_cast<int>(clique.size()) - 1;
    for (int w : touched)
      if (!member[static_cast<std::size_t>(w)] && hits[static_cast<std::size_t>(w)] == need)
        one_off.emplace_back(static_cast<int>(total - id_sum[static_cast<std::size_t>(w)]), w);
    for (int w : touched) {
      hits[static_cast<std::size_t>(w)] = 0;
      id_sum[static_cast<std::size_t>(w)] = 0;
    }
    touched.clear();
    for (int x : clique) member[static_cast<std::size_t>(x)] = 0;
    std::sort(one_off.begin(), one_off.end());
    int out = -1, a = -1, b = -1;
    for (std::size_t i = 0; i < one_off.size() && out < 0;) {
      std::size_t j = i;
      while (j < one_off.size() && one_off[j].first == one_off[i].first) ++j;
      for (std::size_t k = i; k + 1 < j && out < 0; ++k) {
        marks.mark_neighbours(g, one_off[k].second);
        for (std::size_t l = k + 1; l < j; ++l)
          if (marks.has(one_off[l].second)) {
            out = one_off[i].first;
            a = one_off[k].second;
            b = one_off[l].second;
            break;
          }
      }
      i = j;
    }
    if (out < 0) break;  // no improving swap
    clique.erase(std::find(clique.begin(), clique.end(), out));
    clique.push_back(a);
    clique.push_back(b);
    clique = extend_clique(g, std::move(clique), std::vector<int>(n, 0), 0, marks);
  }
  std::sort(clique.begin(), clique.end());
  return clique;
}

/// The vertices of the k-core (degree at least k after repeatedly removing lower degrees), given
/// every vertex's degree and the length of each vertex's row (`row_length`, the cost of walking
/// it). Peeling walks the rows of the removed vertices; when most vertices go at once, recounting
/// the survivors' degrees among themselves walks fewer rows, and the peel continues from there.
template <typename Graph, typename RowLength>
std::vector<int> k_core(const Graph& g, std::vector<int> deg, int k, RowLength&& row_length) {
  const int n = g.size();
  std::vector<char> removed(static_cast<std::size_t>(n), 0);
  std::vector<int> stack;
  std::size_t removed_rows = 0, kept_rows = 0;
  for (int v = 0; v < n; ++v) {
    if (deg[static_cast<std::size_t>(v)] < k) {
      removed[static_cast<std::size_t>(v)] = 1;
      stack.push_back(v);
      removed_rows += row_length(v);
    } else {
      kept_rows += row_length(v);
    }
  }
  if (kept_rows < removed_rows) {
    stack.clear();
    for (int v = 0; v < n; ++v) {
      if (removed[static_cast<std::size_t>(v)]) continue;
      int d = 0;
      g.for_each_neighbor(v, [&](int w) { d += !removed[static_cast<std::size_t>(w)]; });
      deg[static_cast<std::size_t>(v)] = d;
    }
    for (int v = 0; v < n; ++v)
      if (!removed[static_cast<std::size_t>(v)] && deg[static_cast<std::size_t>(v)] < k) {
        removed[static_cast<std::size_t>(v)] = 1;
        stack.push_back(v);
      }
  }
  while (!stack.empty()) {
    const int v = stack.back();
    stack.pop_back();
    g.for_each_neighbor(v, [&](int w) {
      const auto sw = static_cast<std::size_t>(w);
      if (!removed[sw] && --deg[sw] < k) {
        removed[sw] = 1;
        stack.push_back(w);
      }
    });
  }
  std::vector<int> keep;
  for (int v = 0; v < n; ++v)
    if (!removed[static_cast<std::size_t>(v)]) keep.push_back(v);
  return keep;
}

/// The k-core, peeling only.
template <typename Graph>
std::vector<int> k_core(const Graph& g, std::vector<int> deg, int k) {
  return k_core(g, std::move(deg), k, [](int) { return std::size_t{0}; });
}

/// Whether `vertices` are pairwise adjacent in g.
template <typename Graph>
bool is_clique(const Graph& g, const std::vector<int>& vertices, Marks& marks) {
  for (std::size_t a = 0; a < vertices.size(); ++a) {
    marks.mark_neighbours(g, vertices[a]);
    for (std::size_t b = 0; b < vertices.size(); ++b)
      if (a != b && !marks.has(vertices[b])) return false;
  }
  return true;
}

/// Exact search for a clique larger than `best` on `level` (the exact solver, started from
/// `best`): the largest clique found, `best` itself when there is none; `proven` tells whether
/// the search finished within `max_nodes` branch-and-bound nodes.
/// `bound`, if given, receives the upper bound on the clique number the search reached.
std::vector<int> larger_clique(const PyramidGraph& g, int level, std::vector<int> best,
                               long max_nodes, bool& proven, int* bound = nullptr,
                               Deadline deadline = kNoDeadline, bool* out_of_time = nullptr);

/// larger_clique on the |best|-core already found: `keep` (sorted pyramid ids, empty when the
/// core is) and the level's subgraph induced by it, in local ids.
std::vector<int> larger_clique_in(const LevelCsr& core, const std::vector<int>& keep,
                                  std::vector<int> best, long max_nodes, bool& proven,
                                  int* bound = nullptr, Deadline deadline = kNoDeadline,
                                  bool* out_of_time = nullptr);

struct SearchBudget;
/// The exact solver on one level within `budget` (nodes and deadline, shared by the levels of a
/// pyramid): the best clique found, whether it is proven maximum, the bound reached, and which
/// budget stopped it.
/// `seed`, if given, is a clique of this level to start from (the previous level's: levels nest).
CliqueResult exact_level(const PyramidGraph& g, int level, const CliqueParams& params,
                         SearchBudget& budget, const std::vector<int>& seed = {});

}  // namespace pagor::detail
