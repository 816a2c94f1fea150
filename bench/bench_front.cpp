// Section 9: the front end (landmarks and correspondences) per class, on the shared KITTI pairs
// and on semreg-dev, where the class-agnostic `structure` keypoints are added.

#include <time.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>

#include "bench_sections.hpp"
#include "bench_util.hpp"
#include "pagor/config.hpp"
#include "pagor/front/correspondences.hpp"
#include "pagor/front/landmarks.hpp"
#include "pagor/io/clouds.hpp"
#include "pagor/io/kitti.hpp"

namespace pagor::bench {
namespace {

// CPU time of the calling thread [ms]: on a shared machine it shows the work without the waits.
double thread_cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec * 1e3 + ts.tv_nsec / 1e6;
}

// Landmarks of both clouds (with the fallback when the pair needs it) and their matching,
// `reps` times; prints one row of medians and the per-class medians summed over both clouds.
void front_row(const std::string& name, const PointCloud& source, const PointCloud& target,
               const Config& config, int reps) {
  std::vector<double> landmarks, matching, landmarks_cpu, matching_cpu;
  std::map<std::string, std::vector<double>> per_class;
  std::size_t m = 0, count_s = 0, count_t = 0;
  for (int r = 0; r <= reps; ++r) {  // run 0 is the warm-up
    const double c0 = thread_cpu_ms();
    const auto t0 = std::chrono::steady_clock::now();
    LandmarkSet s = extract_landmarks(source, config.label_scheme, config.landmarks);
    LandmarkSet t = extract_landmarks(target, config.label_scheme, config.landmarks);
    if (needs_fallback(source, target, s, t, config.landmarks.fallback)) {
      add_fallback_landmarks(source, config.label_scheme, config.landmarks, s);
      add_fallback_landmarks(target, config.label_scheme, config.landmarks, t);
    }
    const auto t1 = std::chrono::steady_clock::now();
    const double c1 = thread_cpu_ms();
    const CorrespondenceSet c = match_landmarks(s, t, config.correspondences);
    const auto t2 = std::chrono::steady_clock::now();
    const double c2 = thread_cpu_ms();
    if (r == 0) continue;
    landmarks.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    matching.push_back(std::chrono::duration<double, std::milli>(t2 - t1).count());
    landmarks_cpu.push_back(c1 - c0);
    matching_cpu.push_back(c2 - c1);
    std::map<std::string, double> sum;
    for (const auto* set : {&s, &t})
      for (const ClassSummary& k : set->classes) sum[k.name] += k.time_ms;
    for (const auto& [k, v] : sum) per_class[k].push_back(v);
    m = c.items.size();
    count_s = s.landmarks.size();
    count_t = t.landmarks.size();
  }
  std::string classes;
  for (const auto& [k, v] : per_class)
    classes += (classes.empty() ? "" : ", ") + k + " " + fmt(Timing{v}.median(), 1);
  row({name, std::to_string(count_s) + "/" + std::to_string(count_t),
       fmt(Timing{landmarks}.median(), 1) + " ms", fmt(Timing{landmarks_cpu}.median(), 1) + " ms",
       std::to_string(m), fmt(Timing{matching}.median(), 2) + " ms",
       fmt(Timing{matching_cpu}.median(), 2) + " ms", classes},
      {10, 12, 10, 10, 6, 10, 10, 0});
}

}  // namespace

void bench_front(const Options& o) {
  std::printf(
      "\n## 9. Front end, 1 thread: landmarks of both clouds and their correspondences "
      "(medians of wall and thread CPU time; per class: wall [ms], both clouds)\n");
  row({"pair", "landmarks", "landmarks", "CPU", "corr.", "matching", "CPU", "per class [ms]"},
      {10, 12, 10, 10, 6, 10, 10, 0});
  const Config kitti = default_config();
  for (const auto& [s, t] : {std::pair{0, 20}, std::pair{20, 30}, std::pair{0, 30}}) {
    const auto pair = kitti_pair(o.kitti_root, s, t);
    if (!pair) break;
    front_row(std::to_string(s) + "->" + std::to_string(t), pair->first.cloud, pair->second.cloud,
              kitti, o.reps);
  }
  Config semreg = default_config();
  semreg.label_scheme = builtin_label_scheme("semantickitti-learning");
  for (const char* n : {"03", "04", "05", "06", "07", "08", "09", "10", "11", "12"}) {
    const std::filesystem::path dir = std::filesystem::path(o.semreg_root) / n;
    if (!std::filesystem::exists(dir / "source.pcd")) {
      std::printf("(skipped semreg-dev: no %s)\n", (dir / "source.pcd").c_str());
      break;
    }
    const LoadedCloud a = load_cloud((dir / "source.pcd").string());
    const LoadedCloud b = load_cloud((dir / "target.pcd").string());
    front_row(std::string("semreg ") + n, a.cloud, b.cloud, semreg, o.reps);
  }
}

}  // namespace pagor::bench
