#pragma once
// Internal to the clique solvers: one level of the pyramid as a plain CSR, its k-core
// decomposition, and greedy cliques grown with neighbour marks (no adjacency look-ups).

#include <algorithm>
#include <cstdint>
#include <vector>

#include "pagor/pyramid_graph.hpp"

namespace pagor::detail {

/// Level l of a pyramid graph over all its vertices; neighbour lists sorted.
struct LevelCsr {
  std::vector<std::int64_t> offsets;  // vertex v's neighbours are [offsets[v], offsets[v+1])
  std::vector<int> neighbors;

  int size() const { return static_cast<int>(offsets.size()) - 1; }
  int degree(int v) const {
    return static_cast<int>(offsets[static_cast<std::size_t>(v) + 1] -
                            offsets[static_cast<std::size_t>(v)]);
  }
  const int* begin(int v) const { return neighbors.data() + offsets[static_cast<std::size_t>(v)]; }
  const int* end(int v) const {
    return neighbors.data() + offsets[static_cast<std::size_t>(v) + 1];
  }
};

/// The edges of level `level` (those whose lowest level is at most `level`).
LevelCsr level_csr(const PyramidGraph& g, int level);

/// Core numbers (Batagelj and Zaversnik's bucket algorithm, O(V + E)) and the degeneracy order:
/// `order[i]` is the i-th vertex removed (lowest core first), `position` its inverse.
struct CoreDecomposition {
  std::vector<int> core, order, position;
  int degeneracy = 0;  // largest core number
};
CoreDecomposition core_decomposition(const LevelCsr& g);

/// Scratch marks for neighbourhood intersections: mark a set, then test membership in O(1).
class Marks {
 public:
  explicit Marks(int n) : stamp_(static_cast<std::size_t>(n), 0) {}
  void next() { ++tick_; }
  void set(int v) { stamp_[static_cast<std::size_t>(v)] = tick_; }
  bool has(int v) const { return stamp_[static_cast<std::size_t>(v)] == tick_; }
  void mark_neighbours(const LevelCsr& g, int v) {
    next();
    for (const int* w = g.begin(v); w != g.end(v); ++w) set(*w);
  }

 private:
  std::vector<std::uint32_t> stamp_;
  std::uint32_t tick_ = 0;
};

/// Grows `clique` (a clique of g) into a maximal one, taking among the vertices adjacent to all
/// members the one with the largest `priority` first (ties: lower id). Only vertices with
/// `priority[v] >= min_priority` are considered. Returns the grown clique, sorted.
template <typename T>
std::vector<int> extend_clique(const LevelCsr& g, std::vector<int> clique,
                               const std::vector<T>& priority, T min_priority, Marks& marks) {
  if (clique.empty()) return clique;
  std::vector<int> cand;
  // Candidates: neighbours of the first member that are adjacent to every other member.
  for (const int* w = g.begin(clique[0]); w != g.end(clique[0]); ++w)
    if (priority[static_cast<std::size_t>(*w)] >= min_priority) cand.push_back(*w);
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

/// A lower bound: greedy cliques grown from up to `starts` vertices of largest core number that
/// are not yet in the best clique (members by core number), the largest kept. Sorted.
std::vector<int> greedy_clique(const LevelCsr& g, const CoreDecomposition& cores, int starts,
                               Marks& marks);

/// The vertices of the k-core (degree at least k after repeatedly removing lower degrees).
std::vector<int> k_core(const LevelCsr& g, int k);

/// Whether `vertices` are pairwise adjacent in g.
bool is_clique(const LevelCsr& g, const std::vector<int>& vertices, Marks& marks);

}  // namespace pagor::detail
