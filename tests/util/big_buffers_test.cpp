#include <catch2/catch.hpp>
#include <cstdint>
#include <thread>
#include <vector>

#include "util/big_buffers.hpp"

using namespace pagor::detail;

TEST_CASE(
    "block size classes hold the request, waste at most an eighth below 1 MiB, fill 2 MiB pages") {
  for (std::size_t bytes = BlockCache::kMin; bytes < (std::size_t(1) << 28);
       bytes = bytes * 9 / 7) {
    const std::size_t c = BlockCache::size_class(bytes);
    CAPTURE(bytes, c);
    CHECK(c >= bytes);
    CHECK(BlockCache::size_class(c) == c);  // a class is its own class
    if (c < BlockCache::kHuge / 2)
      CHECK(c - bytes <= bytes / 8);
    else
      CHECK(c % BlockCache::kHuge == 0);
  }
}

TEST_CASE("a thread's freed large arrays come back to its next allocation of their class") {
  using Vec = std::vector<std::uint64_t, BlockAllocator<std::uint64_t>>;
  std::thread([] {  // a thread of its own: an empty cache to start from, freed when it ends
    const std::uint64_t* first = nullptr;
    {
      Vec a(100000, 1);  // 800 kB
      first = a.data();
      CHECK(reinterpret_cast<std::uintptr_t>(first) % 64 == 0);
    }
    Vec b(100000, 0);  // the same class: the same block, zeroed as asked
    CHECK(b.data() == first);
    CHECK(b.front() == 0);
    CHECK(b.back() == 0);
    Vec c(100000, 2);  // b still holds it: a new one
    CHECK(c.data() != first);
    Vec big(1 << 20, 3);  // 8 MiB: 2 MiB-aligned
    CHECK(reinterpret_cast<std::uintptr_t>(big.data()) % BlockCache::kHuge == 0);
    {
      // More than the cache keeps (64 MiB): the oldest are freed, the newest 8 of 8 MiB kept.
      std::vector<Vec> many;
      for (int k = 0; k < 10; ++k) many.emplace_back(1 << 20, 0);
      const std::uint64_t* newest = many.back().data();
      many.clear();  // destroyed first to last
      CHECK(BlockCache::of_this_thread().kept_bytes() == std::size_t(64) << 20);
      Vec again(1 << 20, 5);  // the most recently kept block of its class
      CHECK(again.data() == newest);
      CHECK(BlockCache::of_this_thread().kept_bytes() == std::size_t(56) << 20);
    }
    Vec small(10, 4);  // below 64 KiB: the plain allocator
    CHECK(small[9] == 4);
  })
      .join();
}
