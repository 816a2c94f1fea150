#include <Eigen/Geometry>
#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>
#include <random>
#include <set>

#include "pagor/graph/densest_clique.hpp"
#include "pagor/graph/pyramid_graph.hpp"
#include "pagor/io/kitti.hpp"
#include "pagor/pipeline.hpp"
#include "support/clique_reference.hpp"
#include "util/random_draw.hpp"

using namespace pagor;
using pagor::test::random_graph;

namespace {

// Correspondences: `inliers` consistent with one rigid motion (noise `sigma`), the rest random.
std::vector<Correspondence> planted(int inliers, int outliers, double sigma, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> coord(-40.0, 40.0);
  std::normal_distribution<double> noise(0.0, sigma);
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(0.1, 0.2, 1).normalized()).toRotationMatrix();
  const Eigen::Vector3d t(10, -4, 1);
  std::vector<Correspondence> c;
  int id = 0;
  for (int k = 0; k < inliers + outliers; ++k) {
    Correspondence x;
    x.source = x.target = id++;
    x.p = draw3(coord, rng);
    x.p.z() /= 8;
    x.q = k < inliers ? Eigen::Vector3d(R * x.p + t + draw3(noise, rng))
                      : Eigen::Vector3d(draw3(coord, rng).cwiseQuotient(Eigen::Vector3d(1, 1, 8)));
    c.push_back(x);
  }
  std::shuffle(c.begin(), c.end(), rng);  // inliers anywhere in the list
  return c;
}

std::set<int> inlier_ids(const std::vector<Correspondence>& c, int inliers) {
  std::set<int> s;
  for (std::size_t i = 0; i < c.size(); ++i)
    if (c[i].source < inliers) s.insert(static_cast<int>(i));
  return s;
}

}  // namespace

TEST_CASE("the cascaded solver finds the planted clique with 50 to 95 % outliers") {
  GraphParams gp;
  gp.trim = TrimKind::difference;
  gp.thresholds = {0.1, 0.2, 0.4, 0.8};
  CliqueParams cp;
  for (const auto& [inliers, outliers] :
       {std::pair{30, 30}, std::pair{30, 120}, std::pair{20, 380}}) {
    for (std::uint64_t seed : {1u, 2u, 3u}) {
      INFO(inliers << " inliers, " << outliers << " outliers, seed " << seed);
      const auto c = planted(inliers, outliers, 0.01, seed);
      const PyramidGraph g = build_pyramid_graph(c, gp);
      const auto result = solve_pyramid(g, cp);
      REQUIRE(result.size() == 4);
      const std::set<int> truth = inlier_ids(c, inliers);
      for (const auto& level : result) {
        CHECK(is_clique(g, level.level, level.vertices));
        const std::set<int> found(level.vertices.begin(), level.vertices.end());
        std::size_t hit = 0;
        for (int v : found) hit += truth.count(v);
        // Noise 0.01 m per axis: every inlier pair is within even the tightest level (0.1 m)...
        CHECK(hit == truth.size());
        // ...and random outliers rarely join all of them.
        CHECK(found.size() <= truth.size() + 1);
      }
    }
  }
}

TEST_CASE("the relaxation agrees with the exact solver on small random graphs") {
  CliqueParams cp;
  cp.prove_first = false;  // the relaxation itself
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    for (bool prune : {true, false}) {
      INFO("seed " << seed << (prune ? " with" : " without") << " pruning");
      cp.prune = prune;
      const PyramidGraph g = random_graph(60, 0.15, 9 + static_cast<int>(seed % 5), seed);
      const CliqueResult exact = exact_max_clique(g, 0, cp);
      REQUIRE(exact.proven);
      const CliqueResult relaxed = solve_clipper(g, 0, {}, cp);
      CHECK(is_clique(g, 0, relaxed.vertices));
      CHECK(relaxed.vertices == exact.vertices);
    }
  }
}

TEST_CASE("warm start gives the same cliques as cold start with fewer iterations") {
  GraphParams gp;
  gp.trim = TrimKind::difference;
  gp.thresholds = {0.1, 0.2, 0.4, 0.8};
  const bool prune = GENERATE(false, true);
  int cascaded_steps = 0, independent_steps = 0;
  for (std::uint64_t seed : {4u, 5u, 6u}) {
    const auto c = planted(25, 225, 0.03, seed);
    const PyramidGraph g = build_pyramid_graph(c, gp);
    CliqueParams cp;
    cp.prune = prune;
    cp.prove_first = false;      // the relaxation itself
    cp.settle_selected = false;  // every level's full cascade
    cp.solver = CliqueSolver::cascaded;
    const auto warm = solve_pyramid(g, cp);
    cp.solver = CliqueSolver::independent;
    const auto cold = solve_pyramid(g, cp);
    for (std::size_t l = 0; l < warm.size(); ++l) {
      CHECK(warm[l].vertices == cold[l].vertices);
      cascaded_steps += warm[l].gradient_steps;
      independent_steps += cold[l].gradient_steps;
    }
  }
  INFO((prune ? "pruned" : "unpruned")
       << " gradient steps: cascaded " << cascaded_steps << ", independent " << independent_steps);
  // With pruning, a level whose core is itself a clique needs no gradient step at all, cascaded
  // or not.
  if (prune)
    CHECK(cascaded_steps <= independent_steps);
  else
    CHECK(cascaded_steps < independent_steps);
}

TEST_CASE("the solver is deterministic for a seed") {
  const auto c = planted(20, 200, 0.03, 9);
  const PyramidGraph g = build_pyramid_graph(c, GraphParams{});
  const auto a = solve_pyramid(g, CliqueParams{});
  const auto b = solve_pyramid(g, CliqueParams{});
  for (std::size_t l = 0; l < a.size(); ++l) {
    CHECK(a[l].vertices == b[l].vertices);
    CHECK(a[l].u == b[l].u);
  }
}

TEST_CASE("graphs without vertices or edges") {
  const PyramidGraph empty = build_pyramid_graph({}, GraphParams{});
  for (const auto solver :
       {CliqueSolver::cascaded, CliqueSolver::independent, CliqueSolver::exact}) {
    CliqueParams cp;
    cp.solver = solver;
    const auto r = solve_pyramid(empty, cp);
    REQUIRE(r.size() == GraphParams{}.thresholds.size());
    CHECK(r[0].vertices.empty());
  }
  const PyramidGraph lonely = random_graph(5, 0.0, 0, 1);
  const CliqueResult r = solve_clipper(lonely, 0, {}, CliqueParams{});
  CHECK(r.vertices.size() == 1);
}

TEST_CASE("never smaller than CLIPPER rounded to the full support, on association problems") {
  // Issue 11's problems, small enough for the dense reference: 10 to 30 % inliers.
  const GraphParams gp = test::association_params();
  for (const auto& [m, inliers] :
       {std::pair{80, 8}, std::pair{150, 15}, std::pair{200, 20}, std::pair{120, 36}}) {
    for (std::uint64_t seed : {1u, 2u, 3u}) {
      const auto c = test::association(m, inliers, seed);
      const PyramidGraph g = build_pyramid_graph(c, gp);
      for (const auto solver : {CliqueSolver::cascaded, CliqueSolver::independent}) {
        CliqueParams cp;
        cp.solver = solver;
        cp.settle_selected = false;  // every level's full cascade
        const auto ours = solve_pyramid(g, cp);
        for (int l = 0; l < g.levels(); ++l) {
          INFO("m " << m << ", seed " << seed << ", level " << l
                    << (solver == CliqueSolver::cascaded ? ", cascaded" : ", independent"));
          const auto reference = test::clipper_full_support(g, l, cp.seed);
          REQUIRE(is_clique(g, l, reference));
          const auto& found = ours[static_cast<std::size_t>(l)].vertices;
          CHECK(is_clique(g, l, found));
          CHECK(found.size() >= reference.size());
          CHECK(found.size() <= exact_max_clique(g, l, cp).vertices.size());
        }
      }
    }
  }
}

TEST_CASE("never smaller than CLIPPER rounded to the full support, on random graphs") {
  for (std::uint64_t seed = 0; seed < 12; ++seed) {
    const double p = 0.05 + 0.05 * static_cast<double>(seed % 4);
    const PyramidGraph g = random_graph(90, p, 6 + static_cast<int>(seed % 6), seed);
    INFO("seed " << seed << ", p " << p);
    const auto reference = test::clipper_full_support(g, 0, 42);
    REQUIRE(is_clique(g, 0, reference));
    for (bool prune : {true, false}) {
      CliqueParams cp;
      cp.prune = prune;
      cp.prove_first = !prune;  // the relaxation alone, and the bound's shortcut
      const CliqueResult r = solve_clipper(g, 0, {}, cp);
      CHECK(is_clique(g, 0, r.vertices));
      CHECK(r.vertices.size() >= reference.size());
    }
  }
}

TEST_CASE("the cascade never returns a smaller clique than the independent solves") {
  const GraphParams gp = test::association_params();
  for (std::uint64_t seed : {11u, 12u, 13u, 14u}) {
    const auto c = test::association(400, 40, seed);
    const PyramidGraph g = build_pyramid_graph(c, gp);
    CliqueParams cp;
    cp.settle_selected = false;  // every level's full cascade
    const auto warm = solve_pyramid(g, cp);
    cp.solver = CliqueSolver::independent;
    const auto cold = solve_pyramid(g, cp);
    for (std::size_t l = 0; l < warm.size(); ++l) {
      INFO("seed " << seed << ", level " << l);
      CHECK(is_clique(g, static_cast<int>(l), warm[l].vertices));
      CHECK(warm[l].vertices.size() >= cold[l].vertices.size());
      // Each level's clique is a clique of every later level (the edges only grow).
      if (l > 0) CHECK(warm[l].vertices.size() >= warm[l - 1].vertices.size());
    }
  }
}

// A warm start can settle in a worse local optimum than a cold one; the cascade then still finds
// at least what the independent solves find, level by level (scenes where the upper levels need
// the relaxation, unlike the association problems above).
TEST_CASE("the cascade is never smaller than the independent solves, level by level") {
  const long check_nodes = GENERATE(0L, 200000L);  // the cold fallback alone, and with the check
  const bool prove_first = GENERATE(false, true);
  const auto check = [check_nodes, prove_first](const PyramidGraph& g, const std::string& what) {
    CliqueParams cp;
    cp.cascade_check_nodes = check_nodes;
    cp.prove_first = prove_first;
    cp.settle_selected = false;  // every level's full cascade
    const auto warm = solve_pyramid(g, cp);
    cp.solver = CliqueSolver::independent;
    const auto cold = solve_pyramid(g, cp);
    for (std::size_t l = 0; l < warm.size(); ++l) {
      INFO(what << ", level " << l << ": " << warm[l].vertices.size() << " cascaded, "
                << cold[l].vertices.size() << " independent");
      CHECK(is_clique(g, static_cast<int>(l), warm[l].vertices));
      CHECK(warm[l].vertices.size() >= cold[l].vertices.size());
      CHECK((warm[l].start == CliqueStart::cold) == (l == 0));
    }
  };
  for (std::uint64_t seed = 1; seed <= 6; ++seed)
    check(build_pyramid_graph(planted(25, 400, 0.05, seed), GraphParams{}),
          "planted, seed " + std::to_string(seed));
  if (!std::filesystem::exists(std::string(PAGOR_KITTI_DIR) + "/sequences/00/velodyne/000000.bin"))
    return;
  const KittiSequence seq(PAGOR_KITTI_DIR, "00");
  for (const auto& [s, t] : {std::pair{0, 20}, std::pair{20, 30}, std::pair{0, 30}}) {
    Pipeline p(default_config(), 1);
    p.set_input(seq.load_frame(s).cloud, seq.load_frame(t).cloud);
    p.run();
    check(p.graph(), "KITTI " + std::to_string(s) + " -> " + std::to_string(t));
  }
}

TEST_CASE("a level whose lower bound is proven maximum skips the relaxation") {
  GraphParams gp;
  gp.trim = TrimKind::difference;
  gp.thresholds = {0.1, 0.2, 0.4, 0.8};
  for (std::uint64_t seed : {4u, 5u, 6u}) {
    const auto c = planted(25, 225, 0.03, seed);
    const PyramidGraph g = build_pyramid_graph(c, gp);
    for (const CliqueSolver solver : {CliqueSolver::cascaded, CliqueSolver::independent}) {
      CliqueParams cp;
      cp.solver = solver;
      cp.prove_first_min_edges = 0;  // every level, however small
      const auto proven = solve_pyramid(g, cp);
      cp.prove_first = false;
      cp.prune = false;  // the relaxation on every vertex (a pruned core may already be a clique)
      const auto relaxed = solve_pyramid(g, cp);
      int relaxed_steps = 0;
      for (std::size_t l = 0; l < proven.size(); ++l) {
        INFO("seed " << seed << ", level " << l);
        const CliqueResult exact = exact_max_clique(g, static_cast<int>(l), CliqueParams{});
        CHECK(is_clique(g, static_cast<int>(l), proven[l].vertices));
        // The bound proves the level's clique maximum at once: no gradient step, and a clique as
        // large as the exact solver's (and never smaller than the relaxation's).
        CHECK(proven[l].proven);
        CHECK(proven[l].gradient_steps == 0);
        CHECK(proven[l].vertices.size() == exact.vertices.size());
        CHECK(proven[l].clique_number_bound == static_cast<int>(exact.vertices.size()));
        CHECK(proven[l].vertices.size() >= relaxed[l].vertices.size());
        relaxed_steps += relaxed[l].gradient_steps;
      }
      CHECK(relaxed_steps > 0);  // off: the relaxation runs (the paper's Alg. 1)
    }
  }
}

TEST_CASE("weighted affinities always run the relaxation") {
  // The densest clique under Gaussian weights need not be the largest: no shortcut by bounds.
  GraphParams gp;
  gp.trim = TrimKind::difference;
  gp.thresholds = {0.1, 0.2, 0.4, 0.8};
  gp.affinity = AffinityKind::gaussian;
  const PyramidGraph g = build_pyramid_graph(planted(25, 225, 0.03, 4), gp);
  int steps = 0;
  for (const CliqueResult& r : solve_pyramid(g, CliqueParams{})) steps += r.gradient_steps;
  CHECK(steps > 0);
}

TEST_CASE("the paper's preset runs the relaxation on every level") {
  CHECK_FALSE(preset_config("paper").clique.prove_first);
  CliqueParams small;  // below prove_first_min_edges the relaxation runs
  small.prove_first_min_edges = 1000000;
  GraphParams gp;
  gp.trim = TrimKind::difference;
  gp.thresholds = {0.1, 0.2, 0.4, 0.8};
  const PyramidGraph g = build_pyramid_graph(planted(25, 225, 0.03, 4), gp);
  small.prune = false;
  int steps = 0;
  for (const CliqueResult& r : solve_pyramid(g, small)) steps += r.gradient_steps;
  CHECK(steps > 0);
  CHECK(default_config().clique.prove_first);
}

namespace {

// Two nested levels on n vertices: edges of probability p0 at level 0, and at level 1 also those
// of probability p1 (a dense level, as the loosest of a learned matcher's problem); a planted
// clique of k vertices from level `planted` on.
PyramidGraph two_levels(int n, int k, double p0, double p1, std::uint64_t seed, int planted = 0) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> draw(0.0, 1.0);
  std::vector<std::vector<std::pair<int, std::uint8_t>>> adj(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      const double x = draw(rng);
      const int level = x < p0 ? 0 : (i < k && j < k) ? planted : x < p1 ? 1 : -1;
      if (level < 0) continue;
      adj[static_cast<std::size_t>(i)].emplace_back(j, static_cast<std::uint8_t>(level));
      adj[static_cast<std::size_t>(j)].emplace_back(i, static_cast<std::uint8_t>(level));
    }
  PyramidGraph g;
  g.vertices = n;
  g.thresholds = {1.0, 2.0};
  g.offsets.assign(1, 0);
  g.edges_at_level = {0, 0};
  for (auto& row : adj) {
    std::sort(row.begin(), row.end());
    for (const auto& [v, level] : row) {
      g.neighbors.push_back(v);
      g.level.push_back(level);
      g.trim.push_back(0.0f);
      for (int l = level; l < 2; ++l) ++g.edges_at_level[static_cast<std::size_t>(l)];
    }
    g.offsets.push_back(static_cast<std::int64_t>(g.neighbors.size()));
  }
  for (auto& e : g.edges_at_level) e /= 2;
  return g;
}

}  // namespace

// On a level its bounded proof cannot settle, the proof's search is not run a second time after
// the relaxation: its largest clique stands in, and the level reports the proof's bound and the
// node budget. The cascade still never loses to the independent solves.
TEST_CASE("a level the bounded proof cannot settle keeps that search's clique and bound") {
  int unsettled = 0;
  for (std::uint64_t seed : {21u, 22u, 23u}) {
    const PyramidGraph g = two_levels(300, 20, 0.05, 0.5, seed);
    CliqueParams cp;
    cp.prove_first_min_edges = 0;
    cp.cascade_check_nodes = 30;  // too few nodes to prove the dense level
    cp.settle_selected = false;   // every level's full cascade
    const auto warm = solve_pyramid(g, cp);
    cp.solver = CliqueSolver::independent;
    const auto cold = solve_pyramid(g, cp);
    for (std::size_t l = 0; l < warm.size(); ++l) {
      const CliqueResult& r = warm[l];
      INFO("seed " << seed << ", level " << l << ": " << r.vertices.size() << " members, bound "
                   << r.clique_number_bound);
      CHECK(is_clique(g, static_cast<int>(l), r.vertices));
      CHECK(r.vertices.size() >= cold[l].vertices.size());
      if (l > 0) CHECK(r.vertices.size() >= warm[l - 1].vertices.size());
      if (r.proven) continue;
      ++unsettled;
      CHECK(r.start != CliqueStart::cold);  // a warm level
      CHECK(r.budget == CliqueBudget::nodes);
      CHECK(r.gradient_steps > 0);  // the relaxation ran
      CHECK(r.clique_number_bound > static_cast<int>(r.vertices.size()));
      CHECK(static_cast<std::size_t>(r.clique_number_bound) <= g.active_vertices(int(l)));
    }
  }
  CHECK(unsettled > 0);  // the path was taken
}

// The relaxation finds a clique larger than the bounded proof's (planted at level 1 only): the
// search runs again from it, and its stronger pruning proves the level.
TEST_CASE("a relaxation's larger clique is searched from, and proven, after a failed proof") {
  int proven = 0;
  for (std::uint64_t seed : {31u, 32u, 33u, 34u}) {
    const PyramidGraph g = two_levels(200, 30, 0.05, 0.4, seed, 1);
    CliqueParams cp;
    cp.prove_first_min_edges = 0;
    cp.cascade_check_nodes = 30;
    cp.settle_selected = false;  // the full cascade's check on every level
    const auto r = solve_pyramid(g, cp);
    INFO("seed " << seed << ": level 1 " << r[1].vertices.size() << " members, bound "
                 << r[1].clique_number_bound << (r[1].proven ? ", proven" : ""));
    CHECK(is_clique(g, 1, r[1].vertices));
    CHECK(r[1].vertices.size() >= 30u);
    proven += r[1].proven;
    if (r[1].proven) CHECK(r[1].clique_number_bound == static_cast<int>(r[1].vertices.size()));
  }
  CHECK(proven == 4);
}

// With two threads, a level whose bounded proof fails solves its cold-start fallback beside the
// warm relaxation: every level's result is the one thread's, field by field.
TEST_CASE("two threads give the one-thread cliques, the fallback run beside the relaxation") {
  int beside = 0;
  for (std::uint64_t seed : {21u, 22u, 31u, 32u}) {
    const PyramidGraph g = two_levels(300, 25, 0.05, 0.5, seed, seed > 30 ? 1 : 0);
    CliqueParams cp;
    cp.prove_first_min_edges = 0;
    cp.cascade_check_nodes = 30;
    cp.settle_selected = false;  // every level's full cascade, fallback included
    const auto one = solve_pyramid(g, cp);
    const auto two = solve_pyramid(g, cp, kNoDeadline, 2);
    REQUIRE(one.size() == two.size());
    for (std::size_t l = 0; l < one.size(); ++l) {
      INFO("seed " << seed << ", level " << l);
      CHECK(two[l].vertices == one[l].vertices);
      CHECK(two[l].proven == one[l].proven);
      CHECK(two[l].clique_number_bound == one[l].clique_number_bound);
      CHECK(two[l].budget == one[l].budget);
      CHECK(two[l].start == one[l].start);
      CHECK(two[l].gradient_steps == one[l].gradient_steps);
      CHECK(two[l].penalty_updates == one[l].penalty_updates);
      CHECK(two[l].u == one[l].u);
      beside += l > 0 && !one[l].proven;  // where the fallback ran
    }
  }
  CHECK(beside > 0);
}

// settle_selected: the first pass gives each level's searches probe_nodes, keeps the clique of a
// level they cannot prove without relaxing it, and runs no fallback; settle_level finishes such a
// level in two steps (the relaxation, then the search and the fallback), as the full cascade
// would: a clique no smaller, and never smaller than the independent solve's.
TEST_CASE(
    "a first pass leaves unproven levels unsettled, and settling one restores the guarantee") {
  int unsettled = 0;
  for (std::uint64_t seed : {21u, 22u, 23u}) {
    const PyramidGraph g = two_levels(300, 20, 0.05, 0.5, seed);
    CliqueParams cp;
    cp.prove_first_min_edges = 0;
    cp.cascade_check_nodes = 3000;
    cp.probe_nodes = 30;
    REQUIRE(cp.settle_selected);  // the default
    const auto first = solve_pyramid(g, cp);
    CliqueParams independent = cp;
    independent.solver = CliqueSolver::independent;
    independent.settle_selected = false;
    const auto cold = solve_pyramid(g, independent);
    for (std::size_t l = 0; l < first.size(); ++l) {
      const CliqueResult& r = first[l];
      INFO("seed " << seed << ", level " << l << ": " << r.vertices.size() << " members");
      CHECK(is_clique(g, static_cast<int>(l), r.vertices));
      CHECK(r.settled == (r.proven || r.budget == CliqueBudget::time));
      if (r.settled) {
        CHECK(r.budget != CliqueBudget::probe);
        continue;
      }
      ++unsettled;
      CHECK(r.budget == CliqueBudget::probe);
      CHECK_FALSE(r.relaxed);  // its bounded proof ran and failed: the relaxation waits
      CHECK(r.gradient_steps == 0);
      CliqueResult s = r;
      int steps = 0;
      while (!s.settled && steps < 3) {
        const CliqueResult before = s;
        s = settle_level(g, s, cp);
        ++steps;
        CHECK(is_clique(g, static_cast<int>(l), s.vertices));
        CHECK(s.vertices.size() >= before.vertices.size());  // never shrinks
        CHECK(s.time_ms >= before.time_ms);
        CHECK(s.relaxed);
      }
      CHECK(steps <= 2);
      CHECK(s.settled);
      CHECK(s.gradient_steps > 0);  // the relaxation ran
      CHECK(s.budget != CliqueBudget::probe);
      CHECK(s.vertices.size() >= cold[l].vertices.size());
      if (s.proven) CHECK(s.clique_number_bound == static_cast<int>(s.vertices.size()));
      const CliqueResult again = settle_level(g, s, cp);  // a settled level is left as it is
      CHECK(again.vertices == s.vertices);
      CHECK(again.time_ms == s.time_ms);
      // Two threads: the fallback beside the search, the same level.
      CliqueResult t = r;
      while (!t.settled) t = settle_level(g, t, cp, kNoDeadline, 2);
      CHECK(t.vertices == s.vertices);
      CHECK(t.proven == s.proven);
      CHECK(t.start == s.start);
    }
  }
  CHECK(unsettled > 0);  // the path was taken
}

// settle_selection steps the selected level until it is settled, fits it again whenever its
// clique changed and selects again after each step.
TEST_CASE("settle_selection settles what the selection picks, and selects again") {
  const PyramidGraph g = two_levels(300, 20, 0.05, 0.5, 22u);
  CliqueParams cp;
  cp.prove_first_min_edges = 0;
  cp.cascade_check_nodes = 3000;
  cp.probe_nodes = 0;  // the colouring's proof only: the dense level is left unsettled
  std::vector<CliqueResult> cliques = solve_pyramid(g, cp);
  REQUIRE(cliques.size() == 2);
  REQUIRE_FALSE(cliques[1].settled);
  // The same steps by hand: how many, and which changed the clique.
  int steps = 0, changes = 0;
  for (CliqueResult c = cliques[1]; !c.settled; ++steps) {
    const std::vector<int> before = c.vertices;
    c = settle_level(g, c, cp);
    changes += c.vertices != before;
  }
  int selections = 0;
  std::vector<int> refits;
  const double ms = settle_selection(
      g, cliques, cp, kNoDeadline,
      [&] {
        ++selections;
        return 1;
      },
      [&](int level) { refits.push_back(level); }, [](int) { return false; });
  CHECK(cliques[1].settled);
  CHECK(ms >= 0.0);
  CHECK(is_clique(g, 1, cliques[1].vertices));
  CHECK(selections == changes + 1);  // once first, then after every step that grew the clique
  CHECK(steps >= 1);
  CHECK(refits == std::vector<int>(static_cast<std::size_t>(changes), 1));
  CHECK(cliques[0].settled);  // never selected, never touched
  // Nothing selected, or the selected level's answer already given by a settled one: nothing
  // settled.
  std::vector<CliqueResult> untouched = solve_pyramid(g, cp);
  const auto never = [](int) { return false; };
  CHECK(settle_selection(
            g, untouched, cp, kNoDeadline, [] { return -1; }, [](int) {}, never) == 0.0);
  CHECK_FALSE(untouched[1].settled);
  int asked = 0;
  CHECK(settle_selection(
            g, untouched, cp, kNoDeadline, [] { return 1; }, [](int) {},
            [&](int level) {
              ++asked;
              return level == 1;
            }) == 0.0);
  CHECK(asked == 1);
  CHECK_FALSE(untouched[1].settled);
}

TEST_CASE("the paper's preset settles every level in the cascade") {
  CHECK_FALSE(preset_config("paper").clique.settle_selected);
  CHECK(default_config().clique.settle_selected);
  const PyramidGraph g = two_levels(300, 20, 0.05, 0.5, 21u);
  CliqueParams cp = preset_config("paper").clique;
  cp.cascade_check_nodes = 30;
  for (const CliqueResult& r : solve_pyramid(g, cp)) {
    CHECK(r.settled);
    CHECK(r.budget != CliqueBudget::probe);
  }
}

TEST_CASE("a clique through anchors: the largest that holds them, not the graph's largest") {
  // Two cliques, {0..5} and the larger {6..14}, and vertex 15 adjacent to 0..3 only.
  std::vector<std::vector<int>> adj(16);
  const auto join = [&](int a, int b) {
    adj[static_cast<std::size_t>(a)].push_back(b);
    adj[static_cast<std::size_t>(b)].push_back(a);
  };
  for (int a = 0; a < 6; ++a)
    for (int b = a + 1; b < 6; ++b) join(a, b);
  for (int a = 6; a < 15; ++a)
    for (int b = a + 1; b < 15; ++b) join(a, b);
  for (int a = 0; a < 4; ++a) join(a, 15);
  const PyramidGraph g = test::graph_from_lists(adj);
  const std::vector<int> small{0, 1, 2, 3, 4, 5};
  CHECK(clique_through(g, 0, {3}, 1000) == small);
  CHECK(clique_through(g, 0, {5, 2}, 1000) == small);
  CHECK(clique_through(g, 0, {15}, 1000) == std::vector<int>{0, 1, 2, 3, 15});
  // Anchors that are not adjacent: the largest subset that is a clique (here one of them, the
  // first), ids outside the graph ignored.
  CHECK(clique_through(g, 0, {3, 8, 99, -1}, 1000) == small);
  CHECK(clique_through(g, 0, {8, 3}, 1000).size() == 9u);
  CHECK(clique_through(g, 0, {99}, 1000).empty());
  CHECK(is_clique(g, 0, clique_through(g, 0, {15, 5}, 1000)));
  // No search (0 nodes): the greedy clique among the common neighbours, still through the anchor.
  const std::vector<int> greedy = clique_through(g, 0, {3}, 0);
  CHECK(is_clique(g, 0, greedy));
  CHECK(std::binary_search(greedy.begin(), greedy.end(), 3));
  {
    // A trap for the greedy clique: the anchor 0's neighbours are a complete bipartite graph on
    // 1..10 and 11..20 (degree 10, cliques of 2) and a clique on 21..26 (degree 5). Greedy from the
    // highest degrees finds 2 of them; the search, within its budget, the 6; at 0 nodes only the
    // greedy clique is taken.
    std::vector<std::vector<int>> t(27);
    const auto link = [&](int a, int b) {
      t[static_cast<std::size_t>(a)].push_back(b);
      t[static_cast<std::size_t>(b)].push_back(a);
    };
    for (int v = 1; v <= 26; ++v) link(0, v);
    for (int a = 1; a <= 10; ++a)
      for (int b = 11; b <= 20; ++b) link(a, b);
    for (int a = 21; a <= 26; ++a)
      for (int b = a + 1; b <= 26; ++b) link(a, b);
    const PyramidGraph trap = test::graph_from_lists(t);
    CHECK(clique_through(trap, 0, {0}, 0).size() == 3u);
    CHECK(clique_through(trap, 0, {0}, 1000) == std::vector<int>{0, 21, 22, 23, 24, 25, 26});
  }
  // More than 12 anchors: kept in their order while they stay a clique.
  CHECK(clique_through(g, 0, {6, 7, 8, 9, 10, 11, 12, 13, 14, 0, 1, 2, 3}, 1000).size() == 9u);
}

TEST_CASE("a clique through anchors on a level above the first, within a small budget") {
  // Level 1 holds a planted clique of 40 (from level 1 on) among 300 vertices; through one of its
  // members the search finds it, also with a budget too small for the whole graph's proof, and
  // never returns less than a clique through the anchor.
  const PyramidGraph g = two_levels(300, 40, 0.05, 0.3, 7, 1);
  for (const long budget : {0L, 50L, 100000L}) {
    const std::vector<int> c = clique_through(g, 1, {5}, budget);
    CAPTURE(budget, c.size());
    CHECK(is_clique(g, 1, c));
    CHECK(std::binary_search(c.begin(), c.end(), 5));
    if (budget == 100000) CHECK(c.size() >= 40u);
  }
  CHECK(clique_through(g, 0, {5}, 100000).size() < 40u);  // level 0 has no such clique
}

TEST_CASE("above a level its probe could not settle, a level gets the colouring's proof alone") {
  // Level 0 dense (half of all pairs), too hard for a probe of 1,000 nodes; level 1 adds a
  // planted clique of 40 that such a probe finds there (and proves) when it runs. The first pass
  // leaves level 0 unsettled and gives level 1 no search: it keeps level 0's clique grown,
  // unsettled too; settling it finds the planted clique.
  const PyramidGraph g = two_levels(300, 40, 0.5, 0.6, 5, 1);
  CliqueParams cp;
  cp.prove_first_min_edges = 0;
  cp.probe_nodes = 1000;
  const auto first = solve_pyramid(g, cp);
  REQUIRE(first.size() == 2u);
  CHECK(first[0].budget == CliqueBudget::probe);
  CHECK(first[1].budget == CliqueBudget::probe);
  CHECK(first[1].vertices.size() < 40u);
  CHECK(is_clique(g, 1, first[1].vertices));
  CliqueResult s = first[1];
  while (!s.settled) s = settle_level(g, s, cp);
  CHECK(s.vertices.size() >= 40u);
  CHECK(is_clique(g, 1, s.vertices));
}
