// Exact maximum clique: branch and bound on bitsets with greedy-colouring bounds (as in MCQ/MCS
// and San Segundo's BBMC), over subproblems taken in a core-based order (as in PMC).
//
// A clique larger than the best one so far lies in the |best|-core, and its vertex that comes
// first in the degeneracy order has all other members among its later neighbours. So each vertex
// v of that core is one subproblem: v and its later neighbours, pruned to the local core that can
// hold a larger clique, solved exactly on a bit-matrix. The degeneracy bounds each subproblem's
// size, which keeps the bit-matrices small even on large sparse graphs. Before any subproblem, a
// greedy colouring of that core that needs no more colours than |best| proves best maximum.

#include <algorithm>
#include <chrono>
#include <cstdint>

#include "graph/bit_graph.hpp"
#include "graph/clique_graph.hpp"
#include "pagor/graph/densest_clique.hpp"

namespace pagor {
namespace {

// The subproblem of v: v's later neighbours in the degeneracy order that could be in a clique
// larger than `best`, pruned to the local (|best| - 1)-core. Returns the clique found (with v),
// or empty. When the budget stops it, `complete` becomes false and `bound` at least the bound on
// cliques through v it reached.
std::vector<int> solve_subproblem(const detail::LevelCsr& g, const detail::CoreDecomposition& cd,
                                  int v, int best, detail::SearchBudget& budget, bool& complete,
                                  int& bound, std::vector<int>& local) {
  std::vector<int> cand;
  const int pv = cd.position[static_cast<std::size_t>(v)];
  for (const int* w = g.begin(v); w != g.end(v); ++w)
    if (cd.position[static_cast<std::size_t>(*w)] > pv &&
        cd.core[static_cast<std::size_t>(*w)] >= best)
      cand.push_back(*w);
  // A clique with v larger than `best` needs `best` of these, each adjacent to best - 1 others.
  for (std::size_t before = 0; before != cand.size() && static_cast<int>(cand.size()) >= best;) {
    before = cand.size();
    for (std::size_t i = 0; i < cand.size(); ++i) local[static_cast<std::size_t>(cand[i])] = 1;
    std::vector<int> kept;
    for (int a : cand) {
      int d = 0;
      for (const int* w = g.begin(a); w != g.end(a); ++w)
        d += local[static_cast<std::size_t>(*w)] == 1;
      if (d >= best - 1) kept.push_back(a);
    }
    for (int a : cand) local[static_cast<std::size_t>(a)] = -1;
    cand.swap(kept);
  }
  if (static_cast<int>(cand.size()) < best) return {};
  // Local order: by core number, highest first (vertices coloured first get the low colours).
  std::stable_sort(cand.begin(), cand.end(), [&](int a, int b) {
    return cd.core[static_cast<std::size_t>(a)] > cd.core[static_cast<std::size_t>(b)];
  });
  const int n = static_cast<int>(cand.size());
  for (int i = 0; i < n; ++i)
    local[static_cast<std::size_t>(cand[static_cast<std::size_t>(i)])] = i;
  // The subproblem as bits (a near-complete one is searched on its sparse complement).
  detail::BitGraph local_graph(n);
  for (int i = 0; i < n; ++i)
    for (const int* w = g.begin(cand[static_cast<std::size_t>(i)]);
         w != g.end(cand[static_cast<std::size_t>(i)]); ++w) {
      const int j = local[static_cast<std::size_t>(*w)];
      if (j > i) local_graph.connect(i, j);
    }
  for (int a : cand) local[static_cast<std::size_t>(a)] = -1;
  bool finished = true;
  int sub_bound = 0;
  const std::vector<int> found =  // with v: larger than best
      detail::max_clique_bits(local_graph, best - 1, budget, finished, sub_bound);
  if (!finished) {
    complete = false;
    bound = std::max(bound, sub_bound + 1);
  }
  if (found.empty()) return {};
  std::vector<int> clique{v};
  for (int i : found) clique.push_back(cand[static_cast<std::size_t>(i)]);
  return clique;
}

// Whether a greedy colouring of the vertices that could be in a clique larger than `size` (core
// number at least `size`), taken from the end of the degeneracy order, needs no more than `size`
// colours: then every clique among them has at most `size` vertices, and none is larger.
bool colouring_proves(const detail::LevelCsr& g, const detail::CoreDecomposition& cd, int size) {
  const int n = g.size();
  std::vector<int> colour(static_cast<std::size_t>(n), -1),
      taken_by(static_cast<std::size_t>(n) + 1, -1);
  for (int i = n - 1; i >= 0; --i) {
    const int v = cd.order[static_cast<std::size_t>(i)];
    if (cd.core[static_cast<std::size_t>(v)] < size) continue;
    for (const int* w = g.begin(v); w != g.end(v); ++w)
      if (colour[static_cast<std::size_t>(*w)] >= 0)
        taken_by[static_cast<std::size_t>(colour[static_cast<std::size_t>(*w)])] = v;
    int c = 0;
    while (taken_by[static_cast<std::size_t>(c)] == v) ++c;
    if (c >= size) return false;  // a colour beyond `size`
    colour[static_cast<std::size_t>(v)] = c;
  }
  return true;
}

// The exact search from the clique `best`: one subproblem per vertex that could be in a larger
// one, from the end of the degeneracy order (the densest part first, where large cliques are).
// When the budget runs out, `optimal` is false and `bound` an upper bound on the clique number:
// the largest bound of an interrupted subproblem or core number + 1 of a vertex not searched.
std::vector<int> search_from(const detail::LevelCsr& csr, const detail::CoreDecomposition& cd,
                             std::vector<int> best, detail::SearchBudget& budget, bool& optimal,
                             int& bound) {
  optimal = true;
  bound = 0;
  if (!best.empty() && colouring_proves(csr, cd, static_cast<int>(best.size()))) {
    std::sort(best.begin(), best.end());
    bound = static_cast<int>(best.size());
    return best;
  }
  std::vector<int> local(static_cast<std::size_t>(csr.size()), -1);
  int i = csr.size() - 1;
  for (; i >= 0 && !budget.exhausted(); --i) {
    const int v = cd.order[static_cast<std::size_t>(i)];
    const int size = static_cast<int>(best.size());
    if (cd.core[static_cast<std::size_t>(v)] < size) continue;  // in no clique larger than best
    std::vector<int> c = solve_subproblem(csr, cd, v, size, budget, optimal, bound, local);
    if (c.size() > best.size()) best = std::move(c);
  }
  for (; i >= 0; --i) {  // not searched: a clique through v has at most core(v) + 1 vertices
    const int c = cd.core[static_cast<std::size_t>(cd.order[static_cast<std::size_t>(i)])];
    if (c >= static_cast<int>(best.size())) {
      optimal = false;
      bound = std::max(bound, c + 1);
    }
  }
  bound = std::max(bound, static_cast<int>(best.size()));
  std::sort(best.begin(), best.end());
  return best;
}

}  // namespace

std::vector<int> detail::larger_clique(const PyramidGraph& g, int level, std::vector<int> best,
                                       long max_nodes, bool& optimal, int* bound) {
  optimal = true;
  if (bound) *bound = static_cast<int>(best.size());
  if (g.vertices == 0) return best;
  const detail::LevelCsr csr = detail::level_csr(g, level);
  detail::SearchBudget budget;
  budget.max_nodes = max_nodes > 0 ? max_nodes : -1;
  if (max_nodes <= 0) budget.out_of_nodes = true;  // no search: only the colouring's proof
  int reached = 0;
  best =
      search_from(csr, detail::core_decomposition(csr), std::move(best), budget, optimal, reached);
  if (bound) *bound = reached;
  return best;
}

CliqueResult detail::exact_level(const PyramidGraph& g, int level, const CliqueParams& p,
                                 SearchBudget& budget) {
  const auto t0 = std::chrono::steady_clock::now();
  CliqueResult r;
  r.level = level;
  r.optimal = true;
  if (g.vertices > 0) {
    const detail::LevelCsr csr = detail::level_csr(g, level);
    const detail::CoreDecomposition cd = detail::core_decomposition(csr);
    detail::Marks marks(g.vertices);
    r.vertices =
        search_from(csr, cd, detail::greedy_clique(csr, cd.core, p.greedy_starts * 8, marks),
                    budget, r.optimal, r.upper_bound);
  }
  r.budget = r.optimal            ? CliqueBudget::none
             : budget.out_of_time ? CliqueBudget::time
                                  : CliqueBudget::nodes;
  r.time_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

CliqueResult exact_max_clique(const PyramidGraph& g, int level, const CliqueParams& p) {
  detail::SearchBudget budget;
  budget.max_nodes = p.exact_max_nodes;
  if (p.exact_time_budget_ms > 0)
    budget.deadline = detail::SearchBudget::Clock::now() +
                      std::chrono::microseconds(static_cast<long>(p.exact_time_budget_ms * 1000));
  return detail::exact_level(g, level, p, budget);
}

}  // namespace pagor
