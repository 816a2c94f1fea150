#pragma once
/// \file densest_clique.hpp
/// Densest clique of each pyramid level: the CLIPPER relaxation
///   maximise u^T M_d u  subject to  u >= 0, |u| <= 1,   M_d = M - d (1 1^T - C),
/// by projected gradient ascent with backtracking, raising the penalty d until the support of u is
/// a clique, then keeping the round(u^T C u) largest entries. Cascaded (Alg. 1 of the paper): the
/// sparsest level is solved first and each next level starts from the previous solution.
/// The rounded clique is grown to a maximal one and improved by swaps (one member out, two
/// vertices in). Also an exact maximum clique by branch and bound (exact_clique.cpp).

#include <chrono>
#include <vector>

#include "pagor/graph/pyramid_graph.hpp"
#include "pagor/util/fields.hpp"

namespace pagor {

/// Which densest-clique solver.
enum class CliqueSolver {
  cascaded,     ///< CLIPPER relaxation, each level warm-started from the previous one (Alg. 1)
  independent,  ///< CLIPPER relaxation, each level from the same initial vector
  exact,        ///< exact maximum clique (branch and bound)
};
inline constexpr EnumEntry<CliqueSolver> kCliqueSolvers[] = {
    {CliqueSolver::cascaded, "cascaded",
     "CLIPPER relaxation, each level warm-started from the previous one (Alg. 1)"},
    {CliqueSolver::independent, "independent",
     "CLIPPER relaxation, each level from the same initial vector"},
    {CliqueSolver::exact, "exact", "exact maximum clique by branch and bound"},
};
inline const auto& enum_entries(CliqueSolver) {
  return kCliqueSolvers;
}

/// How a level's search started.
enum class CliqueStart {
  cold,      ///< from greedy cliques of this level (the first level, or independent levels)
  warm,      ///< from the previous level's clique and relaxation vector (cascaded, Alg. 1)
  fallback,  ///< cascaded, but a greedy clique of this level beat the warm start: started cold
};
inline constexpr EnumEntry<CliqueStart> kCliqueStarts[] = {
    {CliqueStart::cold, "cold", "from greedy cliques of this level"},
    {CliqueStart::warm, "warm", "from the previous level's clique and relaxation vector"},
    {CliqueStart::fallback, "fallback", "a greedy clique beat the warm start: started cold"},
};
inline const auto& enum_entries(CliqueStart) {
  return kCliqueStarts;
}

/// Which budget, if any, stopped a level's clique search.
enum class CliqueBudget {
  none,   ///< no search was cut short
  nodes,  ///< a branch-and-bound node budget ran out
  time,   ///< the wall-time budget ran out
};
inline constexpr EnumEntry<CliqueBudget> kCliqueBudgets[] = {
    {CliqueBudget::none, "none", "no search was cut short"},
    {CliqueBudget::nodes, "nodes", "a node budget ran out"},
    {CliqueBudget::time, "time", "the time budget ran out"},
};
inline const auto& enum_entries(CliqueBudget) {
  return kCliqueBudgets;
}

/// The densest-clique solver (CLIPPER relaxation) and the exact search.
struct CliqueParams {
  // Each field's meaning, unit and valid range: fields() below (docs/config.md).
  CliqueSolver solver = CliqueSolver::cascaded;
  bool prune = true;
  bool prove_first = true;
  long prove_first_min_edges = 3000;
  double tol_u = 1e-8;
  double tol_F = 1e-9;
  int max_inner_iterations = 200;
  int max_outer_iterations = 1000;
  double beta = 0.25;
  int max_line_search = 99;
  double eps = 1e-9;
  double support_tol = 1e-6;
  std::uint64_t seed = 42;
  double warm_start_mix = 0.05;
  double warm_start_penalty = 1.0;
  long exact_max_nodes = 20000000;
  double exact_time_budget_ms = 1000.0;
  int greedy_starts = 4;
  int max_swaps = 64;
  double pair_time_budget_ms = 10000.0;
  bool cascade_fallback = true;
  long cascade_check_nodes = 200000;
  double max_step = 1e6;

  template <class V>
  static void fields(V&& v) {
    v(&CliqueParams::solver, {"solver", "The densest-clique solver."});
    v(&CliqueParams::prune,
      {"prune",
       "Relax on the k-core that can hold a clique as large as a greedy one, and never return "
       "less than the greedy clique."});
    v(&CliqueParams::prove_first,
      {"prove_first",
       "Binary affinity: first try to prove the lower bound's clique maximum (on a dense level by "
       "a colouring seeded by that clique, then) by a bounded exact search (cascade_check_nodes); "
       "when that succeeds the relaxation is skipped. Off: the relaxation always runs (the "
       "paper's Alg. 1)."});
    v(&CliqueParams::prove_first_min_edges,
      {"prove_first_min_edges",
       "prove_first applies to levels with at least this many edges; on smaller graphs the "
       "relaxation is cheap and its choice among equal-size cliques is kept.",
       "", Range::closed(0, 1e12)});
    v(&CliqueParams::tol_u, {"tol_u", "The gradient ascent stops when u moves less than this.", "",
                             Range::above(0, 1), std::numeric_limits<double>::quiet_NaN(), true});
    v(&CliqueParams::tol_F,
      {"tol_F", "The gradient ascent stops when the objective changes less than this.", "",
       Range::above(0, 1), std::numeric_limits<double>::quiet_NaN(), true});
    v(&CliqueParams::max_inner_iterations,
      {"max_inner_iterations", "Gradient steps for one penalty d, at most.", "",
       Range::closed(1, 100000)});
    v(&CliqueParams::max_outer_iterations,
      {"max_outer_iterations", "Penalty increases, at most.", "", Range::closed(1, 100000)});
    v(&CliqueParams::beta,
      {"beta", "Backtracking line search: step reduction factor.", "", Range::open(0, 1)});
    v(&CliqueParams::max_line_search,
      {"max_line_search", "Backtracking steps per gradient step, at most.", "",
       Range::closed(1, 1000)});
    v(&CliqueParams::eps, {"eps", "Numerical zero of the relaxation.", "", Range::above(0, 1),
                           std::numeric_limits<double>::quiet_NaN(), true});
    v(&CliqueParams::support_tol,
      {"support_tol", "Entries of u below this fraction of the largest count as zero.", "",
       Range::below(0, 1)});
    v(&CliqueParams::seed, {"seed", "Seed of the relaxation's initial vector."});
    v(&CliqueParams::warm_start_mix,
      {"warm_start_mix", "Cascaded: weight of the random start mixed into a warm start.", "",
       Range::closed(0, 1000)});
    v(&CliqueParams::warm_start_penalty,
      {"warm_start_penalty",
       "Cascaded: a warm-started level begins with this fraction of the previous level's final "
       "penalty d (1: where it stopped; 0: from d = 0).",
       "", Range::closed(0, 1)});
    v(&CliqueParams::exact_max_nodes,
      {"exact_max_nodes",
       "Exact solver: branch-and-bound nodes over all levels, at most (a node whose reductions do "
       "the work of several counts as several).",
       "", Range::closed(1, 1e10), std::numeric_limits<double>::quiet_NaN(), true});
    v(&CliqueParams::exact_time_budget_ms,
      {"exact_time_budget_ms",
       "Exact solver: wall time of all levels, at most (a level may use what earlier ones left); "
       "the best clique found is returned, marked not proven, with the bound reached; 0: none.",
       "ms", Range::closed(1, 3.6e6), 0.0, true});
    v(&CliqueParams::greedy_starts,
      {"greedy_starts",
       "Greedy cliques grown from the highest cores for the pruning's bound (prove_first's search "
       "on a warm level starts from the previous level's clique grown instead; the relaxation "
       "still grows them).",
       "", Range::closed(1, 1000)});
    v(&CliqueParams::max_swaps,
      {"max_swaps", "Improving swaps (one member out, two in) tried on the rounded clique.", "",
       Range::closed(0, 100000)});
    v(&CliqueParams::pair_time_budget_ms,
      {"pair_time_budget_ms",
       "Wall time one registration may take up to the end of its clique step, from the start of "
       "the run; the clique search gets what is left, and when it runs out each unfinished level "
       "keeps the best clique found so far (its budget reads 'time'); 0: none.",
       "ms", Range::closed(1, 3.6e6), 0.0, true});
    v(&CliqueParams::cascade_fallback,
      {"cascade_fallback",
       "Cascaded: a warm-started level whose clique its check (a colouring, then the search of "
       "cascade_check_nodes) does not prove maximum is also solved from the cold start; the "
       "larger clique is kept (start 'fallback' when it wins)."});
    v(&CliqueParams::cascade_check_nodes,
      {"cascade_check_nodes",
       "Cascaded: node budget of the exact search for a larger clique that ends each "
       "warm-started level (a node whose reductions do the work of several counts as several); "
       "0: no search.",
       "", Range::closed(0, 1e10), std::numeric_limits<double>::quiet_NaN(), true});
    v(&CliqueParams::max_step,
      {"max_step", "The largest gradient step tried; beyond it a step only renormalises.", "",
       Range::above(0, 1e12), std::numeric_limits<double>::quiet_NaN(), true});
  }
};

/// The clique found on one level.
struct CliqueResult {
  int level = 0;
  std::vector<int> vertices;  ///< clique members (correspondence indices), increasing
  std::vector<double> u;      ///< final relaxation vector (empty for the exact solver)
  int gradient_steps = 0;     ///< accepted and rejected gradient steps, over all penalties
  int penalty_updates = 0;    ///< outer iterations (increases of d)
  double penalty = 0.0;       ///< final penalty d
  /// whether the clique is proven maximum on its level: the exact solver's search, or a cascaded
  /// level's search for a larger clique, finished within its budget
  bool proven = false;
  /// an upper bound on the level's clique number that the search reached (the clique's size when
  /// proven; 0 when no bound was computed)
  int clique_number_bound = 0;
  CliqueBudget budget = CliqueBudget::none;  ///< which budget cut a search short
  CliqueStart start = CliqueStart::cold;     ///< how the level's search started
  double time_ms = 0.0;                      ///< wall time [ms]
};

/// CLIPPER relaxation on level `level` from `u0` (any non-negative vector of the graph's size; it
/// is normalised; an all-zero or empty one means the seeded random start). With `params.prune`,
/// the relaxation runs on the k-core that can hold a clique as large as a lower bound —
/// `known_clique` (if it is a clique on this level) grown to a maximal clique, or greedy cliques
/// from the highest degrees if they are larger — and the answer is never smaller than that
/// bound; when that core is itself a clique it is the answer and no gradient step is taken.
/// `d0` is the initial penalty (a warm start may carry part of the previous level's).
/// Wall-clock instant after which a search stops with what it has (time_point::max(): never).
using Deadline = std::chrono::steady_clock::time_point;
inline constexpr Deadline kNoDeadline = Deadline::max();

CliqueResult solve_clipper(const PyramidGraph& graph, int level, const std::vector<double>& u0,
                           const CliqueParams& params, const std::vector<int>& known_clique = {},
                           double d0 = 0.0, Deadline deadline = kNoDeadline);

/// The seeded random start of the relaxation (uniform in (0, 1], normalised).
std::vector<double> random_start(int size, std::uint64_t seed);

/// Exact maximum clique on level `level`: one subproblem per vertex of the core that can hold a
/// larger clique than the best so far (the vertex and its later neighbours in the degeneracy
/// order), each solved by branch and bound on bitsets with greedy-colouring bounds, or, when it is
/// near-complete, as a maximum independent set of its sparse complement. Anytime: when the node
/// budget (`params.exact_max_nodes`) or the time budget (`params.exact_time_budget_ms`) runs out
/// it returns the best clique so far with `proven = false`, the bound reached in
/// `clique_number_bound` and the budget in `budget`.
CliqueResult exact_max_clique(const PyramidGraph& graph, int level, const CliqueParams& params);

/// One clique per level, in level order, with the solver `params.solver` selects. After
/// `deadline` every search stops with the best clique it has (a level not yet started keeps its
/// lower bound: the previous level's clique grown, or greedy cliques), and its `budget` reads
/// `time`. With `threads` > 1 (cascaded), a level whose bounded proof fails solves its cold-start
/// fallback beside the warm relaxation: the same cliques, sooner (unless the deadline passes).
std::vector<CliqueResult> solve_pyramid(const PyramidGraph& graph, const CliqueParams& params,
                                        Deadline deadline = kNoDeadline, int threads = 1);

/// Whether every pair of `vertices` is adjacent at `level`.
bool is_clique(const PyramidGraph& graph, int level, const std::vector<int>& vertices);

}  // namespace pagor
