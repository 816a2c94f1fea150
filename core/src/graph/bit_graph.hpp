#pragma once
// Internal to the clique solvers: a graph on a few hundred or thousand local vertices as rows of
// bits (row v: the neighbours of v), for the operations a clique search repeats — intersecting a
// candidate set with a neighbourhood, counting a vertex's neighbours in a set — one word at a time.

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <vector>

#include "pagor/graph/pyramid_graph.hpp"
#include "util/big_buffers.hpp"

namespace pagor::detail {

using Word = std::uint64_t;

inline int words_for(int n) {
  return (n + 63) / 64;
}
inline bool test_bit(const Word* set, int v) {
  return (set[v >> 6] >> (v & 63)) & 1;
}
inline void set_bit(Word* set, int v) {
  set[v >> 6] |= Word(1) << (v & 63);
}
inline void clear_bit(Word* set, int v) {
  set[v >> 6] &= ~(Word(1) << (v & 63));
}

/// The popcount instruction is not in the x86-64 baseline the project builds for: loops that
/// count bits get a clone for CPUs that have it (chosen once at load time) and a portable one.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define PAGOR_POPCOUNT_CLONES __attribute__((target_clones("popcnt", "default")))
#else
#define PAGOR_POPCOUNT_CLONES
#endif

/// Set bits of a & b over `words` words (the hardware instruction where the CPU has it).
int count_and(const Word* a, const Word* b, int words);
/// The same inline, for loops over short rows inside a PAGOR_POPCOUNT_CLONES function (where it
/// compiles to the instruction): there a call per row cost more than the row.
inline int count_and_inline(const Word* a, const Word* b, int words) {
  int n = 0;
  for (int i = 0; i < words; ++i) n += __builtin_popcountll(a[i] & b[i]);
  return n;
}
/// Set bits of a over `words` words.
int count_bits(const Word* a, int words);

/// Calls f(v) for every set bit v of `set`, in increasing order.
template <typename F>
void for_each_bit(const Word* set, int words, F&& f) {
  for (int i = 0; i < words; ++i)
    for (Word x = set[i]; x; x &= x - 1) f(i * 64 + __builtin_ctzll(x));
}

/// A graph on local vertices 0..n-1 as rows of bits; `ids` maps them to the pyramid's vertices.
class BitGraph {
 public:
  BitGraph() = default;
  explicit BitGraph(int n)
      : n_(n),
        w_(words_for(n)),
        bits_(static_cast<std::size_t>(n) * static_cast<std::size_t>(words_for(n)), 0) {}
  int size() const { return n_; }
  int words() const { return w_; }
  Word* row(int v) { return bits_.data() + static_cast<std::size_t>(v) * w_; }
  const Word* row(int v) const { return bits_.data() + static_cast<std::size_t>(v) * w_; }
  void connect(int a, int b) {
    set_bit(row(a), b);
    set_bit(row(b), a);
  }
  bool adjacent(int a, int b) const { return test_bit(row(a), b); }
  int degree(int v) const { return count_bits(row(v), w_); }
  /// Every vertex, as a set of bits.
  std::vector<Word> all() const;
  /// Interface of the clique helpers (clique_graph.hpp).
  template <typename F>
  void for_each_neighbor(int v, F&& f) const {
    for_each_bit(row(v), w_, f);
  }

  std::vector<int> ids;  ///< local vertex -> pyramid vertex

 private:
  int n_ = 0, w_ = 0;
  std::vector<Word, BlockAllocator<Word>> bits_;  // megabytes on dense levels
};

/// Level `level` of `g` induced by `vertices` (pyramid ids, any order; local vertex i is
/// vertices[i]). `local` is scratch of g.vertices entries, all -1 on entry and on return.
BitGraph induce_bits(const PyramidGraph& g, int level, const std::vector<int>& vertices,
                     std::vector<int>& local);

/// A colour class grown greedily on b's rows: takes, in increasing id, every vertex of Q (words
/// [lo, span); vertices beyond the span are never neighbours of those in it) that is adjacent to
/// none taken before, clearing each from U. Returns how many it took; Q is used up.
inline int take_class(const BitGraph& b, Word* U, Word* Q, int lo, int span) {
  int n = 0;
  for (int k = lo; k < span; ++k)
    while (Q[k]) {
      const int a = k * 64 + __builtin_ctzll(Q[k]);
      clear_bit(U, a);
      ++n;
      const Word* ra = b.row(a);
      for (int t = k; t < span; ++t) Q[t] &= ~ra[t];
      clear_bit(Q, a);
    }
  return n;
}

/// Greedy colouring on bit rows with at most `colours` colours, of the vertices in U (words
/// [0, span), `count` of them), taken in increasing id: each vertex gets the lowest colour none of
/// its earlier neighbours has. Built a colour class at a time (the same colouring): a class takes,
/// in order, every vertex left that is adjacent to none it has taken. Returns how many stay
/// uncoloured; U keeps them. Q: scratch.
inline int colour_greedily(const BitGraph& b, Word* U, Word* Q, int span, int count, int colours) {
  int remaining = count, lo = 0;  // the words below `lo` are empty
  for (int colour = 0; colour < colours && remaining > 0; ++colour) {
    while (lo < span && !U[lo]) ++lo;
    std::copy(U + lo, U + span, Q + lo);
    remaining -= take_class(b, U, Q, lo, span);
  }
  return remaining;
}

/// What a search may spend: branch-and-bound nodes and wall time. Shared by the searches of one
/// level so that the budget is the level's.
struct SearchBudget {
  using Clock = std::chrono::steady_clock;
  long max_nodes = 0;                                     ///< 0: none
  Clock::time_point deadline = Clock::time_point::max();  ///< max(): none
  long nodes = 0;                                         ///< spent so far
  bool out_of_nodes = false, out_of_time = false;         ///< which limit stopped a search
  /// Counts `units` nodes (a node that did the work of several counts as several); false once a
  /// limit is reached (the clock is read each time the count passes a multiple of 256).
  bool spend(long units = 1) {
    const long before = nodes;
    nodes += units;
    if (max_nodes > 0 && nodes > max_nodes) out_of_nodes = true;
    if ((before >> 8) != (nodes >> 8) && deadline != Clock::time_point::max() &&
        Clock::now() > deadline)
      out_of_time = true;
    return !exhausted();
  }
  bool exhausted() const { return out_of_nodes || out_of_time; }
  /// Reads the clock (between searches, where no node is spent); false once past the deadline.
  bool in_time() {
    if (deadline != Clock::time_point::max() && Clock::now() > deadline) out_of_time = true;
    return !out_of_time;
  }
};

/// A maximum clique of `g` if it has more than `lower` vertices, else empty (local ids). Branch
/// and bound with greedy-colouring bounds on bits (MCQ/BBMC); a graph of at least 32 vertices and
/// 90 % density is searched as a maximum independent set of its sparse complement instead.
/// `complete` becomes false when the budget stopped the search (the clique is then the best
/// found); `upper_bound` receives a bound on the clique number (exact when complete).
std::vector<int> max_clique_bits(const BitGraph& g, int lower, SearchBudget& budget, bool& complete,
                                 int& upper_bound);

/// The largest clique found greedily from up to `starts` vertices of highest degree: each step
/// takes the candidate with most neighbours among the candidates (local ids, sorted).
std::vector<int> greedy_clique_bits(const BitGraph& g, int starts);

}  // namespace pagor::detail
