#include <algorithm>
#include <catch2/catch.hpp>
#include <random>

#include "pagor/graph/pyramid_graph.hpp"
#include "pagor/graph/trim.hpp"
#include "util/random_draw.hpp"

using namespace pagor;

namespace {

std::vector<Correspondence> random_correspondences(int m, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> coord(-30.0, 30.0);
  std::uniform_int_distribution<int> landmark(0, m / 3);
  std::vector<Correspondence> c(static_cast<std::size_t>(m));
  for (auto& x : c) {
    x.class_index = 0;
    x.source = landmark(rng);  // repeated landmarks on purpose
    x.target = landmark(rng);
    x.p = draw3(coord, rng);
    x.p.z() *= 0.1;
    // Half of them consistent with a pure translation, so every level has edges.
    x.q = (x.source % 2 == 0) ? x.p + Eigen::Vector3d(5, 1, 0) : draw_on_plane(coord, rng, 0.0);
  }
  return c;
}

// Checks, array by array (a failure names the array), that `got` is the graph `want` is.
void check_same_graph(const PyramidGraph& got, const PyramidGraph& want) {
  CHECK(got.vertices == want.vertices);
  CHECK(got.thresholds == want.thresholds);
  CHECK(got.offsets == want.offsets);
  CHECK(got.neighbors == want.neighbors);
  CHECK(got.level == want.level);
  CHECK(got.trim == want.trim);
  CHECK(got.edges_at_level == want.edges_at_level);
}

// Lowest level of pair (i, j) by the definition, or -1.
int reference_level(const std::vector<Correspondence>& c, std::size_t i, std::size_t j,
                    const GraphParams& p) {
  if (c[i].source == c[j].source || c[i].target == c[j].target) return -1;
  const double a = (c[i].p - c[j].p).norm(), b = (c[i].q - c[j].q).norm();
  if (a < p.min_length || b < p.min_length) return -1;
  const double t = trim_value(p.trim, a, b);
  for (std::size_t l = 0; l < p.thresholds.size(); ++l)
    if (t <= p.thresholds[l]) return static_cast<int>(l);
  return -1;
}

}  // namespace

TEST_CASE("TRIM values") {
  CHECK(trim_value(TrimKind::difference, 10.0, 10.5) == Approx(0.5));
  CHECK(trim_value(TrimKind::ratio, 10.0, 12.0) == Approx(0.2));
  CHECK(trim_value(TrimKind::ratio, 12.0, 10.0) == Approx(0.2));
  CHECK(trim_value(TrimKind::ratio, 0.0, 1.0) == HUGE_VAL);
}

TEST_CASE("the one-pass pyramid equals the per-level definition, for both TRIM kinds") {
  const auto c = random_correspondences(300, 11);
  for (TrimKind kind : {TrimKind::difference, TrimKind::ratio}) {
    GraphParams p;
    p.trim = kind;
    p.thresholds = kind == TrimKind::ratio ? std::vector<double>{0.01, 0.03, 0.1}
                                           : std::vector<double>{0.1, 0.3, 1.0};
    const PyramidGraph g = build_pyramid_graph(c, p);
    REQUIRE(g.levels() == 3);
    std::vector<std::size_t> count(3, 0);
    for (std::size_t i = 0; i < c.size(); ++i)
      for (std::size_t j = 0; j < c.size(); ++j) {
        if (i == j) continue;
        const int ref = reference_level(c, std::min(i, j), std::max(i, j), p);
        for (int l = 0; l < 3; ++l) {
          const bool expected = ref >= 0 && ref <= l;
          if (g.adjacent(static_cast<int>(i), static_cast<int>(j), l) != expected) {
            FAIL("pair " << i << ", " << j << " at level " << l << ": expected " << expected);
          }
          if (i < j && expected) ++count[static_cast<std::size_t>(l)];
        }
      }
    for (int l = 0; l < 3; ++l)
      CHECK(g.edges_at_level[static_cast<std::size_t>(l)] == count[static_cast<std::size_t>(l)]);
    CHECK(g.edges_at_level[0] > 0);
    CHECK(g.edges_at_level[0] <= g.edges_at_level[1]);
    CHECK(g.edges_at_level[1] <= g.edges_at_level[2]);
  }
}

TEST_CASE("threads give the same graph") {
  const auto c = random_correspondences(500, 3);
  GraphParams p;
  const PyramidGraph one = build_pyramid_graph(c, p, 1);
  const PyramidGraph two = build_pyramid_graph(c, p, 2);
  const PyramidGraph three = build_pyramid_graph(c, p, 3);
  check_same_graph(two, one);
  check_same_graph(three, one);
}

TEST_CASE("a builder reusing its storage gives the graphs of fresh builds, whatever came before") {
  // Larger, smaller, empty, then larger again; threads and TRIM kinds change between builds, so
  // the kept arrays and scratch are both longer and shorter than the next graph needs.
  struct Step {
    int m;
    std::uint64_t seed;
    int threads;
    TrimKind trim;
  };
  const Step steps[] = {{700, 1, 1, TrimKind::ratio},      {300, 2, 2, TrimKind::difference},
                        {0, 3, 1, TrimKind::ratio},        {900, 4, 3, TrimKind::ratio},
                        {600, 5, 1, TrimKind::difference}, {900, 4, 1, TrimKind::ratio}};
  PyramidGraphBuilder builder;
  CHECK(builder.graph().vertices == 0);
  const PyramidGraph& kept = builder.graph();
  for (const Step& s : steps) {
    const auto c = random_correspondences(s.m, s.seed);
    GraphParams p;
    p.trim = s.trim;
    if (s.trim == TrimKind::difference) p.thresholds = {0.1, 0.3, 1.0};
    const PyramidGraph fresh = build_pyramid_graph(c, p, 1);
    const PyramidGraph& built = builder.build(c, p, s.threads);
    CAPTURE(s.m, s.threads);
    CHECK(&built == &kept);  // the same object, rebuilt
    CHECK(built.vertices == s.m);
    CHECK(built.thresholds == p.thresholds);
    check_same_graph(built, fresh);
    if (s.m > 0) CHECK(built.edges_at_level.back() > 0);
  }
  // A copy has the graph; a moved-from builder builds again.
  PyramidGraphBuilder copy = builder;
  CHECK(copy.graph().neighbors == builder.graph().neighbors);
  PyramidGraphBuilder moved = std::move(builder);
  CHECK(builder.graph().vertices == 0);  // NOLINT(bugprone-use-after-move): left empty
  CHECK(builder.graph().offsets.empty());
  const auto c = random_correspondences(200, 9);
  builder.build(c, GraphParams{});  // NOLINT(bugprone-use-after-move): rebuilt on purpose
  CHECK(builder.graph().neighbors == build_pyramid_graph(c, GraphParams{}).neighbors);
  CHECK(moved.graph().vertices == 900);
}

TEST_CASE("large and far-flung graphs (tiled placement, the exact path) equal the definition") {
  // m = 2500 spans three tiles of target rows and many blocks; coordinates of +-3e5 m take the
  // exact test on every pair (no single-precision pass). Built in one builder with 3 threads,
  // compared with a fresh 1-thread build and, on a sample of rows, with the definition.
  PyramidGraphBuilder builder;
  for (const double scale : {1.0, 1e4}) {
    auto c = random_correspondences(scale == 1.0 ? 2500 : 600, 21);
    for (auto& x : c) {
      x.p *= scale;
      x.q *= scale;
    }
    GraphParams p;  // ratio TRIM: the same consistency at any scale
    p.trim = TrimKind::ratio;
    p.thresholds = {0.01, 0.03, 0.1};
    const PyramidGraph& g = builder.build(c, p, 3);
    const PyramidGraph one = build_pyramid_graph(c, p, 1);
    CAPTURE(scale, c.size());
    check_same_graph(g, one);
    REQUIRE(g.edges_at_level.back() > 0);
    for (int v = 0; v < g.vertices; ++v) {  // rows sorted, every edge in both rows, same level
      const auto b = static_cast<std::size_t>(g.offsets[static_cast<std::size_t>(v)]);
      const auto e = static_cast<std::size_t>(g.offsets[static_cast<std::size_t>(v) + 1]);
      REQUIRE(std::is_sorted(g.neighbors.begin() + b, g.neighbors.begin() + e));
      for (std::size_t k = b; k < e; ++k) REQUIRE(g.adjacent(g.neighbors[k], v, g.level[k]));
    }
    for (std::size_t i = 0; i < c.size(); i += 37)
      for (std::size_t j = 0; j < c.size(); ++j) {
        if (i == j) continue;
        const int ref = reference_level(c, std::min(i, j), std::max(i, j), p);
        for (int l = 0; l < 3; ++l)
          if (g.adjacent(static_cast<int>(i), static_cast<int>(j), l) != (ref >= 0 && ref <= l))
            FAIL("pair " << i << ", " << j << " at level " << l << ": expected level " << ref);
      }
  }
}

TEST_CASE("the edges' TRIM values are kept for the gaussian affinity alone, as the definition") {
  // A builder alternating the affinities (its scratch keeps or drops the values), on 1 and 3
  // threads: under the binary affinity no value is kept, under the gaussian every edge's is its
  // TRIM in single precision, in both rows.
  const auto c = random_correspondences(1500, 31);
  PyramidGraphBuilder builder;
  for (const AffinityKind affinity :
       {AffinityKind::gaussian, AffinityKind::binary, AffinityKind::gaussian}) {
    for (const int threads : {1, 3}) {
      GraphParams p;
      p.affinity = affinity;
      const PyramidGraph& g = builder.build(c, p, threads);
      CAPTURE(to_string(affinity), threads);
      REQUIRE(g.edges_at_level.back() > 0);
      if (affinity == AffinityKind::binary) {
        CHECK(g.trim.empty());
        continue;
      }
      REQUIRE(g.trim.size() == g.neighbors.size());
      for (int v = 0; v < g.vertices; ++v)
        for (auto e = static_cast<std::size_t>(g.offsets[static_cast<std::size_t>(v)]);
             e < static_cast<std::size_t>(g.offsets[static_cast<std::size_t>(v) + 1]); ++e) {
          const auto& a = c[static_cast<std::size_t>(v)];
          const auto& b = c[static_cast<std::size_t>(g.neighbors[e])];
          const float want =
              static_cast<float>(trim_value(p.trim, (a.p - b.p).norm(), (a.q - b.q).norm()));
          if (g.trim[e] != want) FAIL("edge " << v << ", " << g.neighbors[e] << ": " << g.trim[e]);
        }
      check_same_graph(g, build_pyramid_graph(c, p, 1));
    }
  }
}

TEST_CASE("gaussian affinities fall with the TRIM and vanish above the level") {
  std::vector<Correspondence> c(3);
  c[0] = {0, 0, 0, {0, 0, 0}, {0, 0, 0}, 1};
  c[1] = {0, 1, 1, {10, 0, 0}, {10.05, 0, 0}, 1};  // difference 0.05 with c[0]
  c[2] = {0, 2, 2, {0, 10, 0}, {0, 10.4, 0}, 1};   // difference 0.4 with c[0]
  GraphParams p;
  p.trim = TrimKind::difference;
  p.thresholds = {0.1, 0.5};
  p.affinity = AffinityKind::gaussian;
  p.sigma_ratio = 0.5;
  const PyramidGraph g = build_pyramid_graph(c, p);
  auto edge = [&](int u, int v) {
    for (auto e = g.offsets[static_cast<std::size_t>(u)];
         e < g.offsets[static_cast<std::size_t>(u) + 1]; ++e)
      if (g.neighbors[static_cast<std::size_t>(e)] == v) return static_cast<std::size_t>(e);
    FAIL("no edge " << u << "-" << v);
    return std::size_t{0};
  };
  CHECK(g.weight(edge(0, 1), 0) ==
        Approx(std::exp(-0.05 * 0.05 / (2 * 0.05 * 0.05))).epsilon(1e-4));
  CHECK(g.weight(edge(0, 2), 0) == 0.0);
  CHECK(g.weight(edge(0, 2), 1) == Approx(std::exp(-0.4 * 0.4 / (2 * 0.25 * 0.25))).epsilon(1e-4));
}

TEST_CASE("empty and tiny inputs") {
  GraphParams p;
  const PyramidGraph empty = build_pyramid_graph({}, p);
  CHECK(empty.vertices == 0);
  CHECK(empty.edges_at_level.size() == p.thresholds.size());
  std::vector<Correspondence> one(1);
  const PyramidGraph single = build_pyramid_graph(one, p, 4);
  CHECK(single.vertices == 1);
  CHECK(single.neighbors.empty());
}
