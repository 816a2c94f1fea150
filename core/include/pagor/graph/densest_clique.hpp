#pragma once
/// \file densest_clique.hpp
/// Densest clique of each pyramid level: the CLIPPER relaxation
///   maximise u^T M_d u  subject to  u >= 0, |u| <= 1,   M_d = M - d (1 1^T - C),
/// by projected gradient ascent with backtracking, raising the penalty d until the support of u is
/// a clique, then keeping the round(u^T C u) largest entries. Cascaded (Alg. 1 of the paper): the
/// sparsest level is solved first and each next level starts from the previous solution.
/// The rounded clique is grown to a maximal one and improved by swaps (one member out, two
/// vertices in). Also an exact maximum clique by branch and bound (exact_clique.cpp).

#include <vector>

#include "pagor/config.hpp"
#include "pagor/graph/pyramid_graph.hpp"

namespace pagor {

/// The clique found on one level.
struct CliqueResult {
  int level = 0;
  std::vector<int> vertices;  ///< clique members (correspondence indices), increasing
  std::vector<double> u;      ///< final relaxation vector (empty for the exact solver)
  int gradient_steps = 0;     ///< accepted and rejected gradient steps, over all penalties
  int penalty_updates = 0;    ///< outer iterations (increases of d)
  double penalty = 0.0;       ///< final penalty d
  bool optimal = false;       ///< exact solver: whether the search finished within its budget
  double time_ms = 0.0;       ///< wall time [ms]
};

/// CLIPPER relaxation on level `level` from `u0` (any non-negative vector of the graph's size; it
/// is normalised; an all-zero or empty one means the seeded random start). With `params.prune`,
/// the relaxation runs on the k-core that can hold a clique as large as a lower bound —
/// `known_clique` (if it is a clique on this level) grown to a maximal clique, or greedy cliques
/// from the highest degrees if they are larger — and the answer is never smaller than that
/// bound; when that core is itself a clique it is the answer and no gradient step is taken.
/// `d0` is the initial penalty (a warm start may carry part of the previous level's).
CliqueResult solve_clipper(const PyramidGraph& graph, int level, const std::vector<double>& u0,
                           const CliqueParams& params, const std::vector<int>& known_clique = {},
                           double d0 = 0.0);

/// The seeded random start of the relaxation (uniform in (0, 1], normalised).
std::vector<double> random_start(int size, std::uint64_t seed);

/// Exact maximum clique on level `level`: one subproblem per vertex of the core that can hold a
/// larger clique than the best so far (the vertex and its later neighbours in the degeneracy
/// order), each solved by branch and bound on bitsets with greedy-colouring bounds, or, when it is
/// near-complete, as a maximum independent set of its sparse complement.
/// Stops after `params.exact_max_nodes` search nodes with the best clique so far and
/// `optimal = false`.
CliqueResult exact_max_clique(const PyramidGraph& graph, int level, const CliqueParams& params);

/// One clique per level, in level order, with the solver `params.solver` selects.
std::vector<CliqueResult> solve_pyramid(const PyramidGraph& graph, const CliqueParams& params);

/// Whether every pair of `vertices` is adjacent at `level`.
bool is_clique(const PyramidGraph& graph, int level, const std::vector<int>& vertices);

}  // namespace pagor
