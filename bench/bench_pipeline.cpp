// Sections 1 and 3-6: graph construction, GNC, verification, end to end per KITTI pair and the
// studio's re-run latency.

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>

#include "bench_sections.hpp"
#include "bench_util.hpp"
#include "pagor/graph/pyramid_graph.hpp"
#include "pagor/io/kitti.hpp"
#include "pagor/pipeline.hpp"
#include "pagor/pose/gnc.hpp"
#include "pagor/verify/verification.hpp"
#include "util/random_draw.hpp"

namespace pagor::bench {

void bench_graph(const Options& o) {
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
    const Timing one = measure([&] { g = build_pyramid_graph(c, gp, 1); }, m >= 2000 ? 5 : o.reps);
    const Timing two = measure([&] { g = build_pyramid_graph(c, gp, 2); }, m >= 2000 ? 5 : o.reps);
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

void bench_gnc(const Options& o) {
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
      p.push_back(draw3(coord, rng).cwiseQuotient(Eigen::Vector3d(1, 1, 10)));
      q.push_back(i < n * 4 / 5 ? Eigen::Vector3d(T.block<3, 3>(0, 0) * p.back() +
                                                  T.block<3, 1>(0, 3) + draw3(noise, rng))
                                : draw_on_plane(coord, rng, 0.0));
    }
    GncParams se3, se2;
    se2.model = PoseModel::se2;
    const Timing a = measure([&] { estimate_pose_gnc(p, q, se3); }, o.reps * 4);
    const Timing b = measure([&] { estimate_pose_gnc(p, q, se2); }, o.reps * 4);
    row({std::to_string(n), fmt(a.median(), 4) + " ms", fmt(b.median(), 4) + " ms"}, w);
  }
}

void bench_verification(const Options& o) {
  std::printf("\n## 4. Verification of 4 candidates on the full KITTI scans 20 -> 30\n");
  const auto pair = kitti_pair(o.kitti_root, 20, 30);
  if (!pair) return;
  const KittiSequence seq(o.kitti_root, "00");
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
    const Timing one = measure([&] { verify_candidates(*v, candidates, vp, 1); }, o.reps);
    const Timing two = measure([&] { verify_candidates(*v, candidates, vp, 2); }, o.reps);
    row({fmt(voxel), std::to_string(v->source_points().size()), fmt(prep.median(), 2) + " ms",
         fmt(one.median(), 2) + " ms", fmt(two.median(), 2) + " ms",
         fmt(one.median() / two.median()) + "x"},
        w);
  }
}

void bench_end_to_end(const Options& o) {
  std::printf(
      "\n## 5. End to end per KITTI pair (clouds in memory -> selected pose), by stage [ms]\n");
  const Stage stages[] = {
      Stage::landmarks, Stage::correspondences,   Stage::graph,        Stage::clique,
      Stage::gnc,       Stage::verification_prep, Stage::verification, Stage::refinement,
      Stage::acceptance};
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
    const auto pair = kitti_pair(o.kitti_root, s, t);
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
          std::max(3, o.reps / 2));
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

void bench_studio(const Options& o) {
  std::printf(
      "\n## 6. Studio re-run latency on KITTI 20 -> 30 (pipeline with caching, 1 thread)\n");
  const auto pair = kitti_pair(o.kitti_root, 20, 30);
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
        o.reps, 1);
    row({name, fmt(t.median(), 2) + " ms"}, w);
  };
  rerun("mu", [&](Config& c) { c.verification.mu = (++k % 2) ? 1.2 : 1.0; });
  rerun("one threshold", [&](Config& c) { c.graph.thresholds[1] = (++k % 2) ? 0.05 : 0.04; });
  rerun("clustering (car tolerance)",
        [&](Config& c) { c.landmarks.classes[0].cluster_tolerance = (++k % 2) ? 0.55 : 0.5; });
}

}  // namespace pagor::bench
