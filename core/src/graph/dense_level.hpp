#pragma once
// Internal to the clique solvers: a dense level of the pyramid as bit rows over all its vertices,
// for the steps before the exact search — degrees, the lower bound's greedy cliques, the k-core
// peel and the core's CSR. On rows of hundreds of neighbours these intersect a word at a time,
// where walking the pyramid's rows visits every entry and skips the higher levels' edges.
// Each gives the same result as its counterpart in clique_graph.hpp.

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

/// The subgraph induced by `keep` (sorted; local vertex i is keep[i]) as a CSR with sorted rows;
/// `degree`: every vertex's degree in g.
LevelCsr level_csr(const BitGraph& g, const std::vector<int>& keep,
                   const std::vector<int>& degree);

}  // namespace pagor::detail
