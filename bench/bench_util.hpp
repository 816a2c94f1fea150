#pragma once
// Timing and memory helpers of the benchmark suite.

#include <chrono>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

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

/// Prints a row of a fixed-width table.
void row(const std::vector<std::string>& cells, const std::vector<int>& widths);
std::string fmt(double v, int decimals = 2);

}  // namespace pagor::bench
