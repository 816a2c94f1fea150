// Sections 2, 7 and 8: the densest-clique step, cascaded against independent, on the all-to-all
// scene, on issue 11's association problems and on the graphs of the shared KITTI pairs.

#include <cstdio>

#include "bench_sections.hpp"
#include "bench_util.hpp"
#include "pagor/eval/association_problem.hpp"
#include "pagor/graph/pyramid_graph.hpp"
#include "pagor/pipeline.hpp"

namespace pagor::bench {
namespace {

// Per level "size (precision/recall)" of cliques against ground-truth flags.
std::string clique_quality(const std::vector<CliqueResult>& cliques,
                           const std::vector<char>& inlier) {
  std::size_t total = 0;
  for (char f : inlier) total += f != 0;
  std::string out;
  for (const auto& c : cliques) {
    std::size_t hit = 0;
    for (int v : c.vertices) hit += inlier[static_cast<std::size_t>(v)] != 0;
    const double precision = c.vertices.empty() ? 0.0 : double(hit) / c.vertices.size();
    const double recall = total ? double(hit) / total : 0.0;
    out += (out.empty() ? "" : ", ") + std::to_string(c.vertices.size()) + " (" + fmt(precision) +
           "/" + fmt(recall) + ")";
  }
  return out;
}

// "same sets", "same sizes" or "differ".
const char* agreement(const SolverComparison& c) {
  return c.same_sets() ? "same sets" : c.same_sizes() ? "same sizes" : "differ";
}

}  // namespace

void bench_clique(const Options& o) {
  std::printf(
      "\n## 2. Densest clique, 4 levels: cascaded (warm start) vs independent (same random "
      "start)\n");
  const std::vector<int> w = {8, 12, 12, 10, 12, 12, 10, 18};
  row({"m", "cascaded", "independent", "ratio", "steps casc.", "steps indep.", "sizes",
       "exact (level 0)"},
      w);
  GraphParams gp;
  for (int m : {500, 1000, 2000}) {
    const auto c = all_to_all_scene(m, 0.05, 2);
    const PyramidGraph g = build_pyramid_graph(c, gp);
    const SolverComparison r = cascaded_vs_independent(g, o.reps);
    CliqueParams exact;
    exact.exact_max_nodes = 2000000;
    CliqueResult e;
    const Timing te = measure([&] { e = exact_max_clique(g, 0, exact); }, 1, 0);
    const std::string exact_text =
        e.proven ? fmt(te.median(), 1) + " ms, " +
                       (e.vertices.size() == r.a[0].vertices.size() ? "same" : "differs")
                 : "budget hit";
    row({std::to_string(c.size()), fmt(r.time_a.median(), 3) + " ms",
         fmt(r.time_b.median(), 3) + " ms", fmt(r.ratio()) + "x",
         std::to_string(gradient_steps(r.a)), std::to_string(gradient_steps(r.b)), agreement(r),
         exact_text},
        w);
    std::printf("         clique sizes per level: cascaded %s, independent %s%s\n",
                sizes(r.a).c_str(), sizes(r.b).c_str(),
                r.same_sets()
                    ? ""
                    : " (equal-size cliques differ in members: ties between maximum cliques)");
  }
  // The same without k-core pruning: the relaxation alone, as in CLIPPER.
  std::printf("without k-core pruning (relaxation on every vertex):\n");
  for (int m : {500, 1000}) {
    const auto c = all_to_all_scene(m, 0.05, 2);
    const PyramidGraph g = build_pyramid_graph(c, gp);
    CliqueParams unpruned;
    unpruned.prune = false;
    const SolverComparison r = cascaded_vs_independent(g, 5, unpruned);
    row({std::to_string(c.size()), fmt(r.time_a.median(), 3) + " ms",
         fmt(r.time_b.median(), 3) + " ms", fmt(r.ratio()) + "x", "", "", agreement(r), ""},
        w);
  }
}

// Issue 11's problem set: random points, 10 % inliers, difference TRIM, 4 levels, Gaussian
// affinity. The clique step alone (graph built once), cascaded and independent in the same run,
// and the exact solver on all 4 levels.
void bench_association(const Options& o) {
  std::printf(
      "\n## 7. Association problems (issue 11): random points in a 10 m cube, 10 %% inliers with "
      "noise <= 0.02 m,\n##    difference TRIM, eps = 0.03/0.06/0.12/0.24 m, Gaussian affinity "
      "sigma = eps/2; clique step, 4 levels, 1 thread\n");
  const std::vector<int> w = {6, 10, 24, 12, 12, 8, 16, 10};
  row({"m", "graph", "density per level [%]", "cascaded", "independent", "ratio", "exact (4 lev.)",
       "same size"},
      w);
  std::vector<std::string> notes;
  const GraphParams gp = association_graph_params();
  for (int m : {100, 500, 1000, 2000, 5000}) {
    AssociationParams ap;
    ap.m = m;
    ap.seed = static_cast<std::uint64_t>(m);
    const AssociationProblem problem = association_problem(ap);
    if (!o.write_dir.empty()) {
      const std::string path = o.write_dir + "/association_m" + std::to_string(m) + ".txt";
      if (!write_association_problem(path, problem,
                                     "pagor_bench association problem m = " + std::to_string(m) +
                                         ", seed " + std::to_string(ap.seed)))
        std::printf("(could not write %s)\n", path.c_str());
    }
    PyramidGraph g;
    const Timing tg = measure([&] { g = build_pyramid_graph(problem.correspondences, gp, 1); },
                              m >= 2000 ? 3 : 5);
    std::string density;
    const double pairs = 0.5 * m * (m - 1.0);
    for (std::size_t l = 0; l < g.edges_at_level.size(); ++l)
      density += (l ? "/" : "") + fmt(100.0 * g.edges_at_level[l] / pairs, 2);
    const SolverComparison r =
        cascaded_vs_independent(g, m >= 2000 ? std::max(3, o.reps / 3) : o.reps);
    CliqueParams exact;
    exact.solver = CliqueSolver::exact;
    exact.exact_max_nodes = 1000000;
    std::vector<CliqueResult> e;
    const Timing te = measure([&] { e = solve_pyramid(g, exact); }, m >= 2000 ? 1 : 3, 0);
    bool optimal = true;
    for (const auto& level : e) optimal = optimal && level.proven;
    row({std::to_string(m), fmt(tg.median(), 1) + " ms", density, fmt(r.time_a.median(), 3) + " ms",
         fmt(r.time_b.median(), 3) + " ms", fmt(r.ratio()) + "x",
         fmt(te.median(), 1) + (optimal ? " ms" : " ms (budget)"), r.same_sizes() ? "yes" : "no"},
        w);
    notes.push_back("m = " + std::to_string(m) + ": cliques (precision/recall) cascaded " +
                    clique_quality(r.a, problem.inlier) + "; independent " + sizes(r.b) +
                    "; exact " + sizes(e) + (optimal ? "" : " (not proven)"));
  }
  for (const auto& n : notes) std::printf("  %s\n", n.c_str());
}

// The cascade on the real pairs: the clique step of the default pipeline, cascaded vs
// independent, on the graphs of the shared KITTI pairs.
void bench_cascade_kitti(const Options& o) {
  std::printf("\n## 8. Cascaded vs independent clique step on the KITTI pairs (default config)\n");
  const std::vector<int> w = {8, 8, 12, 12, 8, 12, 14, 12, 12, 14, 14};
  row({"pair", "m", "cascaded", "independent", "ratio", "exact", "sizes exact", "steps casc.",
       "steps indep.", "sizes casc.", "sizes indep."},
      w);
  for (const auto& [s, t] : {std::pair{0, 20}, std::pair{20, 30}, std::pair{0, 30}}) {
    const auto pair = kitti_pair(o.kitti_root, s, t);
    if (!pair) return;
    Pipeline p(default_config(), 1);
    p.set_input(pair->first.cloud, pair->second.cloud);
    p.run();
    const PyramidGraph& g = p.graph();
    const SolverComparison r = cascaded_vs_independent(g, o.reps, p.config().clique);
    CliqueParams exact = p.config().clique;
    exact.solver = CliqueSolver::exact;
    std::vector<CliqueResult> e;
    const Timing te = measure([&] { e = solve_pyramid(g, exact); }, o.reps);
    row({std::to_string(s) + "->" + std::to_string(t), std::to_string(g.vertices),
         fmt(r.time_a.median(), 3) + " ms", fmt(r.time_b.median(), 3) + " ms", fmt(r.ratio()) + "x",
         fmt(te.median(), 3) + " ms", sizes(e), std::to_string(gradient_steps(r.a)),
         std::to_string(gradient_steps(r.b)), sizes(r.a), sizes(r.b)},
        w);
  }
}

}  // namespace pagor::bench
