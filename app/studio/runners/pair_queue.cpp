#include "runners/pair_queue.hpp"

#include <cassert>

namespace pagor::studio {

PairQueue::PairQueue(const std::vector<int>& home, int jobs)
    : kept_(static_cast<std::size_t>(jobs)) {
  assert(jobs >= 1);
  for (std::size_t i = 0; i < home.size(); ++i) {
    assert(home[i] < jobs);
    if (home[i] >= 0)
      kept_[static_cast<std::size_t>(home[i])].push_back(i);
    else
      unkept_.push_back(i);
  }
}

std::optional<std::size_t> PairQueue::next(int job) {
  const std::lock_guard<std::mutex> lock(mutex_);
  auto take_front = [](std::deque<std::size_t>& q) {
    const std::size_t i = q.front();
    q.pop_front();
    return i;
  };
  std::deque<std::size_t>& own = kept_[static_cast<std::size_t>(job)];
  if (!own.empty()) return take_front(own);
  if (!unkept_.empty()) return take_front(unkept_);
  // Another runner's kept pair, from the back of the longest queue: its owner would reach it
  // last, and the others of that queue stay with the runner that re-runs them cheaply.
  std::deque<std::size_t>* longest = nullptr;
  for (std::deque<std::size_t>& q : kept_)
    if (!q.empty() && (!longest || q.size() > longest->size())) longest = &q;
  if (!longest) return std::nullopt;
  const std::size_t i = longest->back();
  longest->pop_back();
  return i;
}

}  // namespace pagor::studio
