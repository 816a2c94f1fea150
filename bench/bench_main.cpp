// pagor_bench: the benchmark suite. Medians over repeated runs; comparisons are ratios measured in
// the same run. Never asserts anything about time: the tests do the correctness.
//
//   build/bench/pagor_bench [--kitti-root DIR] [--reps N] [--write-problems DIR] [--only
//   graph|clique|gnc|verification|e2e|studio|association|cascade]

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>
#include <string>

#include "association_problem.hpp"
#include "bench_util.hpp"
#include "pagor/densest_clique.hpp"
#include "pagor/gnc.hpp"
#include "pagor/kitti.hpp"
#include "pagor/pipeline.hpp"
#include "pagor/pyramid_graph.hpp"
#include "pagor/verification.hpp"

using namespace pagor;
using namespace pagor::bench;

namespace {

int g_reps = 15;

void bench_graph() {
  std::printf(
      "\n## 1. Pyramid graph, k = 4 levels (ratio TRIM, default thresholds), all-to-all scene\n");
  const std::vector<int> w = {8, 10, 12, 12, 12, 14, 12};
  row({"m", "edges@k", "1 thread", "2 threads", "speed-up", "peak [MB]", "dense [MB]"}, w);
  GraphParams gp;
  double t100 = 0, previous_t = 0;
  int previous_m = 0;
  std::string growth;
  for (int m : {100, 500, 1000, 2000, 5000}) {
    const auto c = all_to_all_scene(m, 0.05, 1);
    PyramidGraph g;
    const Timing one = measure([&] { g = build_pyramid_graph(c, gp, 1); }, m >= 2000 ? 5 : g_reps);
    const Timing two = measure([&] { g = build_pyramid_graph(c, gp, 2); }, m >= 2000 ? 5 : g_reps);
    const double peak = peak_memory_mb([&] {
      const auto h = build_pyramid_graph(c, gp, 1);
      (void)h;
    });
    const double dense =
        4.0 * c.size() * c.size() * sizeof(double) / 1e6;  // an m x m double matrix per level
    row({std::to_string(c.size()), std::to_string(g.edges_at_level.back()),
         fmt(one.median(), 3) + " ms", fmt(two.median(), 3) + " ms",
         fmt(one.median() / two.median()) + "x", fmt(peak, 1), fmt(dense, 0)},
        w);
    if (m == 100) t100 = one.median();
    if (previous_m) {
      growth +=
          "  m " + std::to_string(previous_m) + " -> " + std::to_string(c.size()) + ": time x" +
          fmt(one.median() / previous_t, 1) + " (m^" +
          fmt(std::log(one.median() / previous_t) / std::log(double(c.size()) / previous_m), 2) +
          ")\n";
    }
    previous_t = one.median();
    previous_m = static_cast<int>(c.size());
  }
  std::printf("growth (pairs grow as m^2):\n%s", growth.c_str());
  (void)t100;
}

void bench_clique() {
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
    CliqueParams cascaded, independent;
    independent.solver = CliqueSolver::independent;
    std::vector<CliqueResult> a, b;
    const Timing ta = measure([&] { a = solve_pyramid(g, cascaded); }, g_reps);
    const Timing tb = measure([&] { b = solve_pyramid(g, independent); }, g_reps);
    int sa = 0, sb = 0;
    bool agree = true, same_sizes = true;
    std::string sizes_a, sizes_b;
    for (std::size_t l = 0; l < a.size(); ++l) {
      sa += a[l].gradient_steps;
      sb += b[l].gradient_steps;
      agree = agree && a[l].vertices == b[l].vertices;
      same_sizes = same_sizes && a[l].vertices.size() == b[l].vertices.size();
      sizes_a += (l ? "," : "") + std::to_string(a[l].vertices.size());
      sizes_b += (l ? "," : "") + std::to_string(b[l].vertices.size());
    }
    CliqueParams exact;
    exact.exact_max_nodes = 2000000;
    CliqueResult e;
    const Timing te = measure([&] { e = exact_max_clique(g, 0, exact); }, 1, 0);
    const std::string exact_text =
        e.optimal ? fmt(te.median(), 1) + " ms, " +
                        (e.vertices.size() == a[0].vertices.size() ? "same" : "differs")
                  : "budget hit";
    row({std::to_string(c.size()), fmt(ta.median(), 3) + " ms", fmt(tb.median(), 3) + " ms",
         fmt(tb.median() / ta.median()) + "x", std::to_string(sa), std::to_string(sb),
         agree        ? "same sets"
         : same_sizes ? "same sizes"
                      : "differ",
         exact_text},
        w);
    std::printf(
        "         clique sizes per level: cascaded %s, independent %s%s\n", sizes_a.c_str(),
        sizes_b.c_str(),
        agree ? "" : " (equal-size cliques differ in members: ties between maximum cliques)");
  }
  // The same without k-core pruning: the relaxation alone, as in CLIPPER.
  std::printf("without k-core pruning (relaxation on every vertex):\n");
  for (int m : {500, 1000}) {
    const auto c = all_to_all_scene(m, 0.05, 2);
    const PyramidGraph g = build_pyramid_graph(c, gp);
    CliqueParams cascaded, independent;
    cascaded.prune = independent.prune = false;
    independent.solver = CliqueSolver::independent;
    std::vector<CliqueResult> a, b;
    const Timing ta = measure([&] { a = solve_pyramid(g, cascaded); }, 5);
    const Timing tb = measure([&] { b = solve_pyramid(g, independent); }, 5);
    bool agree = true;
    for (std::size_t l = 0; l < a.size(); ++l) agree = agree && a[l].vertices == b[l].vertices;
    row({std::to_string(c.size()), fmt(ta.median(), 3) + " ms", fmt(tb.median(), 3) + " ms",
         fmt(tb.median() / ta.median()) + "x", "", "", agree ? "yes" : "no", ""},
        w);
  }
}

void bench_gnc() {
  std::printf("\n## 3. GNC-TLS for one clique (20 %% outliers, noise 0.05 m)\n");
  const std::vector<int> w = {8, 12, 12};
  row({"size", "SE(3)", "SE(2)"}, w);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> coord(-40.0, 40.0);
  std::normal_distribution<double> noise(0.0, 0.05);
  Transform T = Transform::Identity();
  T.block<3, 3>(0, 0) = Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  T.block<3, 1>(0, 3) = Eigen::Vector3d(10, 2, 0);
  for (int n : {10, 50, 100, 500}) {
    std::vector<Eigen::Vector3d> p, q;
    for (int i = 0; i < n; ++i) {
      p.emplace_back(coord(rng), coord(rng), coord(rng) / 10);
      q.push_back(i < n * 4 / 5
                      ? Eigen::Vector3d(T.block<3, 3>(0, 0) * p.back() + T.block<3, 1>(0, 3) +
                                        Eigen::Vector3d(noise(rng), noise(rng), noise(rng)))
                      : Eigen::Vector3d(coord(rng), coord(rng), 0));
    }
    GncParams se3, se2;
    se2.model = PoseModel::se2;
    const Timing a = measure([&] { estimate_pose_gnc(p, q, se3); }, g_reps * 4);
    const Timing b = measure([&] { estimate_pose_gnc(p, q, se2); }, g_reps * 4);
    row({std::to_string(n), fmt(a.median(), 4) + " ms", fmt(b.median(), 4) + " ms"}, w);
  }
}

std::optional<std::pair<LoadedCloud, LoadedCloud>> kitti_pair(const std::string& root, int s,
                                                              int t) {
  try {
    const KittiSequence seq(root, "00");
    return std::make_pair(seq.load_frame(s), seq.load_frame(t));
  } catch (const std::exception& e) {
    std::printf("(skipped: %s)\n", e.what());
    return std::nullopt;
  }
}

void bench_verification(const std::string& root) {
  std::printf("\n## 4. Verification of 4 candidates on the full KITTI scans 20 -> 30\n");
  const auto pair = kitti_pair(root, 20, 30);
  if (!pair) return;
  const KittiSequence seq(root, "00");
  const Transform gt = seq.ground_truth(20, 30);
  std::vector<PoseEstimate> candidates(4);
  for (int i = 0; i < 4; ++i) {
    candidates[static_cast<std::size_t>(i)].valid = true;
    Transform d = Transform::Identity();
    d(0, 3) = 0.3 * i;
    candidates[static_cast<std::size_t>(i)].T_target_source = d * gt;
  }
  const std::vector<int> w = {10, 12, 14, 14, 14, 10};
  row({"voxel [m]", "points", "prepare", "score x4 (1t)", "score x4 (2t)", "speed-up"}, w);
  for (double voxel : {0.25, 0.5, 1.0}) {
    std::optional<Verifier> v;
    const Timing prep =
        measure([&] { v.emplace(pair->first.cloud, pair->second.cloud, voxel); }, 5);
    VerificationParams vp;
    const Timing one = measure([&] { verify_candidates(*v, candidates, vp, 1); }, g_reps);
    const Timing two = measure([&] { verify_candidates(*v, candidates, vp, 2); }, g_reps);
    row({fmt(voxel), std::to_string(v->source_points().size()), fmt(prep.median(), 2) + " ms",
         fmt(one.median(), 2) + " ms", fmt(two.median(), 2) + " ms",
         fmt(one.median() / two.median()) + "x"},
        w);
  }
}

void bench_end_to_end(const std::string& root) {
  std::printf(
      "\n## 5. End to end per KITTI pair (clouds in memory -> selected pose), by stage [ms]\n");
  const Stage stages[] = {
      Stage::landmarks, Stage::correspondences,   Stage::graph,       Stage::clique,
      Stage::pose,      Stage::verification_prep, Stage::verification};
  std::vector<int> w = {10, 8};
  std::vector<std::string> head = {"pair", "threads"};
  for (Stage s : stages) {
    head.push_back(stage_name(s));
    w.push_back(std::max<int>(7, static_cast<int>(std::strlen(stage_name(s)))));
  }
  head.push_back("total");
  w.push_back(8);
  row(head, w);
  for (const auto& [s, t] : {std::pair{0, 20}, std::pair{20, 30}, std::pair{0, 30}}) {
    const auto pair = kitti_pair(root, s, t);
    if (!pair) return;
    double totals[2] = {0, 0};
    for (int threads : {1, 2}) {
      std::vector<std::vector<double>> per(std::size(stages));
      const Timing total = measure(
          [&] {
            Pipeline p(default_config(), threads);
            p.set_input(pair->first.cloud, pair->second.cloud);
            p.run();
            for (std::size_t i = 0; i < std::size(stages); ++i)
              per[i].push_back(p.time_ms(stages[i]));
          },
          std::max(3, g_reps / 2));
      std::vector<std::string> cells = {std::to_string(s) + "->" + std::to_string(t),
                                        std::to_string(threads)};
      for (auto& v : per) cells.push_back(fmt(Timing{v}.median(), 1));
      cells.push_back(fmt(total.median(), 1));
      row(cells, w);
      totals[threads - 1] = total.median();
    }
    std::printf("%10s speed-up with 2 threads: %.2fx\n", "", totals[0] / totals[1]);
  }
}

void bench_studio(const std::string& root) {
  std::printf(
      "\n## 6. Studio re-run latency on KITTI 20 -> 30 (pipeline with caching, 1 thread)\n");
  const auto pair = kitti_pair(root, 20, 30);
  if (!pair) return;
  Pipeline p(default_config(), 1);
  p.set_input(pair->first.cloud, pair->second.cloud);
  p.run();
  const std::vector<int> w = {28, 12};
  row({"change", "re-run"}, w);
  int k = 0;
  const auto rerun = [&](const char* name, const std::function<void(Config&)>& edit) {
    const Timing t = measure(
        [&] {
          Config c = p.config();
          edit(c);
          // Alternate between two values so that every run has something to recompute.
          p.set_config(c);
          p.run();
        },
        g_reps, 1);
    row({name, fmt(t.median(), 2) + " ms"}, w);
  };
  rerun("mu", [&](Config& c) { c.verification.mu = (++k % 2) ? 1.2 : 1.0; });
  rerun("one threshold", [&](Config& c) { c.graph.thresholds[1] = (++k % 2) ? 0.05 : 0.04; });
  rerun("clustering (car tolerance)",
        [&](Config& c) { c.landmarks.classes[0].cluster_tolerance = (++k % 2) ? 0.55 : 0.5; });
}

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

std::string sizes(const std::vector<CliqueResult>& cliques) {
  std::string out;
  for (const auto& c : cliques) out += (out.empty() ? "" : ",") + std::to_string(c.vertices.size());
  return out;
}

// Issue 11's problem set: random points, 10 % inliers, difference TRIM, 4 levels, Gaussian
// affinity. The clique step alone (graph built once), cascaded and independent in the same run,
// and the exact solver on all 4 levels.
void bench_association(const std::string& write_dir) {
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
    if (!write_dir.empty()) {
      const std::string path = write_dir + "/association_m" + std::to_string(m) + ".txt";
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
    CliqueParams cascaded, independent, exact;
    independent.solver = CliqueSolver::independent;
    exact.solver = CliqueSolver::exact;
    exact.exact_max_nodes = 1000000;
    const int reps = m >= 2000 ? std::max(3, g_reps / 3) : g_reps;
    std::vector<CliqueResult> a, b, e;
    const Timing ta = measure([&] { a = solve_pyramid(g, cascaded); }, reps);
    const Timing tb = measure([&] { b = solve_pyramid(g, independent); }, reps);
    const Timing te = measure([&] { e = solve_pyramid(g, exact); }, m >= 2000 ? 1 : 3, 0);
    bool optimal = true, same = true;
    for (std::size_t l = 0; l < e.size(); ++l) {
      optimal = optimal && e[l].optimal;
      same = same && a[l].vertices.size() == b[l].vertices.size();
    }
    row({std::to_string(m), fmt(tg.median(), 1) + " ms", density, fmt(ta.median(), 3) + " ms",
         fmt(tb.median(), 3) + " ms", fmt(tb.median() / ta.median()) + "x",
         fmt(te.median(), 1) + (optimal ? " ms" : " ms (budget)"), same ? "yes" : "no"},
        w);
    notes.push_back("m = " + std::to_string(m) + ": cliques (precision/recall) cascaded " +
                    clique_quality(a, problem.inlier) + "; independent " + sizes(b) + "; exact " +
                    sizes(e) + (optimal ? "" : " (not proven)"));
  }
  for (const auto& n : notes) std::printf("  %s\n", n.c_str());
}

// The cascade on the real pairs: the clique step of the default pipeline, cascaded vs
// independent, on the graphs of the shared KITTI pairs.
void bench_cascade_kitti(const std::string& root) {
  std::printf("\n## 8. Cascaded vs independent clique step on the KITTI pairs (default config)\n");
  const std::vector<int> w = {8, 8, 12, 12, 8, 20, 20};
  row({"pair", "m", "cascaded", "independent", "ratio", "sizes casc.", "sizes indep."}, w);
  for (const auto& [s, t] : {std::pair{0, 20}, std::pair{20, 30}, std::pair{0, 30}}) {
    const auto pair = kitti_pair(root, s, t);
    if (!pair) return;
    Pipeline p(default_config(), 1);
    p.set_input(pair->first.cloud, pair->second.cloud);
    p.run();
    const PyramidGraph& g = p.graph();
    CliqueParams cascaded = p.config().clique, independent = p.config().clique;
    cascaded.solver = CliqueSolver::cascaded;
    independent.solver = CliqueSolver::independent;
    std::vector<CliqueResult> a, b;
    const Timing ta = measure([&] { a = solve_pyramid(g, cascaded); }, g_reps);
    const Timing tb = measure([&] { b = solve_pyramid(g, independent); }, g_reps);
    row({std::to_string(s) + "->" + std::to_string(t), std::to_string(g.vertices),
         fmt(ta.median(), 3) + " ms", fmt(tb.median(), 3) + " ms",
         fmt(tb.median() / ta.median()) + "x", sizes(a), sizes(b)},
        w);
  }
}
}  // namespace

int main(int argc, char** argv) {
  std::string root = PAGOR_DEFAULT_KITTI_DIR, only, write_dir;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--kitti-root")
      root = argv[i + 1];
    else if (a == "--reps")
      g_reps = std::max(1, std::atoi(argv[i + 1]));
    else if (a == "--only")
      only = argv[i + 1];
    else if (a == "--write-problems")
      write_dir = argv[i + 1];
    else {
      std::fprintf(stderr,
                   "usage: pagor_bench [--kitti-root DIR] [--reps N] [--only SECTION] "
                   "[--write-problems DIR]\n");
      return 2;
    }
  }
  std::printf("# pagor_bench (medians of %d runs unless noted)\n", g_reps);
  if (only.empty() || only == "graph") bench_graph();
  if (only.empty() || only == "clique") bench_clique();
  if (only.empty() || only == "gnc") bench_gnc();
  if (only.empty() || only == "verification") bench_verification(root);
  if (only.empty() || only == "e2e") bench_end_to_end(root);
  if (only.empty() || only == "studio") bench_studio(root);
  if (only.empty() || only == "association") bench_association(write_dir);
  if (only.empty() || only == "cascade") bench_cascade_kitti(root);
  return 0;
}
