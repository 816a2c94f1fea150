// A dense level as bit rows (graph/dense_level.hpp) gives what the pyramid's own rows give.

#include <algorithm>
#include <catch2/catch.hpp>
#include <random>

#include "graph/dense_level.hpp"
#include "pagor/graph/densest_clique.hpp"
#include "support/clique_reference.hpp"

using namespace pagor;

TEST_CASE(
    "a level's bit rows give its own rows' degrees, greedy cliques, k-cores, cores, searches") {
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    const int m = seed % 2 ? 150 : 300;
    GraphParams params;
    params.min_length = 0.0;
    const PyramidGraph g = build_pyramid_graph(test::association(m, m / 10, seed), params);
    std::mt19937_64 rng(seed);
    // All levels from `first` on in one pass equal each level on its own.
    const int first = static_cast<int>(seed % 3);
    const std::vector<detail::BitGraph> all = detail::levels_bits(g, first);
    REQUIRE(all.size() == static_cast<std::size_t>(g.levels()));
    for (int l = 0; l < g.levels(); ++l) {
      INFO("seed " << seed << " level " << l);
      const detail::BitGraph bits = detail::level_bits(g, l);
      const detail::BitGraph& one_pass = all[static_cast<std::size_t>(l)];
      REQUIRE(one_pass.size() == (l < first ? 0 : g.vertices));
      for (int v = 0; v < one_pass.size(); ++v)
        REQUIRE(std::equal(bits.row(v), bits.row(v) + bits.words(), one_pass.row(v)));
      const std::vector<int> deg = detail::degrees(bits);
      REQUIRE(deg == detail::level_degrees(g, l));
      const detail::PyramidLevel view{g, l};
      detail::Marks marks(g.vertices);
      // Greedy cliques, and a clique grown from single vertices with and without a floor.
      const std::vector<int> greedy = detail::greedy_clique(view, deg, 4, marks);
      CHECK(detail::greedy_clique(bits, deg, 4, marks) == greedy);
      CHECK(detail::is_clique(bits, greedy, marks));
      for (int t = 0; t < 10; ++t) {
        const int v = static_cast<int>(rng() % static_cast<std::uint64_t>(g.vertices));
        for (int floor : {0, 3})
          CHECK(detail::extend_clique(bits, {v}, deg, floor, marks) ==
                detail::extend_clique(view, {v}, deg, floor, marks));
      }
      // A vertex outside the clique that misses one of its members makes it no clique.
      for (int v = 0; v < g.vertices && greedy.size() >= 2; ++v) {
        if (std::find(greedy.begin(), greedy.end(), v) != greedy.end()) continue;
        std::vector<int> more = greedy;
        more.push_back(v);
        CHECK(detail::is_clique(bits, more, marks) == detail::is_clique(view, more, marks));
      }
      for (int k : {1, 3, static_cast<int>(greedy.size())}) {
        const std::vector<int> keep =
            detail::k_core(view, deg, k, [&](int v) { return view.row_length(v); });
        CHECK(detail::k_core(bits, deg, k) == keep);
        if (keep.empty()) continue;
        // The core read through the bit rows is its CSR: rows, core decomposition, search.
        const detail::LevelCsr a = detail::level_csr(g, l, keep);
        const detail::CoreView b(bits, keep);
        REQUIRE(b.size() == a.size());
        for (int v = 0; v < a.size(); ++v) {
          std::vector<int> row;
          b.for_each_neighbor(v, [&](int u) { row.push_back(u); });
          CHECK(row == std::vector<int>(a.begin(v), a.end(v)));
          CHECK(b.degree(v) == a.degree(v));
        }
        const detail::CoreDecomposition ca = detail::core_decomposition(a),
                                        cb = detail::core_decomposition(b);
        CHECK(cb.core == ca.core);
        CHECK(cb.order == ca.order);
        CHECK(cb.position == ca.position);
        CHECK(cb.degeneracy == ca.degeneracy);
        for (long nodes : {0L, 50L, 1000000L}) {
          bool proven_a = false, proven_b = false;
          int bound_a = -1, bound_b = -1;
          const std::vector<int> found_a =
              detail::larger_clique_in(a, keep, greedy, nodes, proven_a, &bound_a);
          CHECK(detail::larger_clique_in(b, greedy, nodes, proven_b, &bound_b) == found_a);
          CHECK(proven_b == proven_a);
          CHECK(bound_b == bound_a);
        }
      }
    }
  }
}

TEST_CASE("levels proven on bit rows: the exact solver's clique sizes, proven, on dense levels") {
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    GraphParams params;
    params.min_length = 0.0;
    const PyramidGraph g = build_pyramid_graph(test::association(500, 50, seed), params);
    CliqueParams p;
    p.prove_first = true;
    p.prove_first_min_edges = 0;  // every level
    int dense = 0;
    for (int l = 0; l < g.levels(); ++l) dense += detail::dense_level(g, l);
    REQUIRE(dense >= 2);  // the test goes through the bit rows
    for (CliqueSolver solver : {CliqueSolver::cascaded, CliqueSolver::independent}) {
      p.solver = solver;
      const std::vector<CliqueResult> got = solve_pyramid(g, p);
      for (int l = 0; l < g.levels(); ++l) {
        INFO("seed " << seed << " level " << l);
        const CliqueResult exact = exact_max_clique(g, l, CliqueParams{});
        REQUIRE(exact.proven);
        CHECK(got[static_cast<std::size_t>(l)].proven);
        CHECK(got[static_cast<std::size_t>(l)].vertices.size() == exact.vertices.size());
        CHECK(is_clique(g, l, got[static_cast<std::size_t>(l)].vertices));
      }
    }
  }
}

TEST_CASE("a colouring grown from a clique proves it maximum only when it is") {
  int proven = 0, beyond_plain = 0;
  for (std::uint64_t seed = 0; seed < 240; ++seed) {
    const bool large = seed % 4 == 3;  // rows of two to four words
    const int n = large ? 100 + static_cast<int>(seed % 150) : 12 + static_cast<int>(seed % 60);
    const double p = large ? 0.05 + 0.05 * static_cast<double>(seed % 6)
                           : 0.1 + 0.1 * static_cast<double>(seed % 8);
    const int planted = static_cast<int>(seed % 14) + (large ? 10 : 0);
    const PyramidGraph g = test::random_graph(n, p, planted, seed);
    const CliqueResult exact = exact_max_clique(g, 0, CliqueParams{});
    REQUIRE(exact.proven);
    const detail::BitGraph bits = detail::level_bits(g, 0);
    const std::vector<int> deg = detail::degrees(bits);
    detail::Marks marks(g.vertices);
    std::mt19937_64 rng(seed);
    std::vector<std::vector<int>> cliques = {exact.vertices,
                                             detail::greedy_clique(bits, deg, 4, marks)};
    if (exact.vertices.size() >= 2)  // a clique one short of the maximum
      cliques.emplace_back(exact.vertices.begin() + 1, exact.vertices.end());
    for (int t = 0; t < 6; ++t) {  // maximal cliques grown at random, members in random order
      std::vector<int> priority(static_cast<std::size_t>(n));
      for (int& x : priority) x = static_cast<int>(rng() % 1000);
      std::vector<int> grown = detail::extend_clique(
          bits, {static_cast<int>(rng() % static_cast<std::uint64_t>(n))}, priority, 0, marks);
      std::shuffle(grown.begin(), grown.end(), rng);
      cliques.push_back(std::move(grown));
    }
    for (const std::vector<int>& clique : cliques) {
      INFO("seed " << seed << ", n " << n << ", p " << p << ", clique of " << clique.size()
                   << ", maximum " << exact.vertices.size());
      REQUIRE(detail::is_clique(bits, clique, marks));
      const std::vector<int> keep = detail::k_core(bits, deg, static_cast<int>(clique.size()));
      if (!detail::colouring_from_clique_proves(bits, keep, clique)) continue;
      CHECK(clique.size() == exact.vertices.size());  // never a clique that is not maximum
      ++proven;
      // Proofs that a plain greedy colouring of the core (increasing id) does not give.
      std::vector<detail::Word> u(static_cast<std::size_t>(bits.words()), 0), q(u.size());
      for (int v : keep) detail::set_bit(u.data(), v);
      beyond_plain += detail::colour_greedily(bits, u.data(), q.data(), bits.words(),
                                              static_cast<int>(keep.size()),
                                              static_cast<int>(clique.size())) > 0;
    }
  }
  // 412 and 139 as written; without the left vertices' checks, 290 and 27.
  CHECK(proven >= 300);
  CHECK(beyond_plain >= 60);
}
