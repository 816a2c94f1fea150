#include <algorithm>
#include <catch2/catch.hpp>
#include <chrono>
#include <numeric>
#include <random>

#include "graph/bit_graph.hpp"
#include "graph/clique_graph.hpp"
#include "pagor/graph/densest_clique.hpp"
#include "support/clique_reference.hpp"
#include "support/test_util.hpp"

using namespace pagor;
using test::random_graph;

namespace {

// Core numbers from the definition: the largest k such that v is in the k-core, each k-core
// found by peeling vertices of degree < k until none is left.
std::vector<int> core_numbers_by_definition(const detail::LevelCsr& g) {
  const int n = g.size();
  std::vector<int> core(static_cast<std::size_t>(n), 0);
  for (int k = 1; k <= n; ++k) {
    std::vector<char> in(static_cast<std::size_t>(n), 1);
    for (bool changed = true; changed;) {
      changed = false;
      for (int v = 0; v < n; ++v) {
        if (!in[static_cast<std::size_t>(v)]) continue;
        int d = 0;
        for (const int* w = g.begin(v); w != g.end(v); ++w) d += in[static_cast<std::size_t>(*w)];
        if (d < k) {
          in[static_cast<std::size_t>(v)] = 0;
          changed = true;
        }
      }
    }
    bool any = false;
    for (int v = 0; v < n; ++v)
      if (in[static_cast<std::size_t>(v)]) {
        core[static_cast<std::size_t>(v)] = k;
        any = true;
      }
    if (!any) break;
  }
  return core;
}

// A level's search that its node budget cut short: not proven, says so, and still returns a
// clique of level 0 under a bound no smaller than it.
void check_cut_by_nodes(const PyramidGraph& g, const CliqueResult& r) {
  CHECK_FALSE(r.proven);
  CHECK(r.budget == CliqueBudget::nodes);
  CHECK(is_clique(g, 0, r.vertices));
  CHECK_FALSE(r.vertices.empty());
  CHECK(r.clique_number_bound >= static_cast<int>(r.vertices.size()));
}

}  // namespace

TEST_CASE("core numbers, degeneracy order and k-cores agree with their definitions") {
  for (std::uint64_t seed = 0; seed < 10; ++seed) {
    const PyramidGraph g =
        random_graph(70, 0.04 * static_cast<double>(seed % 5 + 1), static_cast<int>(seed), seed);
    const detail::LevelCsr csr = detail::level_csr(g, 0);
    const detail::CoreDecomposition cd = detail::core_decomposition(csr);
    const std::vector<int> expected = core_numbers_by_definition(csr);
    CHECK(cd.core == expected);
    CHECK(cd.degeneracy == *std::max_element(expected.begin(), expected.end()));
    // In the degeneracy order each vertex has at most `degeneracy` later neighbours, and the
    // position map is the order's inverse.
    for (int i = 0; i < csr.size(); ++i) {
      const int v = cd.order[static_cast<std::size_t>(i)];
      CHECK(cd.position[static_cast<std::size_t>(v)] == i);
      int later = 0;
      for (const int* w = csr.begin(v); w != csr.end(v); ++w)
        later += cd.position[static_cast<std::size_t>(*w)] > i;
      CHECK(later <= cd.core[static_cast<std::size_t>(v)]);
    }
    // k-cores peeled on the CSR and on the pyramid graph read in place.
    std::vector<int> deg;
    for (int v = 0; v < csr.size(); ++v) deg.push_back(csr.degree(v));
    CHECK(detail::level_degrees(g, 0) == deg);
    for (int k : {1, 2, 3, 5}) {
      std::vector<int> by_core;
      for (int v = 0; v < csr.size(); ++v)
        if (expected[static_cast<std::size_t>(v)] >= k) by_core.push_back(v);
      CHECK(detail::k_core(csr, deg, k) == by_core);
      CHECK(detail::k_core(detail::PyramidLevel{g, 0}, deg, k) == by_core);
      // Recounting the survivors first (when their rows are the shorter walk) gives the same.
      CHECK(detail::k_core(csr, deg, k, [](int) { return std::size_t{1}; }) == by_core);
      CHECK(detail::k_core(csr, deg, k, [&](int v) {
              return std::size_t(deg[std::size_t(v)] < k ? 100 : 1);
            }) == by_core);
    }
  }
}

TEST_CASE("a level's CSR holds exactly the edges of that level") {
  const auto c = test::association(150, 15, 3);
  const PyramidGraph g = build_pyramid_graph(c, test::association_params());
  for (int l = 0; l < g.levels(); ++l) {
    const detail::LevelCsr csr = detail::level_csr(g, l);
    CHECK(csr.neighbors.size() == 2 * g.edges_at_level[static_cast<std::size_t>(l)]);
    for (int v = 0; v < g.vertices; ++v)
      for (const int* w = csr.begin(v); w != csr.end(v); ++w) CHECK(g.adjacent(v, *w, l));
  }
}

TEST_CASE("greedy and extended cliques are maximal cliques") {
  for (std::uint64_t seed = 0; seed < 8; ++seed) {
    const PyramidGraph g = random_graph(120, 0.2, 10, seed);
    const detail::LevelCsr csr = detail::level_csr(g, 0);
    const detail::CoreDecomposition cd = detail::core_decomposition(csr);
    detail::Marks marks(g.vertices);
    const detail::PyramidLevel view{g, 0};
    const std::vector<int> one{static_cast<int>(seed)};
    const std::vector<std::vector<int>> cliques = {
        detail::greedy_clique(csr, cd.core, 8, marks),
        detail::greedy_clique(view, detail::level_degrees(g, 0), 8, marks),
        detail::extend_clique(csr, one, cd.core, 0, marks),
        detail::extend_clique(view, one, cd.core, 0, marks)};
    for (const auto& c : cliques) {
      REQUIRE(is_clique(g, 0, c));
      CHECK(detail::is_clique(csr, c, marks));
      CHECK(detail::is_clique(view, c, marks));
      CHECK(std::is_sorted(c.begin(), c.end()));
      for (int v = 0; v < g.vertices; ++v) {  // nothing can join
        if (std::binary_search(c.begin(), c.end(), v)) continue;
        std::vector<int> bigger = c;
        bigger.push_back(v);
        std::sort(bigger.begin(), bigger.end());
        CHECK_FALSE(is_clique(g, 0, bigger));
      }
    }
  }
}

TEST_CASE("the exact solver agrees with brute force on small graphs") {
  CliqueParams cp;
  for (std::uint64_t seed = 0; seed < 40; ++seed) {
    const int n = 8 + static_cast<int>(seed % 10);
    const double p = 0.2 + 0.15 * static_cast<double>(seed % 5);
    const PyramidGraph g = random_graph(n, p, static_cast<int>(seed % 4), seed);
    INFO("seed " << seed << ", n " << n << ", p " << p);
    const CliqueResult r = exact_max_clique(g, 0, cp);
    CHECK(r.proven);
    CHECK(is_clique(g, 0, r.vertices));
    CHECK(r.vertices.size() == test::brute_force_clique(g));
    CHECK(r.clique_number_bound ==
          static_cast<int>(r.vertices.size()));  // proven: the bound is met
    CHECK(r.budget == CliqueBudget::none);
  }
}

TEST_CASE("the exact solver agrees with plain branch and bound on larger graphs") {
  // Subproblems of more than 64 vertices use several words per bit row.
  CliqueParams cp;
  for (std::uint64_t seed = 0; seed < 12; ++seed) {
    const int n = 60 + 20 * static_cast<int>(seed % 5);
    const double p = 0.1 + 0.1 * static_cast<double>(seed % 4);
    const PyramidGraph g = random_graph(n, p, 5 + static_cast<int>(seed % 7) * 3, seed);
    INFO("seed " << seed << ", n " << n << ", p " << p);
    const CliqueResult r = exact_max_clique(g, 0, cp);
    CHECK(r.proven);
    CHECK(is_clique(g, 0, r.vertices));
    CHECK(r.vertices.size() == test::plain_max_clique(g, 0));
  }
  // A complete graph of 130 vertices: one subproblem of 129 vertices, three words per row.
  const PyramidGraph complete = random_graph(130, 0.0, 130, 1);
  CHECK(exact_max_clique(complete, 0, cp).vertices.size() == 130);
}

TEST_CASE("the exact solver agrees with plain branch and bound on association problems") {
  CliqueParams cp;
  const GraphParams gp = test::association_params();
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    const auto c = test::association(250, 25, seed);
    const PyramidGraph g = build_pyramid_graph(c, gp);
    for (int l = 0; l < g.levels(); ++l) {
      INFO("seed " << seed << ", level " << l);
      const CliqueResult r = exact_max_clique(g, l, cp);
      CHECK(r.proven);
      CHECK(is_clique(g, l, r.vertices));
      CHECK(r.vertices.size() == test::plain_max_clique(g, l));
    }
  }
}

namespace {

// A near-complete graph whose clique number is known: its complement is a disjoint union of
// cycles, paths, stars and small complete graphs (independence numbers floor(k/2), ceil(k/2),
// the leaves, 1), so the clique number is the sum of theirs. Vertices are shuffled.
std::pair<PyramidGraph, int> near_complete(std::uint64_t seed, int components) {
  std::mt19937_64 rng(seed);
  std::vector<std::pair<int, int>> missing;  // edges of the complement
  int n = 0, omega = 0;
  for (int c = 0; c < components; ++c) {
    const int kind = static_cast<int>(rng() % 4), k = 2 + static_cast<int>(rng() % 8);
    const int first = n;
    if (kind == 0 && k >= 3) {  // cycle
      for (int i = 0; i < k; ++i) missing.emplace_back(first + i, first + (i + 1) % k);
      omega += k / 2;
    } else if (kind == 1 || kind == 0) {  // path
      for (int i = 0; i + 1 < k; ++i) missing.emplace_back(first + i, first + i + 1);
      omega += (k + 1) / 2;
    } else if (kind == 2) {  // star: a centre and k - 1 leaves
      for (int i = 1; i < k; ++i) missing.emplace_back(first, first + i);
      omega += k - 1;
    } else {  // complete graph
      for (int i = 0; i < k; ++i)
        for (int j = i + 1; j < k; ++j) missing.emplace_back(first + i, first + j);
      omega += 1;
    }
    n += k;
  }
  std::vector<int> ids(static_cast<std::size_t>(n));
  std::iota(ids.begin(), ids.end(), 0);
  std::shuffle(ids.begin(), ids.end(), rng);
  std::vector<std::vector<char>> absent(static_cast<std::size_t>(n),
                                        std::vector<char>(static_cast<std::size_t>(n), 0));
  for (auto [a, b] : missing) {
    absent[static_cast<std::size_t>(ids[static_cast<std::size_t>(a)])]
          [static_cast<std::size_t>(ids[static_cast<std::size_t>(b)])] = 1;
    absent[static_cast<std::size_t>(ids[static_cast<std::size_t>(b)])]
          [static_cast<std::size_t>(ids[static_cast<std::size_t>(a)])] = 1;
  }
  std::vector<std::vector<int>> adj(static_cast<std::size_t>(n));
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b)
      if (a != b && !absent[static_cast<std::size_t>(a)][static_cast<std::size_t>(b)])
        adj[static_cast<std::size_t>(a)].push_back(b);
  return {test::graph_from_lists(std::move(adj)), omega};
}

}  // namespace

TEST_CASE("the exact solver finds the clique number of near-complete graphs") {
  // Near-complete subproblems are searched as independent sets of their sparse complement (with
  // degree and domination reductions and a clique-cover bound); the answer is known by
  // construction.
  CliqueParams cp;
  for (std::uint64_t seed = 0; seed < 16; ++seed) {
    const auto [g, omega] = near_complete(seed, 8 + static_cast<int>(seed % 5) * 6);
    INFO("seed " << seed << ", " << g.vertices << " vertices, clique number " << omega);
    const CliqueResult r = exact_max_clique(g, 0, cp);
    CHECK(r.proven);
    CHECK(is_clique(g, 0, r.vertices));
    CHECK(static_cast<int>(r.vertices.size()) == omega);
    CHECK(r.clique_number_bound == omega);
  }
}

TEST_CASE("the exact solver stops at its node budget and says so") {
  CliqueParams cp;
  cp.exact_max_nodes = 5;
  const PyramidGraph g = random_graph(200, 0.5, 0, 1);
  const CliqueResult r = exact_max_clique(g, 0, cp);
  check_cut_by_nodes(g, r);
}

TEST_CASE("a near-complete graph's search stops at its node budget and says so") {
  // Searched as independent sets of the sparse complement; each node's reductions count as the
  // nodes their work is worth, so that the budget bounds the search's time.
  for (std::uint64_t seed : {1u, 2u}) {
    const PyramidGraph g = random_graph(300, 0.93, 0, seed);
    CliqueParams cp;
    cp.exact_max_nodes = 2000;
    cp.exact_time_budget_ms = 0;
    const CliqueResult r = exact_max_clique(g, 0, cp);
    INFO("seed " << seed << ", clique " << r.vertices.size() << ", bound "
                 << r.clique_number_bound);
    check_cut_by_nodes(g, r);
  }
}

TEST_CASE("a search budget counts nodes by their work and reads the clock at each 256th") {
  detail::SearchBudget b;
  b.max_nodes = 1000;
  b.deadline = detail::SearchBudget::Clock::now() - std::chrono::seconds(1);  // already past
  for (int i = 0; i < 255; ++i) REQUIRE(b.spend());
  CHECK(b.nodes == 255);
  CHECK_FALSE(b.spend());  // the 256th reads the clock
  CHECK(b.out_of_time);
  CHECK_FALSE(b.out_of_nodes);

  detail::SearchBudget big;
  big.max_nodes = 1000;
  CHECK(big.spend(600));  // one node worth 600
  CHECK(big.nodes == 600);
  CHECK_FALSE(big.spend(401));
  CHECK(big.out_of_nodes);

  detail::SearchBudget late;
  late.deadline = detail::SearchBudget::Clock::now() - std::chrono::seconds(1);
  CHECK(late.spend(100));
  CHECK_FALSE(late.spend(200));  // passes 256: the clock is read
  CHECK(late.out_of_time);
}

TEST_CASE("an interrupted exact search returns a bound no smaller than the maximum clique") {
  for (std::uint64_t seed : {1u, 2u, 3u, 4u}) {
    const PyramidGraph g = random_graph(90, 0.45, 0, seed);
    const int omega = test::plain_max_clique(g, 0);
    for (long nodes : {1L, 3L, 20L, 200L}) {
      INFO("seed " << seed << ", " << nodes << " nodes");
      CliqueParams cp;
      cp.exact_max_nodes = nodes;
      const CliqueResult r = exact_max_clique(g, 0, cp);
      CHECK(is_clique(g, 0, r.vertices));
      CHECK(static_cast<int>(r.vertices.size()) <= omega);
      CHECK(r.clique_number_bound >= omega);
      if (r.proven) CHECK(static_cast<int>(r.vertices.size()) == omega);
      CHECK(r.budget == (r.proven ? CliqueBudget::none : CliqueBudget::nodes));
    }
  }
}

TEST_CASE("the exact solver stops at its time budget and says so") {
  // A dense random graph of 400 vertices takes a branch and bound far more than a millisecond.
  CliqueParams cp;
  cp.exact_max_nodes = 10000000000L;
  cp.exact_time_budget_ms = 1;
  const PyramidGraph g = random_graph(400, 0.75, 0, 7);
  const CliqueResult r = exact_max_clique(g, 0, cp);
  CHECK_FALSE(r.proven);
  CHECK(r.budget == CliqueBudget::time);
  CHECK(is_clique(g, 0, r.vertices));
  CHECK(r.clique_number_bound >= static_cast<int>(r.vertices.size()));
  // Over a pyramid the budget is shared: every level says which budget stopped it.
  cp.solver = CliqueSolver::exact;
  for (const CliqueResult& level : solve_pyramid(g, cp)) {
    CHECK(is_clique(g, level.level, level.vertices));
    CHECK(level.budget == (level.proven ? CliqueBudget::none : CliqueBudget::time));
  }
}

TEST_CASE("the exact solver on graphs without vertices or edges") {
  CliqueParams cp;
  const PyramidGraph empty = test::graph_from_lists({});
  CHECK(exact_max_clique(empty, 0, cp).vertices.empty());
  CHECK(exact_max_clique(empty, 0, cp).proven);
  const PyramidGraph lonely = random_graph(4, 0.0, 0, 1);
  const CliqueResult r = exact_max_clique(lonely, 0, cp);
  CHECK(r.vertices.size() == 1);
  CHECK(r.proven);
}

TEST_CASE(
    "near-complete subproblems (solved on the complement) agree with plain branch and bound") {
  CliqueParams cp;
  const std::uint64_t seeds = test::kSanitized ? 4 : 16;  // the reference is exponential
  for (std::uint64_t seed = 0; seed < seeds; ++seed) {
    const int n = 34 + 2 * static_cast<int>(seed % 8);
    const double p = 0.9 + 0.02 * static_cast<double>(seed % 4);
    const PyramidGraph g = random_graph(n, p, static_cast<int>(seed % 3) * 5, seed);
    INFO("seed " << seed << ", n " << n << ", p " << p);
    const CliqueResult r = exact_max_clique(g, 0, cp);
    CHECK(r.proven);
    CHECK(is_clique(g, 0, r.vertices));
    CHECK(r.vertices.size() == test::plain_max_clique(g, 0));
  }
  // Issue 11's problems with more inliers: level 0's inliers are near-complete.
  const GraphParams gp = test::association_params();
  for (std::uint64_t seed : {5u, 6u}) {
    if (test::kSanitized && seed != 5u) continue;
    const auto c = test::association(160, 80, seed);
    const PyramidGraph g = build_pyramid_graph(c, gp);
    INFO("association, seed " << seed);
    const CliqueResult r = exact_max_clique(g, 0, cp);
    CHECK(r.proven);
    CHECK(is_clique(g, 0, r.vertices));
    CHECK(r.vertices.size() == test::plain_max_clique(g, 0));
  }
}

TEST_CASE("the search for a larger clique finds one whenever it exists, from any start") {
  // The search first colours the vertices that could be in a larger clique and stops when that
  // needs no more colours than the start has: it must never stop while a larger clique exists.
  for (std::uint64_t seed = 0; seed < 60; ++seed) {
    const int n = 10 + static_cast<int>(seed % 9);
    const double p = 0.25 + 0.1 * static_cast<double>(seed % 6);
    const PyramidGraph g = random_graph(n, p, 0, seed);
    const std::size_t maximum = test::brute_force_clique(g);
    // Start from a maximal clique grown from each vertex: often smaller than the maximum.
    const detail::PyramidLevel view{g, 0};
    detail::Marks marks(g.vertices);
    const std::vector<int> degree = detail::level_degrees(g, 0);
    for (int v = 0; v < n; ++v) {
      const std::vector<int> start = detail::extend_clique(view, {v}, degree, 1, marks);
      bool proven = false;
      const std::vector<int> got = detail::larger_clique(g, 0, start, 1000000, proven);
      INFO("seed " << seed << ", start vertex " << v << ", start size " << start.size());
      CHECK(proven);
      CHECK(is_clique(g, 0, got));
      CHECK(got.size() == maximum);
    }
  }
  // A 5-cycle: its maximum clique (an edge) is proved only by the search (a greedy colouring
  // needs 3 colours); a 5-cycle with one chord and a triangle: the colouring proves it.
  const PyramidGraph cycle = test::graph_from_lists({{1, 4}, {0, 2}, {1, 3}, {2, 4}, {0, 3}});
  bool proven = false;
  CHECK(detail::larger_clique(cycle, 0, {0, 1}, 1000, proven).size() == 2);
  CHECK(proven);
  const PyramidGraph chord = test::graph_from_lists({{1, 2, 4}, {0, 2}, {0, 1, 3}, {2, 4}, {0, 3}});
  CHECK(detail::larger_clique(chord, 0, {3, 4}, 1000, proven).size() == 3);
  CHECK(proven);
  CHECK(detail::larger_clique(chord, 0, {0, 1, 2}, 1000, proven) == std::vector<int>{0, 1, 2});
  CHECK(proven);
  // The octahedron (every vertex but its opposite one adjacent): 4-regular, so each vertex's
  // subproblem (a 4-cycle) survives pruning and needs search nodes, but three colours suffice and
  // prove its triangles maximum. With no node budget only the colouring can prove it.
  const PyramidGraph octahedron = test::graph_from_lists(
      {{2, 3, 4, 5}, {2, 3, 4, 5}, {0, 1, 4, 5}, {0, 1, 4, 5}, {0, 1, 2, 3}, {0, 1, 2, 3}});
  CHECK(detail::larger_clique(octahedron, 0, {0, 2, 4}, 0, proven) == std::vector<int>{0, 2, 4});
  CHECK(proven);
}
