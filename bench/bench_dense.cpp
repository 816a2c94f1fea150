// Section 10: the back end on dense, real correspondence problems (gedi-dev: a learned matcher's
// correspondences of ten KITTI pairs) and on generated ones (random points, 10 % inliers, any
// rotation), with the default configuration as a new user gets it: per problem and solver the
// graph, clique and GNC times, the clique sizes and their true members, and the selected pose's
// errors. The solvers run side by side on the same graph in one run.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "bench_sections.hpp"
#include "bench_util.hpp"
#include "pagor/config.hpp"
#include "pagor/eval/association_problem.hpp"
#include "pagor/eval/pair_set.hpp"
#include "pagor/io/correspondence_file.hpp"
#include "pagor/verify/evaluation.hpp"
#include "pagor/verify/level_selection.hpp"

namespace pagor::bench {
namespace {

struct Problem {
  std::string name;
  std::vector<Correspondence> items;
  std::vector<char> inlier;
  Transform T_gt = Transform::Identity();
};

// What one solver gave on one problem; times are medians [ms].
struct SolverRun {
  double graph = 0, clique = 0, gnc = 0;
  std::vector<CliqueResult> cliques;
  std::vector<PoseEstimate> poses;
  int selected = -1;
  std::optional<PoseError> error;
  double total() const { return graph + clique + gnc; }
};

std::vector<PoseEstimate> poses_of(const Problem& pr, const std::vector<CliqueResult>& cliques,
                                   const GncParams& gnc) {
  std::vector<PoseEstimate> out;
  for (const CliqueResult& c : cliques) out.push_back(estimate_pose_gnc(pr.items, c.vertices, gnc));
  return out;
}

// The back end as the pipeline runs it without clouds: graph, clique, GNC per level, selection.
// The graph is built as a pipeline registering pair after pair builds it, in the storage of the
// earlier builds (`builder`, one for the whole set).
SolverRun run_solver(const Problem& pr, const Config& config, int reps,
                     PyramidGraphBuilder& builder) {
  SolverRun r;
  r.graph = measure([&] { builder.build(pr.items, config.graph, 1); }, reps).median();
  const PyramidGraph& g = builder.graph();
  // A solver that takes long (the exact one before issue 22) runs once.
  const Timing first = measure([&] { r.cliques = solve_pyramid(g, config.clique); }, 1, 0);
  r.clique = first.median() > 1000
                 ? first.median()
                 : measure([&] { r.cliques = solve_pyramid(g, config.clique); }, reps).median();
  r.gnc = measure([&] { r.poses = poses_of(pr, r.cliques, config.gnc); }, reps).median();
  // The selection, and with clique.settle_selected the selected level settled (its time is the
  // clique step's, measured once: it changes the cliques it settles).
  const auto select = [&] {
    return r.selected = select_without_clouds(r.poses, pr.items, config.gnc.noise_bound).selected;
  };
  const auto refit = [&](int level) {
    const auto l = static_cast<std::size_t>(level);
    r.poses[l] = estimate_pose_gnc(pr.items, r.cliques[l].vertices, config.gnc);
  };
  const auto same_answer = [&](int level) {
    std::vector<char> settled;
    for (const CliqueResult& c : r.cliques) settled.push_back(c.settled);
    return same_answer_as(r.poses, level, settled, config.acceptance.distinct()) >= 0;
  };
  r.clique +=
      settle_selection(g, r.cliques, config.clique, kNoDeadline, select, refit, same_answer);
  if (r.selected >= 0)
    r.error = pose_error(r.poses[static_cast<std::size_t>(r.selected)].T_target_source, pr.T_gt,
                         config.evaluation);
  return r;
}

// Per level "size/true" against the flags.
std::string sizes_true(const std::vector<CliqueResult>& cliques, const std::vector<char>& inlier) {
  std::string out;
  for (const CliqueResult& c : cliques) {
    std::size_t hit = 0;
    for (int v : c.vertices) hit += inlier[static_cast<std::size_t>(v)] != 0;
    out += (out.empty() ? "" : ",") + std::to_string(c.vertices.size()) + "/" +
           std::to_string(hit) + (c.proven ? "" : "?") +
           (c.start == CliqueStart::fallback ? "c" : "") +
           (c.budget == CliqueBudget::none    ? ""
            : c.budget == CliqueBudget::nodes ? "n"
            : c.budget == CliqueBudget::probe ? "p"
                                              : "t");
  }
  return out;
}

std::vector<Problem> gedi_problems(const std::string& dir) {
  std::vector<Problem> out;
  for (int n = 3; n <= 12; ++n) {
    char name[8];
    std::snprintf(name, sizeof(name), "%02d", n);
    const std::string base = dir + "/" + name;
    if (!std::filesystem::exists(base + ".txt")) continue;
    const CorrespondenceFile f = read_correspondence_file(base + ".txt");
    out.push_back(
        {std::string("gedi ") + name, f.items, f.inlier, read_transform_file(base + ".T.txt")});
  }
  return out;
}

std::vector<Problem> generated_problems() {
  std::vector<Problem> out;
  for (int m : {1000, 2000, 5000})
    for (std::uint64_t seed : {1, 2, 3}) {
      AssociationParams a;
      a.m = m;
      a.seed = seed;
      const AssociationProblem p = association_problem(a);
      out.push_back({"gen m=" + std::to_string(m) + " s" + std::to_string(seed), p.correspondences,
                     p.inlier, p.T_target_source});
    }
  return out;
}

// The most any warm start can save on one problem: every level solved on its own (the solve_clipper
// of a level), from the cold start and from that level's own maximum clique (`maxima`, proven; no
// solver has it before the search) handed in as the warm start. Cold time over handed-in time.
double handed_in_ratio(const PyramidGraph& g, const std::vector<CliqueResult>& maxima, int reps) {
  const CliqueParams p = default_config().clique;
  const std::vector<double> cold = random_start(g.vertices, p.seed);
  std::vector<std::vector<double>> warm;
  for (const CliqueResult& c : maxima) {
    warm.emplace_back(static_cast<std::size_t>(g.vertices), 0.0);
    for (int v : c.vertices)
      warm.back()[static_cast<std::size_t>(v)] = 1.0 / std::sqrt(double(c.vertices.size()));
  }
  const int levels = static_cast<int>(maxima.size());
  const double t_cold = measure(
                            [&] {
                              for (int l = 0; l < levels; ++l)
                                solve_clipper(g, l, cold, p, {}, 0.0);
                            },
                            reps)
                            .median();
  const double t_warm = measure(
                            [&] {
                              for (int l = 0; l < levels; ++l)
                                solve_clipper(g, l, warm[static_cast<std::size_t>(l)], p,
                                              maxima[static_cast<std::size_t>(l)].vertices, 0.0);
                            },
                            reps)
                            .median();
  return t_cold / t_warm;
}

// How far the levels' maximum cliques nest: the lowest share of a level's clique that the next
// level's holds.
double nesting(const std::vector<CliqueResult>& maxima) {
  double lowest = 1.0;
  for (std::size_t l = 0; l + 1 < maxima.size(); ++l) {
    const std::vector<int>& a = maxima[l].vertices;
    const std::vector<int>& b = maxima[l + 1].vertices;
    if (a.empty()) continue;
    std::size_t shared = 0;
    for (int v : a) shared += std::binary_search(b.begin(), b.end(), v);
    lowest = std::min(lowest, double(shared) / double(a.size()));
  }
  return lowest;
}

double median_of(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

void run_set(const std::vector<Problem>& problems, const Options& o) {
  const std::vector<int> w = {15, 6, 12, 8, 9, 7, 9, 24, 16};
  row({"problem", "m", "solver", "graph", "clique", "gnc", "total", "clique/true per level",
       "selected: err"},
      w);
  const std::pair<const char*, CliqueSolver> solvers[] = {
      {"cascaded", CliqueSolver::cascaded},
      {"independent", CliqueSolver::independent},
      {"exact", CliqueSolver::exact}};
  std::vector<std::vector<double>> totals(3), cliques(3), ratios(1);
  std::vector<double> handed_in, nested;
  std::vector<int> successes(3, 0);
  PyramidGraphBuilder builder;
  for (const Problem& pr : problems) {
    std::vector<SolverRun> runs;
    for (std::size_t s = 0; s < 3; ++s) {
      Config config = default_config();
      config.clique.solver = solvers[s].second;
      const SolverRun r = run_solver(pr, config, o.reps, builder);
      const bool ok = r.error && r.error->success;
      successes[s] += ok;
      totals[s].push_back(r.total());
      cliques[s].push_back(r.clique);
      const std::string sel = r.error ? std::to_string(r.selected) + ": " +
                                            fmt(r.error->translation, 2) + " m " +
                                            fmt(r.error->rotation_deg, 1) + (ok ? " ok" : " WRONG")
                                      : "none";
      row({pr.name, std::to_string(pr.items.size()), solvers[s].first, fmt(r.graph, 2),
           fmt(r.clique, 2), fmt(r.gnc, 2), fmt(r.total(), 2), sizes_true(r.cliques, pr.inlier),
           sel},
          w);
      runs.push_back(r);
    }
    ratios[0].push_back(runs[1].clique / runs[0].clique);
    const std::vector<CliqueResult>& maxima = runs[2].cliques;  // the exact solver's
    if (std::all_of(maxima.begin(), maxima.end(), [](const CliqueResult& c) { return c.proven; })) {
      handed_in.push_back(handed_in_ratio(builder.graph(), maxima, o.reps));
      nested.push_back(nesting(maxima));
      std::printf(
          "%17s cascaded vs independent %.2fx; with the maxima handed in %.2fx; nesting %.0f %%\n",
          "", ratios[0].back(), handed_in.back(), 100 * nested.back());
    }
  }
  for (std::size_t s = 0; s < 3; ++s)
    std::printf(
        "  %-11s success %d/%zu; graph+clique+gnc median %.2f ms, max %.2f ms; clique median "
        "%.2f ms, max %.2f ms\n",
        solvers[s].first, successes[s], problems.size(), median_of(totals[s]),
        *std::max_element(totals[s].begin(), totals[s].end()), median_of(cliques[s]),
        *std::max_element(cliques[s].begin(), cliques[s].end()));
  std::printf("  cascaded vs independent clique step: median ratio %.2fx, lowest %.2fx\n",
              median_of(ratios[0]), *std::min_element(ratios[0].begin(), ratios[0].end()));
  if (!handed_in.empty()) {
    std::printf(
        "  each level handed its own maximum clique as the warm start (the most any start can "
        "save), levels solved one by one: cold vs handed-in median ratio %.2fx, highest %.2fx "
        "(%zu problems)\n",
        median_of(handed_in), *std::max_element(handed_in.begin(), handed_in.end()),
        handed_in.size());
    std::printf(
        "  nesting: share of a level's maximum clique in the next level's, lowest per problem: "
        "median %.0f %%, lowest %.0f %%\n",
        100 * median_of(nested), 100 * *std::min_element(nested.begin(), nested.end()));
  }
}

}  // namespace

void bench_dense(const Options& o) {
  std::printf(
      "\n## 10. Dense problems, default configuration, back end only (graph + clique + GNC per "
      "level, selection without clouds), 1 thread; sizes as clique/true members, ? = not proven "
      "maximum, c = the warm start lost to the cold one, n/t = a node/time budget stopped the "
      "search, p = not settled (a search of clique.probe_nodes, no fallback)\n");
  const std::vector<Problem> gedi = gedi_problems(o.gedi_root);
  if (gedi.empty())
    std::printf("(no gedi-dev problems under %s)\n", o.gedi_root.c_str());
  else
    run_set(gedi, o);
  std::printf(
      "\n   generated: random points in a 10 m cube, 10 %% inliers, noise 0.02 m, any "
      "rotation\n");
  run_set(generated_problems(), o);
}

}  // namespace pagor::bench
