#pragma once
// Internal to the clique solvers: the CLIPPER relaxation on one level restricted to a vertex
// subset,
//   maximise u^T M_d u  subject to  u >= 0, |u| <= 1,   M_d = M - d (1 1^T - C),
// by projected gradient ascent with backtracking, raising the penalty d until the support of u is
// a clique, then keeping the round(u^T C u) largest entries.

#include <vector>

#include "pagor/graph/densest_clique.hpp"

namespace pagor::detail {

/// One level of the pyramid restricted to a vertex subset, with local ids and per-edge affinities:
/// the relaxation's inner loop then touches neither absent levels nor pruned vertices.
struct LevelGraph {
  std::vector<int> ids;              ///< local -> global vertex id
  std::vector<std::size_t> offsets;  ///< CSR over local ids, neighbours sorted
  std::vector<int> neighbors;
  std::vector<float> weights;  ///< affinity per edge (TRIM values until set_weights)
  bool binary = true;          ///< all weights 1: M u = C u

  std::size_t size() const { return ids.size(); }
  bool complete() const { return neighbors.size() == size() * (size() - 1); }
};

/// The subgraph of level `level` induced by `keep` (sorted), with each edge's TRIM value.
LevelGraph induce(const PyramidGraph& g, int level, const std::vector<int>& keep);

/// TRIM values -> Gaussian affinities of level `level` (as PyramidGraph::weight).
void set_weights(LevelGraph& s, const PyramidGraph& g, int level);

/// Projection onto {u >= 0, |u| = 1}; false when nothing positive is left.
bool project(std::vector<double>& u);

/// The relaxation from a non-negative unit vector `u` (local ids) and penalty `d`; leaves the final
/// vector in `u`, counts steps and penalty updates in `r` (and its final penalty), and returns the
/// rounded clique (local ids).
/// After `deadline` it stops at the end of a penalty step and rounds what it has (r.budget = time).
std::vector<int> relax(const LevelGraph& g, std::vector<double>& u, double d, const CliqueParams& p,
                       CliqueResult& r, Deadline deadline = kNoDeadline);

}  // namespace pagor::detail
