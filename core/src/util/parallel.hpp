#pragma once
/// \file parallel.hpp
/// Splits an index range over threads. Internal to the core.

#include <algorithm>
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace pagor {

/// Calls f(begin, end) on consecutive parts of [0, n) covering it once, on up to `threads`
/// threads (the calling thread takes the first part), so that each part holds at least
/// `min_part` indices; one thread runs all of it inline. The first exception a part throws is
/// rethrown here, after every part has finished.
template <class F>
void parallel_ranges(int threads, std::size_t n, std::size_t min_part, const F& f) {
  const std::size_t most = min_part > 0 ? std::max<std::size_t>(1, n / min_part) : n;
  const auto parts = static_cast<std::size_t>(std::max<std::size_t>(
      1, std::min<std::size_t>(static_cast<std::size_t>(std::max(threads, 1)), most)));
  if (parts == 1) {
    f(std::size_t{0}, n);
    return;
  }
  std::vector<std::exception_ptr> failures(parts);
  const auto run = [&](std::size_t k) {
    try {
      f(n * k / parts, n * (k + 1) / parts);
    } catch (...) {
      failures[k] = std::current_exception();
    }
  };
  std::vector<std::thread> pool;
  pool.reserve(parts - 1);
  for (std::size_t k = 1; k < parts; ++k) pool.emplace_back(run, k);
  run(0);
  for (std::thread& t : pool) t.join();
  for (const std::exception_ptr& e : failures)
    if (e) std::rethrow_exception(e);
}

/// Calls first() and second(), at once when threads > 1 (second() on another thread); when both
/// throw, first()'s exception is the one rethrown, as when they run one after the other.
template <class First, class Second>
void parallel_pair(int threads, const First& first, const Second& second) {
  parallel_ranges(threads, 2, 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) {
      if (k == 0)
        first();
      else
        second();
    }
  });
}

}  // namespace pagor
