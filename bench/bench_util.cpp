#include "bench_util.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>

#include "pagor/io/kitti.hpp"
#include "util/random_draw.hpp"

namespace pagor::bench {

double Timing::median() const {
  std::vector<double> v = runs;
  std::sort(v.begin(), v.end());
  return v.empty()
             ? 0.0
             : (v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]));
}

double Timing::min() const {
  return runs.empty() ? 0.0 : *std::min_element(runs.begin(), runs.end());
}

Timing measure(const std::function<void()>& f, int reps, int warmup) {
  for (int i = 0; i < warmup; ++i) f();
  Timing t;
  for (int i = 0; i < reps; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    t.runs.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  return t;
}

namespace {
long status_kb(const char* key) {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind(key, 0) == 0) return std::atol(line.c_str() + std::string(key).size());
  return -1;
}
}  // namespace

double peak_memory_mb(const std::function<void()>& f) {
  int pipefd[2];
  if (pipe(pipefd) != 0) return -1;
  const pid_t pid = fork();
  if (pid == 0) {
    close(pipefd[0]);
    double mb = -1;
    std::ofstream("/proc/self/clear_refs") << "5";  // reset the peak to the current RSS
    const long before = status_kb("VmRSS:");
    f();
    const long peak = status_kb("VmHWM:");
    if (before >= 0 && peak >= 0) mb = (peak - before) / 1024.0;
    if (write(pipefd[1], &mb, sizeof(mb)) != sizeof(mb)) _exit(1);
    _exit(0);
  }
  close(pipefd[1]);
  double mb = -1;
  if (read(pipefd[0], &mb, sizeof(mb)) != sizeof(mb)) mb = -1;
  close(pipefd[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  return mb;
}

std::vector<Correspondence> all_to_all_scene(int m, double noise, std::uint64_t seed, int classes) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> coord(-50.0, 50.0), height(0.0, 3.0);
  std::normal_distribution<double> jitter(0.0, noise);
  Transform T = Transform::Identity();
  T.block<3, 3>(0, 0) = Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  T.block<3, 1>(0, 3) = Eigen::Vector3d(12.0, -3.0, 0.2);
  // n landmarks per class per scan give n^2 correspondences per class.
  const int n =
      std::max(2, static_cast<int>(std::lround(std::sqrt(static_cast<double>(m) / classes))));
  std::vector<Correspondence> out;
  int source_id = 0, target_id = 0;
  for (int c = 0; c < classes; ++c) {
    std::vector<Eigen::Vector3d> src, tgt;
    for (int i = 0; i < n; ++i) src.push_back(draw3(coord, coord, height, rng));
    for (int i = 0; i < n; ++i) {
      if (i < n / 2) {  // seen by both
        const Eigen::Vector3d q =
            T.block<3, 3>(0, 0) * src[static_cast<std::size_t>(i)] + T.block<3, 1>(0, 3);
        tgt.push_back(q + draw3(jitter, rng));
      } else {
        tgt.push_back(draw3(coord, coord, height, rng));
      }
    }
    std::shuffle(tgt.begin(), tgt.end(), rng);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        Correspondence x;
        x.class_index = c;
        x.source = source_id + i;
        x.target = target_id + j;
        x.p = src[static_cast<std::size_t>(i)];
        x.q = tgt[static_cast<std::size_t>(j)];
        out.push_back(x);
      }
    source_id += n;
    target_id += n;
  }
  return out;
}

void row(const std::vector<std::string>& cells, const std::vector<int>& widths) {
  std::string line;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    std::string c = cells[i];
    const int w = i < widths.size() ? widths[i] : 12;
    if (static_cast<int>(c.size()) < w)
      c = (i == 0 ? c + std::string(w - c.size(), ' ') : std::string(w - c.size(), ' ') + c);
    line += c + "  ";
  }
  std::printf("%s\n", line.c_str());
}

std::string fmt(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*f", decimals, v);
  return buf;
}

bool SolverComparison::same_sizes() const {
  bool same = a.size() == b.size();
  for (std::size_t l = 0; same && l < a.size(); ++l)
    same = a[l].vertices.size() == b[l].vertices.size();
  return same;
}

bool SolverComparison::same_sets() const {
  bool same = a.size() == b.size();
  for (std::size_t l = 0; same && l < a.size(); ++l) same = a[l].vertices == b[l].vertices;
  return same;
}

SolverComparison compare_solvers(const PyramidGraph& g, const CliqueParams& a,
                                 const CliqueParams& b, int reps) {
  SolverComparison out;
  out.time_a = measure([&] { out.a = solve_pyramid(g, a); }, reps);
  out.time_b = measure([&] { out.b = solve_pyramid(g, b); }, reps);
  return out;
}

SolverComparison cascaded_vs_independent(const PyramidGraph& g, int reps, CliqueParams base) {
  // Every level solved in full (no selection here to settle one): the cascade as Alg. 1 runs it.
  base.settle_selected = false;
  CliqueParams independent = base;
  base.solver = CliqueSolver::cascaded;
  independent.solver = CliqueSolver::independent;
  return compare_solvers(g, base, independent, reps);
}

std::string sizes(const std::vector<CliqueResult>& cliques) {
  std::string out;
  for (const auto& c : cliques) out += (out.empty() ? "" : ",") + std::to_string(c.vertices.size());
  return out;
}

int gradient_steps(const std::vector<CliqueResult>& cliques) {
  int n = 0;
  for (const auto& c : cliques) n += c.gradient_steps;
  return n;
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

}  // namespace pagor::bench
