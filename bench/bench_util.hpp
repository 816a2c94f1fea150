#pragma once
// Timing and memory helpers of the benchmark suite.

#include <chrono>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "pagor/graph/densest_clique.hpp"
#include "pagor/io/clouds.hpp"
#include "pagor/types.hpp"

namespace pagor::bench {

/// Wall times of repeated runs [ms].
struct Timing {
  std::vector<double> runs;
  double median() const;
  double min() const;
};

/// Runs `f` `warmup` times unmeasured, then `reps` times measured.
Timing measure(const std::function<void()>& f, int reps, int warmup = 1);

/// Peak resident memory growth [MB] while running `f`, measured in a forked child process
/// (VmHWM after resetting it through /proc/self/clear_refs). Negative when unsupported.
double peak_memory_mb(const std::function<void()>& f);

/// Correspondences as the method makes them: `classes` classes of landmarks, all-to-all within a
/// class, about `m` in total. Half of the landmarks are seen by both scans (moved by a known
/// transform, with `noise` [m]); the rest are seen by one scan only. Fixed seed.
std::vector<Correspondence> all_to_all_scene(int m, double noise, std::uint64_t seed,
                                             int classes = 3);

/// Two clique solvers on the same graph, timed in the same run (a, then b, `reps` times each).
struct SolverComparison {
  std::vector<CliqueResult> a, b;  ///< results of the last run of each
  Timing time_a, time_b;
  double ratio() const { return time_b.median() / time_a.median(); }  ///< b's time over a's
  bool same_sizes() const;  ///< equal clique sizes at every level
  bool same_sets() const;   ///< equal cliques at every level
};
SolverComparison compare_solvers(const PyramidGraph& g, const CliqueParams& a,
                                 const CliqueParams& b, int reps);
/// `base` cascaded (a) against `base` independent (b), every level solved in full (settle_selected
/// off: there is no selection to settle one).
SolverComparison cascaded_vs_independent(const PyramidGraph& g, int reps, CliqueParams base = {});

/// Clique sizes per level, "17,24,29,34".
std::string sizes(const std::vector<CliqueResult>& cliques);
/// Gradient steps summed over the levels.
int gradient_steps(const std::vector<CliqueResult>& cliques);

/// Frames `s` and `t` of KITTI sequence 00 under `root`; prints why and gives nothing when they
/// cannot be read.
std::optional<std::pair<LoadedCloud, LoadedCloud>> kitti_pair(const std::string& root, int s,
                                                              int t);

/// Prints a row of a fixed-width table.
void row(const std::vector<std::string>& cells, const std::vector<int>& widths);
std::string fmt(double v, int decimals = 2);

}  // namespace pagor::bench
