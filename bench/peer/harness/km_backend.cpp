// km_backend: times KISS-Matcher's back end on a correspondence file.
//
// The back end is exactly what KISS-Matcher (MIT-SPARK/KISS-Matcher @ 09d5117) runs after its
// FPFH matching, i.e. the tail of ROBINMatching::match() + KISSMatcher::estimate():
//   1. ROBINMatching::applyOutlierPruning(corres, ...)   [ROBINMatching.cpp]
//        copy float keypoints into 3xN double matrices,
//        g = robin::Make3dRegInvGraph(src, tgt, robin_noise_bound)      (ADJ_LIST storage, default)
//        idx = robin::FindInlierStructure(g, MAX_CORE)                    (robin_mode_ = "max_core")
//   2. KISSMatcher::solve(src_pruned, tgt_pruned)          [KISSMatcher.cpp]
//        resetSolver(); RobustRegistrationSolver(GNC_TLS, noise_bound = solver_noise_bound).solve()
// with KISSMatcherConfig(resolution) defaults: robin_noise_bound = 1.0 * resolution,
// solver_noise_bound = 0.75 * resolution (GNC-TLS: gnc_factor 1.4, max_iter 100, cost_thr 1e-6,
// cbar2 1; the solver doubles the noise bound on its chain-graph TIMs).
// Step 1 is replicated line by line (calling the same ROBIN functions) instead of calling
// ROBINMatching's public applyOutlierPruning(vector, vector) only to time graph and max-core
// separately; KISSMatcher::pruneAndSolve() is not used because at this commit it copies
// src_matched[num_pruned_corr] instead of src_matched[pruned_indices[i]] (a bug).
// Like KISS-Matcher, the ROBIN graph is not freed inside the timed region (KISS-Matcher leaks it;
// we delete it after the clock stops).
//
// usage: km_backend --corr FILE --gt FILE [--resolution 0.3] [--mode max_core|max_clique]
//                   [--reps 4] [--name NAME]
// prints one line of key=value pairs.
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <kiss_matcher/KISSMatcher.hpp>
#include <robin/robin.hpp>

namespace {
struct Problem {
  std::vector<Eigen::Vector3f> src, tgt;
  std::vector<int> flag;  // -1 = absent
};

Problem readCorr(const std::string& path) {
  std::ifstream in(path);
  if (!in) { std::cerr << "cannot open " << path << "\n"; std::exit(2); }
  Problem p;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ss(line);
    double v[8];
    int k = 0;
    while (k < 8 && ss >> v[k]) ++k;
    if (k < 6) continue;
    p.src.emplace_back(float(v[0]), float(v[1]), float(v[2]));
    p.tgt.emplace_back(float(v[3]), float(v[4]), float(v[5]));
    p.flag.push_back(k >= 8 ? int(v[7]) : -1);  // weight (v[6]) is ignored: KISS-Matcher has none
  }
  return p;
}

Eigen::Matrix4d readGt(const std::string& path) {
  std::ifstream in(path);
  if (!in) { std::cerr << "cannot open " << path << "\n"; std::exit(2); }
  Eigen::Matrix4d T;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) in >> T(r, c);
  return T;
}

struct Result {
  double t_graph_ms, t_prune_ms, t_solve_ms, t_total_ms;
  size_t edges, pruned, pruned_true, rot_inl, trans_inl;
  kiss_matcher::RegistrationSolution sol;
};

Result runOnce(const Problem& p, const kiss_matcher::KISSMatcherConfig& cfg, bool max_clique) {
  using clk = std::chrono::steady_clock;
  kiss_matcher::KISSMatcher matcher(cfg);  // constructs FasterPFH/ROBINMatching/solver: untimed
  Result r{};
  const size_t n = p.src.size();

  const auto t0 = clk::now();
  // --- ROBINMatching::applyOutlierPruning ---
  Eigen::Matrix<double, 3, Eigen::Dynamic> src_robin(3, n);
  Eigen::Matrix<double, 3, Eigen::Dynamic> tgt_robin(3, n);
#pragma omp parallel for
  for (size_t i = 0; i < n; ++i) {
    src_robin.col(i) = p.src[i].cast<double>();
    tgt_robin.col(i) = p.tgt[i].cast<double>();
  }
  auto* g = robin::Make3dRegInvGraph(src_robin, tgt_robin, cfg.robin_noise_bound_);
  const auto t1 = clk::now();
  const std::vector<size_t> idx = robin::FindInlierStructure(
      g, max_clique ? robin::InlierGraphStructure::MAX_CLIQUE : robin::InlierGraphStructure::MAX_CORE);
  const auto t2 = clk::now();
  // --- KISSMatcher::estimate -> solve on the pruned correspondences ---
  const size_t m = idx.size();
  Eigen::Matrix<double, 3, Eigen::Dynamic> src_eigen(3, m), tgt_eigen(3, m);
  for (size_t i = 0; i < m; ++i) {
    src_eigen.col(i) = p.src[idx[i]].cast<double>();
    tgt_eigen.col(i) = p.tgt[idx[i]].cast<double>();
  }
  r.sol = matcher.solve(src_eigen, tgt_eigen);
  const auto t3 = clk::now();

  size_t deg_sum = 0;
  for (size_t v = 0; v < g->VertexCount(); ++v) deg_sum += g->GetVertexDegree(v);
  r.edges = deg_sum / 2;
  delete g;
  auto ms = [](clk::duration d) { return std::chrono::duration<double, std::milli>(d).count(); };
  r.t_graph_ms = ms(t1 - t0);
  r.t_prune_ms = ms(t2 - t1);
  r.t_solve_ms = ms(t3 - t2);
  r.t_total_ms = ms(t3 - t0);
  r.pruned = m;
  r.pruned_true = 0;
  for (size_t i : idx) r.pruned_true += (p.flag[i] == 1);
  if (m >= 2) {
    r.rot_inl = matcher.getNumRotationInliers();
    r.trans_inl = matcher.getNumFinalInliers();
  }
  return r;
}
}  // namespace

int main(int argc, char** argv) {
  std::string corr, gt, name, mode = "max_core";
  float resolution = 0.3f;
  int reps = 4;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    auto next = [&]() -> std::string {
      if (i + 1 >= argc) { std::cerr << a << " needs a value\n"; std::exit(2); }
      return argv[++i];
    };
    if (a == "--corr") corr = next();
    else if (a == "--gt") gt = next();
    else if (a == "--resolution") resolution = std::stof(next());
    else if (a == "--mode") mode = next();
    else if (a == "--reps") reps = std::stoi(next());
    else if (a == "--name") name = next();
    else { std::cerr << "unknown option " << a << "\n"; return 2; }
  }
  if (corr.empty() || gt.empty() || (mode != "max_core" && mode != "max_clique") || reps < 1) {
    std::cerr << "usage: km_backend --corr FILE --gt FILE [--resolution 0.3] "
                 "[--mode max_core|max_clique] [--reps 4] [--name NAME]\n";
    return 2;
  }
  const Problem p = readCorr(corr);
  const Eigen::Matrix4d T = readGt(gt);
  size_t n_true = 0;
  for (int f : p.flag) n_true += (f == 1);

  // KISS-Matcher's own default configuration for a given resolution (voxel size).
  const kiss_matcher::KISSMatcherConfig cfg(resolution);

  std::vector<Result> runs;
  for (int k = 0; k < reps; ++k) runs.push_back(runOnce(p, cfg, mode == "max_clique"));
  // runs[0] = first (cold) run in this process; "warm" = best of the later runs.
  double warm = runs.size() > 1 ? 1e300 : runs[0].t_total_ms;
  size_t best = 0;
  for (size_t k = 1; k < runs.size(); ++k)
    if (runs[k].t_total_ms < warm) { warm = runs[k].t_total_ms; best = k; }
  const Result& b = runs[best];
  // Results are deterministic (no randomness in max-core / GNC); report the first run's pose.
  const Result& r0 = runs[0];
  const Eigen::Matrix3d Rgt = T.topLeftCorner<3, 3>();
  const Eigen::Vector3d tgt = T.topRightCorner<3, 1>();
  const double terr = (r0.sol.translation - tgt).norm();
  const double c = std::clamp(((Rgt.transpose() * r0.sol.rotation).trace() - 1.0) / 2.0, -1.0, 1.0);
  const double rerr = std::acos(c) * 180.0 / M_PI;
  const bool ok = terr < 2.0 && rerr < 5.0;
  bool same = true;
  for (const auto& r : runs)
    same = same && (r.sol.translation - r0.sol.translation).norm() < 1e-9 && r.pruned == r0.pruned;

  std::printf(
      "name=%s mode=%s resolution=%.3f robin_noise_bound=%.4f solver_noise_bound=%.4f omp_threads=%d omp_thread_limit=%d "
      "n=%zu n_true=%zu edges=%zu pruned=%zu pruned_true=%zu rot_inliers=%zu trans_inliers=%zu "
      "valid=%d t_err=%.4f r_err=%.4f ok=%d "
      "cold_graph_ms=%.4f cold_prune_ms=%.4f cold_solve_ms=%.4f cold_total_ms=%.4f "
      "warm_graph_ms=%.4f warm_prune_ms=%.4f warm_solve_ms=%.4f warm_total_ms=%.4f reps=%d "
      "deterministic=%d\n",
      name.c_str(), mode.c_str(), resolution, cfg.robin_noise_bound_, cfg.solver_noise_bound_,
      omp_get_max_threads(), omp_get_thread_limit(), p.src.size(), n_true, r0.edges, r0.pruned, r0.pruned_true, r0.rot_inl,
      r0.trans_inl, int(r0.sol.valid), terr, rerr, int(ok), r0.t_graph_ms, r0.t_prune_ms,
      r0.t_solve_ms, r0.t_total_ms, b.t_graph_ms, b.t_prune_ms, b.t_solve_ms, b.t_total_ms, reps,
      int(same));
  return 0;
}
