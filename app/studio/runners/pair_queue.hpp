#pragma once
/// \file pair_queue.hpp
/// Which pair each job of the benchmark view runs next when a pass runs on several runners. A
/// pair whose pipeline a runner keeps goes to that runner: there it re-runs only the stages the
/// change invalidated, elsewhere it would be loaded from its files again. The pairs no runner
/// keeps go to whichever job is free first; a job with nothing of its own left takes the last of
/// another's kept pairs, so that no job idles while pairs wait.

#include <cstddef>
#include <deque>
#include <mutex>
#include <optional>
#include <vector>

namespace pagor::studio {

class PairQueue {
 public:
  /// `home[i]`: the runner (0 .. jobs - 1) keeping pair i's pipeline, or -1 when none does. Each
  /// runner's kept pairs come first, in set order, then the others, in set order.
  PairQueue(const std::vector<int>& home, int jobs);

  /// The next pair for runner `job`; nullopt when every pair has been taken. Thread-safe.
  std::optional<std::size_t> next(int job);

 private:
  std::mutex mutex_;
  std::vector<std::deque<std::size_t>> kept_;  // per runner: the pairs it keeps, not yet taken
  std::deque<std::size_t> unkept_;             // pairs no runner keeps, not yet taken
};

}  // namespace pagor::studio
