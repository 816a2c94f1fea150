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
#include "pagor/params.hpp"
#include "pagor/util/fields.hpp"

namespace pagor {

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
  /// not settled (clique.settle_selected): the level's search had the first pass's budget
  /// (clique.probe_nodes; none, the colouring's proof alone, above a level left unsettled) and it
  /// got no full search or fallback; it was not selected (or lost after its relaxation), or its
  /// pose was the same answer as a settled level's
  probe,
};
inline constexpr EnumEntry<CliqueBudget> kCliqueBudgets[] = {
    {CliqueBudget::none, "none", "no search was cut short"},
    {CliqueBudget::nodes, "nodes", "a node budget ran out"},
    {CliqueBudget::time, "time", "the time budget ran out"},
    {CliqueBudget::probe, "probe",
     "not settled: the first pass's search only (clique.probe_nodes); no full search, no "
     "fallback"},
};
inline const auto& enum_entries(CliqueBudget) {
  return kCliqueBudgets;
}

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
  double time_ms = 0.0;                      ///< wall time [ms], settling included
  /// false: a first pass (clique.settle_selected) left the level unproven within probe_nodes and
  /// without its cold-start fallback; settle_level gives it the rest when the selection needs it
  bool settled = true;
  /// false: the first pass kept its bounded search's clique without running the relaxation
  /// (settle_level's first step runs it)
  bool relaxed = true;
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

/// One clique per level, in level order, with the solver `params.solver` selects. Cascaded with
/// `params.settle_selected`, this is a first pass: each level's bounded searches get
/// `params.probe_nodes` up to the first level they leave unproven, and the levels above it the
/// colouring's proof alone; a level whose bounded proof fails keeps that search's clique without
/// its relaxation (`relaxed` false), no cold-start fallback runs, and a level left unproven is
/// not `settled` (budget `probe`): settle_selection finishes the one the selection picks. After
/// `deadline` every search stops with the best clique it has (a level not yet started keeps its
/// lower bound: the previous level's clique grown, or greedy cliques), and its `budget` reads
/// `time`. With `threads` > 1 (cascaded), a level whose bounded proof fails solves its cold-start
/// fallback beside the warm relaxation: the same cliques, sooner (unless the deadline passes).
std::vector<CliqueResult> solve_pyramid(const PyramidGraph& graph, const CliqueParams& params,
                                        Deadline deadline = kNoDeadline, int threads = 1);

/// One step towards what the full cascade gives a level solve_pyramid's first pass left
/// unsettled: a level not yet relaxed gets its relaxation (warm from its clique, or the cold
/// start for a cold level) and stays unsettled unless that proves it; a relaxed one gets a
/// bounded search for a larger clique from its clique (`params.cascade_check_nodes`), then,
/// unless that proves it maximum, the cold-start fallback of a warm level (cascade_fallback),
/// and is settled. The clique never shrinks; the step's time is added. A settled level is
/// returned as it is. With `threads` > 1 the fallback runs beside the search (the same result).
CliqueResult settle_level(const PyramidGraph& graph, CliqueResult level, const CliqueParams& params,
                          Deadline deadline = kNoDeadline, int threads = 1);

/// The selection with settle_selected: `select()` selects among the levels' candidates and
/// returns the selected level (-1: none). While that level is unsettled and its candidate is not
/// the same answer as a settled level's (`same_answer(level)`: a heuristic, as settling it would
/// seldom change that answer),
/// it takes a settle_level step, and when its clique changed, `refit(level)` fits its candidate
/// again and the selection is re-run (a level that only won by its first pass's clique is then
/// often beaten before its costly search). Each level takes two steps at most. Returns the time
/// spent settling [ms].
template <class Select, class Refit, class SameAnswer>
double settle_selection(const PyramidGraph& graph, std::vector<CliqueResult>& cliques,
                        const CliqueParams& params, Deadline deadline, Select&& select,
                        Refit&& refit, SameAnswer&& same_answer, int threads = 1) {
  double ms = 0.0;
  int level = select();
  while (level >= 0 && !cliques[static_cast<std::size_t>(level)].settled && !same_answer(level)) {
    CliqueResult& c = cliques[static_cast<std::size_t>(level)];
    const std::vector<int> before = c.vertices;
    const double t0 = c.time_ms;
    c = settle_level(graph, std::move(c), params, deadline, threads);
    ms += c.time_ms - t0;
    if (c.vertices == before) continue;  // the same clique: the same candidate and selection
    refit(level);
    level = select();
  }
  return ms;
}

/// Whether every pair of `vertices` is adjacent at `level`.
bool is_clique(const PyramidGraph& graph, int level, const std::vector<int>& vertices);

/// A largest clique of `level` through `anchors`: the largest subset of them that is a clique
/// there (the first such in their order), with a maximum clique of that subset's common
/// neighbours, searched within `max_nodes` (when it runs out, the larger of its best clique and a
/// greedy one; 0: the greedy one alone) among the 8,192 of them with most neighbours there.
/// Sorted; empty when no anchor is a vertex of the graph. A correspondence seen once on each side
/// (a car, a sign) fixes which repetition of a corridor or a street a pose takes, where the densest
/// clique can sit on a whole period's worth of identical pillars instead
/// (Pipeline::anchored_alternatives).
std::vector<int> clique_through(const PyramidGraph& graph, int level,
                                const std::vector<int>& anchors, long max_nodes);

}  // namespace pagor
