#pragma once
// Internal to the clique solvers: a dense level of the pyramid as bit rows over all its vertices,
// for the steps before the exact search — degrees, the lower bound's greedy cliques, the k-core
// peel — and the core the exact search then runs on. On rows of hundreds of neighbours these
// intersect a word at a time, where walking the pyramid's rows visits every entry and skips the
// higher levels' edges. Each gives the same result as its counterpart in clique_graph.hpp.

#include <vector>

#include "graph/bit_graph.hpp"
#include "graph/clique_graph.hpp"

namespace pagor::detail {

/// Whether level `level` of g is better held as bit rows: at most kMaxLevelBits vertices, and
/// rows of bits no larger than the level's edge lists.
bool dense_level(const PyramidGraph& g, int level);
constexpr int kMaxLevelBits = 8192;  // 8 MiB of bits

/// Level `level` over all of g's vertices as bit rows (local vertex v is pyramid vertex v).
BitGraph level_bits(const PyramidGraph& g, int level);

/// Bit rows of the levels from `first` on, built in one pass over g's rows (each entry sets one
/// bit, in the level it joins at, and each level is then or-ed into the next): entry l is level
/// l's bit rows, empty for l < first. Empty when first is past the last level.
std::vector<BitGraph> levels_bits(const PyramidGraph& g, int first);

/// Every vertex's degree.
std::vector<int> degrees(const BitGraph& g);

/// extend_clique on bit rows: the same clique, its candidates intersected a word at a time.
std::vector<int> extend_clique(const BitGraph& g, std::vector<int> clique,
                               const std::vector<int>& priority, int min_priority, Marks& marks);

/// Whether `vertices` are pairwise adjacent.
bool is_clique(const BitGraph& g, const std::vector<int>& vertices, Marks& marks);

/// The k-core's vertices, sorted, given every vertex's degree.
std::vector<int> k_core(const BitGraph& g, std::vector<int> deg, int k);

/// Whether no clique among `keep` (the |clique|-core, sorted) is larger than `clique`, proven by a
/// colouring with |clique| colours: colour class c starts from clique[c] and takes, in increasing
/// id, every vertex of keep left that is adjacent to none it holds. A clique larger than `clique`
/// then holds a vertex left uncoloured; each of at most kMaxLeftOver such vertices is shown to be
/// in none by a greedy colouring of its neighbours in keep with |clique| - 1 colours (a vertex so
/// shown leaves keep for the next one's check). False when that does not prove it (the exact
/// search decides). Costs a pass over keep's rows, where the search's proof first decomposes the
/// core.
bool colouring_from_clique_proves(const BitGraph& g, const std::vector<int>& keep,
                                  const std::vector<int>& clique);
constexpr int kMaxLeftOver = 64;

/// The subgraph of g induced by `keep` (sorted; local vertex i is keep[i]) read through g's rows:
/// what level_csr(g's level, keep) holds, without building it. Neighbours come in increasing
/// local id, as a CSR row lists them. It refers to g and keep, which must outlive it.
class CoreView {
 public:
  CoreView(const BitGraph& g, const std::vector<int>& keep);
  int size() const { return static_cast<int>(keep_.size()); }
  int words() const { return g_.words(); }
  /// v's row over all of g's vertices (pyramid ids), and the kept vertices as bits of such a row.
  const Word* row(int v) const { return g_.row(id(v)); }
  const std::vector<Word>& mask() const { return mask_; }
  int id(int v) const { return keep_[static_cast<std::size_t>(v)]; }
  int local(int pyramid_id) const { return local_[static_cast<std::size_t>(pyramid_id)]; }
  int degree(int v) const { return count_and(row(v), mask_.data(), g_.words()); }
  template <typename F>
  void for_each_neighbor(int v, F&& f) const {
    const Word* r = row(v);
    for (int t = 0; t < g_.words(); ++t)
      for (Word x = r[t] & mask_[static_cast<std::size_t>(t)]; x; x &= x - 1)
        f(local_[static_cast<std::size_t>(t * 64 + __builtin_ctzll(x))]);
  }

 private:
  const BitGraph& g_;
  const std::vector<int>& keep_;
  std::vector<Word> mask_;
  std::vector<int> local_;  // pyramid id -> local id, -1 outside keep
};

/// core_decomposition (clique_graph.hpp) of the view: the same cores, order and positions as on
/// its CSR. Each vertex's neighbours are taken from the rows of those not yet removed, a word at
/// a time, so that an edge is visited once rather than from both ends.
CoreDecomposition core_decomposition(const CoreView& g);

/// larger_clique_in (clique_graph.hpp) on the view: the same clique, bound and proof.
std::vector<int> larger_clique_in(const CoreView& core, std::vector<int> best, long max_nodes,
                                  bool& proven, int* bound = nullptr,
                                  Deadline deadline = kNoDeadline, bool* out_of_time = nullptr);

}  // namespace pagor::detail
