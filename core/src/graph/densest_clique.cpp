#include "pagor/graph/densest_clique.hpp"

#include "graph/bit_graph.hpp"
#include "graph/clique_graph.hpp"
#include "graph/dense_level.hpp"
#include "graph/relaxation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <future>
#include <numeric>
#include <random>

namespace pagor {
namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

}  // namespace

std::vector<double> random_start(int size, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> dist(1e-3, 1.0);
  std::vector<double> u(static_cast<std::size_t>(size));
  for (double& x : u) x = dist(rng);
  detail::project(u);
  return u;
}

bool is_clique(const PyramidGraph& g, int level, const std::vector<int>& vertices) {
  for (std::size_t a = 0; a < vertices.size(); ++a)
    for (std::size_t b = a + 1; b < vertices.size(); ++b)
      if (!g.adjacent(vertices[a], vertices[b], level)) return false;
  return true;
}

namespace {

// The relaxation's optimum on a clique: its indicator vector, normalised (a warm start's u).
std::vector<double> indicator(int size, const std::vector<int>& clique) {
  std::vector<double> u(static_cast<std::size_t>(size), 0.0);
  for (int v : clique) u[static_cast<std::size_t>(v)] = 1.0 / std::sqrt(double(clique.size()));
  return u;
}

// Which cliques make a level's lower bound: the known clique grown and greedy cliques (what the
// relaxation prunes by), or the known clique grown alone when it is one (a proof's start).
enum class LowerBound { known_and_greedy, known_or_greedy };

// A lower bound on the level's clique number: the known clique (if it is one here) grown to a
// maximal one, then (unless `kind` lets the known clique stand alone) greedy cliques from the
// highest degrees that are not in it (a cheap search when the known clique is already large).
template <class Graph>
std::vector<int> lower_bound(const Graph& view, const std::vector<int>& deg,
                             const std::vector<int>& known_clique, const CliqueParams& p,
                             detail::Marks& marks, LowerBound kind = LowerBound::known_and_greedy) {
  std::vector<int> lower;
  if (!known_clique.empty() && detail::is_clique(view, known_clique, marks))
    lower = detail::extend_clique(view, known_clique, deg, static_cast<int>(known_clique.size()),
                                  marks);
  if (kind == LowerBound::known_or_greedy && !lower.empty()) return lower;
  return detail::greedy_clique(view, deg, p.greedy_starts, marks, std::move(lower));
}

// Whether prove_first runs on `level` of g.
bool proves_first(const PyramidGraph& g, int level, const CliqueParams& p) {
  return p.prove_first && g.affinity == AffinityKind::binary && g.vertices > 0 &&
         !(static_cast<std::size_t>(level) < g.edges_at_level.size() &&
           static_cast<long>(g.edges_at_level[static_cast<std::size_t>(level)]) <
               p.prove_first_min_edges);
}

// What a bounded search of a level found without proving it: its largest clique, the upper bound
// it reached and whether its deadline (not its node budget) stopped it.
struct UnprovenSearch {
  bool ran = false;
  std::vector<int> clique;
  int bound = 0;
  bool late = false;
};

// prove_first: the lower bound's clique, when a bounded exact search proves it maximum (then the
// relaxation cannot return a larger one); `r` is left untouched otherwise, and `unproven` tells
// what the search found. `bits`, if given, holds the level's bit rows (from levels_bits).
//
// A warm level's search starts from the previous level's clique grown, without the cold start's
// greedy cliques: the search returns a maximum clique from either start, and the greedy cliques
// cost more than they shorten it (bench/README.md, issue 22's sixth part). A level that is not
// proven goes on to the relaxation, which computes its lower bound with them.
bool proven_without_relaxation(const PyramidGraph& g, int level, const CliqueParams& p,
                               const std::vector<int>& known_clique, double d0, CliqueResult& r,
                               Deadline deadline, const detail::BitGraph* bits,
                               UnprovenSearch& unproven) {
  if (!proves_first(g, level, p)) return false;
  detail::Marks marks(g.vertices);
  bool proven = false, late = false;
  int bound = 0;
  std::vector<int> lower;
  if (bits || detail::dense_level(g, level)) {
    // The same steps on the level's bit rows (dense_level.hpp), with the same clique, bound and
    // search; before the search, a colouring seeded by the bound's clique may prove it (then a
    // level is proven that the search might not prove within cascade_check_nodes).
    detail::BitGraph own;
    if (!bits) {
      own = detail::level_bits(g, level);
      bits = &own;
    }
    const std::vector<int> deg = detail::degrees(*bits);
    lower = lower_bound(*bits, deg, known_clique, p, marks, LowerBound::known_or_greedy);
    const std::vector<int> keep = detail::k_core(*bits, deg, static_cast<int>(lower.size()));
    if (detail::colouring_from_clique_proves(*bits, keep, lower)) {
      proven = true;
      bound = static_cast<int>(lower.size());
      std::sort(lower.begin(), lower.end());
    } else {
      lower = detail::larger_clique_in(detail::CoreView(*bits, keep), std::move(lower),
                                       p.cascade_check_nodes, proven, &bound, deadline, &late);
    }
  } else {
    const detail::PyramidLevel view{g, level};
    lower = lower_bound(view, detail::level_degrees(g, level), known_clique, p, marks,
                        LowerBound::known_or_greedy);
    lower = detail::larger_clique(g, level, std::move(lower), p.cascade_check_nodes, proven, &bound,
                                  deadline, &late);
  }
  if (!proven) {
    unproven = {true, std::move(lower), bound, late};
    return false;
  }
  r.level = level;
  r.vertices = std::move(lower);
  r.proven = true;
  r.clique_number_bound = bound;
  r.start = known_clique.empty() ? CliqueStart::cold : CliqueStart::warm;
  r.penalty = d0;  // no relaxation ran: the next warm level starts from the same penalty
  r.u = indicator(g.vertices, r.vertices);  // the next level's start
  return true;
}

// The relaxation on one level (solve_clipper without the warm level's checks); no timing.
CliqueResult relax_level(const PyramidGraph& g, int level, const std::vector<double>& u0,
                         const CliqueParams& p, const std::vector<int>& known_clique, double d0,
                         Deadline deadline) {
  CliqueResult r;
  r.level = level;
  if (g.vertices == 0) return r;
  const std::size_t n = static_cast<std::size_t>(g.vertices);
  const detail::PyramidLevel view{g, level};
  detail::Marks marks(g.vertices);
  const bool warm = u0.size() == n && !known_clique.empty();
  r.start = warm ? CliqueStart::warm : CliqueStart::cold;

  // Which vertices the relaxation works on: all, or the core that can hold a clique at least as
  // large as a lower bound: the known clique grown to a maximal one, else greedy cliques.
  std::vector<int> lower, keep;
  if (p.prune) {
    const std::vector<int> deg = detail::level_degrees(g, level);
    lower = lower_bound(view, deg, known_clique, p, marks);
    keep = detail::k_core(view, deg, static_cast<int>(lower.size()) - 1,
                          [&](int v) { return view.row_length(v); });
  } else {
    keep.resize(n);
    std::iota(keep.begin(), keep.end(), 0);
  }
  detail::LevelGraph sub = detail::induce(g, level, keep);
  r.u.assign(n, 0.0);
  if (p.prune && sub.complete()) {
    // The core is itself a clique: it is the answer, and the relaxation's optimum is its
    // indicator vector.
    r.vertices = keep;
    r.u = indicator(g.vertices, keep);
    r.proven = true;
    r.clique_number_bound = static_cast<int>(keep.size());
    return r;
  }
  detail::set_weights(sub, g, level);

  // Start vector restricted to the kept vertices; the seeded random start if nothing is left.
  std::vector<double> u(sub.size());
  // A warm start gets a little of the random start mixed in, so that vertices it left at zero
  // start above zero.
  const std::vector<double> start = random_start(g.vertices, p.seed);
  const bool from_u0 = u0.size() == n;
  for (std::size_t i = 0; i < sub.size(); ++i) {
    const auto v = static_cast<std::size_t>(sub.ids[i]);
    u[i] = from_u0 ? u0[v] + p.warm_start_mix * start[v] : 0.0;
  }
  if (!detail::project(u)) {
    for (std::size_t i = 0; i < sub.size(); ++i) u[i] = start[static_cast<std::size_t>(sub.ids[i])];
    detail::project(u);
  }

  const std::vector<int> local =
      sub.size() > 0 ? detail::relax(sub, u, d0, p, r, deadline) : std::vector<int>{};
  for (std::size_t i = 0; i < sub.size(); ++i) r.u[static_cast<std::size_t>(sub.ids[i])] = u[i];
  std::vector<int> found;
  for (int v : local) found.push_back(sub.ids[static_cast<std::size_t>(v)]);
  // Rounding keeps round(u^T C u) entries; vertices adjacent to all of them join, largest u first.
  if (!found.empty()) found = detail::extend_clique(view, found, r.u, 0.0, marks);
  r.vertices = found.size() >= lower.size() ? found : lower;  // never worse than the lower bound
  r.vertices = detail::improve_by_swaps(view, std::move(r.vertices), marks, p.max_swaps);
  return r;
}

}  // namespace

namespace {

// The cascade's fallback: the level solved from the cold start, as the independent solver does.
CliqueResult cold_start(const PyramidGraph& g, int level, const CliqueParams& p,
                        Deadline deadline) {
  return relax_level(g, level, random_start(g.vertices, p.seed), p, {}, 0.0, deadline);
}

// The end of a warm level the relaxation left unproven, or of any level settle_level finishes: a
// bounded search for a larger clique (cascade_check_nodes), then, unless that proves the clique
// maximum and with `fallback`, the level solved from the cold start, the larger clique kept.
// `searched`, if it ran, is prove_first's search of the same budget; `early`, if valid, the cold
// start already under way on another thread.
void check_level(const PyramidGraph& g, int level, const CliqueParams& p, CliqueResult& r,
                 Deadline deadline, const UnprovenSearch& searched, bool fallback,
                 std::future<CliqueResult>* early) {
  // A warm start can settle in a worse local optimum than a cold one (KITTI 20 -> 30, level 2:
  // 29 against 30; gedi-dev 03, level 2: 66 against 68). A warm level therefore ends with a
  // bounded exact search for a larger clique (cheap here: the clique found prunes every vertex
  // whose core number is below its size; a greedy colouring may prove it maximum at once). Unless
  // that proves the clique maximum, the level is also solved from the cold start, exactly as the
  // independent solver does, and the larger clique is kept: the cascade never loses to it.
  // Where prove_first's search of this level already ran out of the same budget and the
  // relaxation found no larger clique than it did, the search is not run again from a clique no
  // larger than its own (on the densest levels it found no proof the second time either, and was
  // a quarter of the time): its largest clique and bound stand in. A larger clique from the
  // relaxation prunes more: then the search runs from it, and often proves it at once.
  bool late = false;
  if (searched.ran && r.vertices.size() <= searched.clique.size()) {
    if (searched.clique.size() > r.vertices.size()) r.vertices = searched.clique;
    r.clique_number_bound = searched.bound;
    r.proven = static_cast<int>(r.vertices.size()) >= searched.bound;
    late = searched.late;
  } else {
    r.vertices = detail::larger_clique(g, level, std::move(r.vertices), p.cascade_check_nodes,
                                       r.proven, &r.clique_number_bound, deadline, &late);
  }
  // 0 nodes: the colouring's proof only
  if (!r.proven && (late || r.budget == CliqueBudget::time))
    r.budget = CliqueBudget::time;
  else if (!r.proven && p.cascade_check_nodes > 0)
    r.budget = CliqueBudget::nodes;
  if (!r.proven && fallback && r.budget != CliqueBudget::time) {
    CliqueResult cold = early && early->valid() ? early->get() : cold_start(g, level, p, deadline);
    if (cold.budget == CliqueBudget::time) r.budget = CliqueBudget::time;
    r.gradient_steps += cold.gradient_steps;
    r.penalty_updates += cold.penalty_updates;
    if (cold.vertices.size() > r.vertices.size()) {
      r.vertices = std::move(cold.vertices);
      r.u = std::move(cold.u);  // the next level starts from where the cold start ended
      r.penalty = cold.penalty;
      r.start = CliqueStart::fallback;
    }
  }
}

// solve_clipper, given the level's bit rows if solve_pyramid built them. With `threads` > 1, a
// warm level whose bounded proof failed (the fallback will most likely run) starts the fallback
// beside the warm relaxation on a second thread; it is used only where it would have run, so the
// result is the same (unless the deadline passes meanwhile).
CliqueResult solve_level(const PyramidGraph& g, int level, const std::vector<double>& u0,
                         const CliqueParams& p, const std::vector<int>& known_clique, double d0,
                         Deadline deadline, const detail::BitGraph* bits, int threads = 1,
                         bool first_pass = false) {
  const auto t0 = Clock::now();
  CliqueResult r;
  UnprovenSearch searched;
  if (proven_without_relaxation(g, level, p, known_clique, d0, r, deadline, bits, searched)) {
    r.time_ms = ms_since(t0);
    return r;
  }
  if (first_pass && searched.ran && !searched.late) {
    // settle_selected's first pass: a level its bounded proof could not settle keeps that
    // search's clique, improved by swaps; its relaxation is left to settle_level (on the densest
    // levels it is most of the level's time, and the level is seldom the one selected).
    detail::Marks marks(g.vertices);
    r.level = level;
    r.vertices = detail::improve_by_swaps(detail::PyramidLevel{g, level},
                                          std::move(searched.clique), marks, p.max_swaps);
    std::sort(r.vertices.begin(), r.vertices.end());
    r.clique_number_bound = std::max(searched.bound, static_cast<int>(r.vertices.size()));
    r.start = known_clique.empty() ? CliqueStart::cold : CliqueStart::warm;
    r.penalty = d0;
    r.u = indicator(g.vertices, r.vertices);
    // The swaps may reach the search's bound: then the clique is proven maximum.
    r.proven = static_cast<int>(r.vertices.size()) >= searched.bound;
    r.budget = r.proven ? CliqueBudget::none : CliqueBudget::nodes;
    r.relaxed = r.proven;  // a maximum clique needs no relaxation
    r.time_ms = ms_since(t0);
    return r;
  }
  const bool warm = p.prune && !known_clique.empty() && g.vertices > 0;
  std::future<CliqueResult> early;
  if (threads > 1 && warm && searched.ran && p.cascade_fallback)
    early = std::async(std::launch::async, [&] { return cold_start(g, level, p, deadline); });
  r = relax_level(g, level, u0, p, known_clique, d0, deadline);
  if (warm && !r.proven)
    check_level(g, level, p, r, deadline, searched, p.cascade_fallback, &early);
  if (r.proven) r.budget = CliqueBudget::none;  // proven maximum: no budget cost it anything
  r.time_ms = ms_since(t0);
  return r;
}

}  // namespace

CliqueResult solve_clipper(const PyramidGraph& g, int level, const std::vector<double>& u0,
                           const CliqueParams& p, const std::vector<int>& known_clique, double d0,
                           Deadline deadline) {
  return solve_level(g, level, u0, p, known_clique, d0, deadline, nullptr);
}

namespace {

// A level started after the deadline: its lower bound only (the known clique grown, or greedy
// cliques), not proven, budget `time`.
CliqueResult lower_bound_only(const PyramidGraph& g, int level, const CliqueParams& p,
                              const std::vector<int>& known_clique) {
  const auto t0 = Clock::now();
  CliqueResult r;
  r.level = level;
  r.budget = CliqueBudget::time;
  r.start = known_clique.empty() ? CliqueStart::cold : CliqueStart::warm;
  if (g.vertices > 0) {
    detail::Marks marks(g.vertices);
    r.vertices = lower_bound(detail::PyramidLevel{g, level}, detail::level_degrees(g, level),
                             known_clique, p, marks);
    r.u = indicator(g.vertices, r.vertices);
  }
  r.time_ms = ms_since(t0);
  return r;
}

}  // namespace

namespace {

// A first pass's level that settle_level would search on: unproven, not stopped by time, and
// either warm (the check and the fallback) or one whose bounded proof ran (a cold level's).
void mark_unsettled(const PyramidGraph& g, const CliqueParams& p, CliqueResult& r) {
  const bool warm = p.prune && r.start != CliqueStart::cold;  // as solve_level's check
  if (r.proven || r.budget == CliqueBudget::time || !(warm || proves_first(g, r.level, p))) return;
  r.settled = false;
  r.budget = CliqueBudget::probe;
}

}  // namespace

CliqueResult settle_level(const PyramidGraph& g, CliqueResult r, const CliqueParams& p,
                          Deadline deadline, int threads) {
  if (r.settled) return r;
  const auto t0 = Clock::now();
  const bool warm = p.prune && r.start != CliqueStart::cold;  // as solve_level's
  if (!r.relaxed) {
    // The first step: the relaxation, warm from the level's clique (the previous level's grown)
    // or, for a cold level, from the cold start; the larger clique is kept. A level that then
    // loses the selection is left here.
    CliqueResult relaxed = r.start != CliqueStart::cold
                               ? relax_level(g, r.level, r.u, p, r.vertices, r.penalty, deadline)
                               : cold_start(g, r.level, p, deadline);
    r.relaxed = true;
    r.gradient_steps = relaxed.gradient_steps;
    r.penalty_updates = relaxed.penalty_updates;
    if (relaxed.vertices.size() > r.vertices.size()) {
      r.vertices = std::move(relaxed.vertices);
      r.u = std::move(relaxed.u);
      r.penalty = relaxed.penalty;
    }
    if (relaxed.proven && r.vertices.size() >= relaxed.vertices.size()) {
      r.proven = true;  // the core the relaxation kept was a clique
      r.clique_number_bound = static_cast<int>(r.vertices.size());
    }
    if (relaxed.budget == CliqueBudget::time) r.budget = CliqueBudget::time;
    r.settled = r.proven || r.budget == CliqueBudget::time;
    if (r.proven) r.budget = CliqueBudget::none;
    r.time_ms += ms_since(t0);
    return r;
  }
  r.budget = CliqueBudget::none;
  // A warm level gets its check and fallback; a cold one the search its proof would have made.
  // With two threads the fallback starts beside the search; it is used only where it would run.
  const bool fallback = warm && p.cascade_fallback;
  std::future<CliqueResult> early;
  if (threads > 1 && fallback)
    early = std::async(std::launch::async, [&g, &p, deadline, level = r.level] {
      return cold_start(g, level, p, deadline);
    });
  check_level(g, r.level, p, r, deadline, UnprovenSearch{}, fallback, &early);
  if (r.proven) r.budget = CliqueBudget::none;
  r.settled = true;
  r.time_ms += ms_since(t0);
  return r;
}

std::vector<int> clique_through(const PyramidGraph& g, int level, const std::vector<int>& anchors,
                                long max_nodes) {
  std::vector<int> valid;
  for (int a : anchors)
    if (a >= 0 && a < g.vertices && std::find(valid.begin(), valid.end(), a) == valid.end())
      valid.push_back(a);
  if (valid.empty()) return {};
  // The largest subset of the anchors that is a clique: every subset of a few, else greedily in
  // their order.
  std::vector<int> chosen;
  const auto subset_clique = [&](const std::vector<int>& s) {
    for (std::size_t i = 0; i < s.size(); ++i)
      for (std::size_t j = i + 1; j < s.size(); ++j)
        if (!g.adjacent(s[i], s[j], level)) return false;
    return true;
  };
  if (valid.size() <= 12) {
    const unsigned all = 1u << valid.size();
    for (unsigned mask = 1; mask < all; ++mask) {
      if (__builtin_popcount(mask) <= static_cast<int>(chosen.size())) continue;
      std::vector<int> s;
      for (std::size_t i = 0; i < valid.size(); ++i)
        if (mask & (1u << i)) s.push_back(valid[i]);
      if (subset_clique(s)) chosen = std::move(s);
    }
  } else {
    for (int a : valid) {
      chosen.push_back(a);
      if (!subset_clique(chosen)) chosen.pop_back();
    }
  }
  // Their common neighbours at this level, and a maximum clique among them.
  std::vector<int> count(static_cast<std::size_t>(g.vertices), 0);
  const detail::PyramidLevel view{g, level};
  for (int a : chosen)
    view.for_each_neighbor(a, [&](int w) { ++count[static_cast<std::size_t>(w)]; });
  std::vector<int> common;
  for (int v = 0; v < g.vertices; ++v)
    if (count[static_cast<std::size_t>(v)] == static_cast<int>(chosen.size())) common.push_back(v);
  if (common.size() > static_cast<std::size_t>(detail::kMaxLevelBits)) {
    // Bit rows for at most kMaxLevelBits of them (megabytes otherwise): those with most
    // neighbours at this level, where a large clique through the anchors lies.
    const std::vector<int> deg = detail::level_degrees(g, level);
    std::stable_sort(common.begin(), common.end(), [&](int a, int b) {
      return deg[static_cast<std::size_t>(a)] > deg[static_cast<std::size_t>(b)];
    });
    common.resize(static_cast<std::size_t>(detail::kMaxLevelBits));
    std::sort(common.begin(), common.end());
  }
  std::vector<int> out = chosen;
  if (!common.empty()) {
    std::vector<int> local(static_cast<std::size_t>(g.vertices), -1);
    const detail::BitGraph sub = detail::induce_bits(g, level, common, local);
    std::vector<int> found = detail::greedy_clique_bits(sub, 8);
    if (max_nodes > 0) {
      detail::SearchBudget budget;
      budget.max_nodes = max_nodes;
      bool complete = true;
      int bound = 0;
      // The search's clique where it finds one at least as large as the greedy one within its
      // budget (a maximum clique when it completes).
      std::vector<int> searched = detail::max_clique_bits(
          sub, std::max(0, static_cast<int>(found.size()) - 1), budget, complete, bound);
      if (searched.size() >= found.size()) found = std::move(searched);
    }
    for (int k : found) out.push_back(common[static_cast<std::size_t>(k)]);
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<CliqueResult> solve_pyramid(const PyramidGraph& g, const CliqueParams& p,
                                        Deadline deadline, int threads) {
  const auto t0 = Clock::now();
  // settle_selected: a first pass with probe_nodes and no fallback (settle_level does the rest).
  const bool first_pass = p.settle_selected && p.solver == CliqueSolver::cascaded;
  CliqueParams pass = p;
  if (first_pass) {
    pass.cascade_check_nodes = p.probe_nodes;
    pass.cascade_fallback = false;
  }
  std::vector<CliqueResult> out;
  const std::vector<double> start = random_start(g.vertices, p.seed);
  // The exact solver's budgets hold for the whole pyramid: the nodes are shared, and level l may
  // run until (l + 1) / levels of the time budget has passed (what a level leaves, the next gets).
  detail::SearchBudget budget;
  budget.max_nodes = p.exact_max_nodes;
  // The dense levels that prove first get their bit rows from one pass over the pyramid's rows
  // (the levels from the first such on: density and edges grow with the level).
  std::vector<detail::BitGraph> bits;
  if (p.solver != CliqueSolver::exact) {
    int first = 0;
    while (first < g.levels() && !(proves_first(g, first, p) && detail::dense_level(g, first)))
      ++first;
    bits = detail::levels_bits(g, first);
  }
  const auto bits_of = [&](int l) {
    return static_cast<std::size_t>(l) < bits.size() && bits[static_cast<std::size_t>(l)].size() > 0
               ? &bits[static_cast<std::size_t>(l)]
               : nullptr;
  };
  for (int l = 0; l < g.levels(); ++l) {
    if (deadline != kNoDeadline && Clock::now() > deadline) {
      // Past the pair's budget: each remaining level keeps its lower bound (levels nest, so the
      // previous level's clique is one here).
      out.push_back(lower_bound_only(g, l, p, l > 0 ? out.back().vertices : std::vector<int>{}));
      continue;
    }
    switch (p.solver) {
      case CliqueSolver::exact:
        budget.deadline = deadline;
        if (p.exact_time_budget_ms > 0)
          budget.deadline =
              std::min(deadline, t0 + std::chrono::microseconds(static_cast<long>(
                                          1000.0 * p.exact_time_budget_ms * (l + 1) / g.levels())));
        budget.out_of_time = false;  // a level's share is its own
        // Level l-1's clique is a clique here too (levels nest): the search starts from it.
        out.push_back(
            detail::exact_level(g, l, p, budget, l > 0 ? out.back().vertices : std::vector<int>{}));
        break;
      case CliqueSolver::independent:
        out.push_back(solve_level(g, l, start, p, {}, 0.0, deadline, bits_of(l)));
        break;
      case CliqueSolver::cascaded:
        // First pass: above a level its probe could not settle, each level (a denser graph that
        // holds that level's) gets the colouring's proof alone. Its search would spend the same
        // budget on a harder graph: on the 20 generated dense problems of bench/peer, 6 of 8 such
        // levels were not proven either (25-65 ms each), and the two that were are not selected.
        if (first_pass && l > 0 && out.back().budget == CliqueBudget::probe)
          pass.cascade_check_nodes = 0;
        // Alg. 1: level l starts where level l-1 ended. Its edges are a subset of level l's, so its
        // clique is also a clique here: a lower bound for pruning.
        if (l == 0)
          out.push_back(
              solve_level(g, l, start, pass, {}, 0.0, deadline, bits_of(l), 1, first_pass));
        else
          out.push_back(solve_level(g, l, out.back().u, pass, out.back().vertices,
                                    p.warm_start_penalty * out.back().penalty, deadline, bits_of(l),
                                    threads, first_pass));
        if (first_pass) mark_unsettled(g, p, out.back());
        break;
    }
  }
  return out;
}

}  // namespace pagor
