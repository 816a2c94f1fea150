#pragma once
// Internal: storage for the dense graphs' large arrays (tens of MiB on thousands of
// correspondences), where first touching the memory costs more than the work on it.

#include <cstdint>
#include <cstdlib>
#include <memory>
#include <new>
#include <utility>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace pagor::detail {

/// Asks the kernel for 2 MiB pages under the reserved, untouched storage of `v` (Linux, where
/// transparent huge pages are "madvise"): faulting tens of MiB in 4 KiB at a time took a third of
/// the graph's time on m = 5000 (a page fault is dear in a virtual machine). A hint only: the
/// storage and its contents are the same either way.
template <class T, class A>
void hint_huge_pages(const std::vector<T, A>& v) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t kHuge = std::uintptr_t(1) << 21;
  const auto begin = reinterpret_cast<std::uintptr_t>(v.data());
  const std::uintptr_t end = begin + v.capacity() * sizeof(T);
  const std::uintptr_t first = (begin + kHuge - 1) & ~(kHuge - 1), last = end & ~(kHuge - 1);
  if (last > first) madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
#else
  (void)v;
#endif
}

/// Gives `v` room for n elements: when it must grow, in fresh storage (the old block freed first,
/// its contents not copied) hinted for huge pages. Storage already large enough is kept.
template <class V>
void reserve_fresh(V& v, std::size_t n) {
  if (v.capacity() >= n) return;
  V().swap(v);
  v.reserve(n);
  hint_huge_pages(v);
}

/// Blocks of 64 KiB and more that a thread freed, kept for its next call: the clique step builds
/// the same large arrays (a dense level's bit rows) on every call, and the system allocator could
/// hand them back in between, so that each call faulted them in again, 4 KiB at a time (on
/// gedi-dev 03 a tenth of the clique step; on the first m = 5000 call of a process, a third). At
/// most 64 MiB and 32 blocks a thread; freed when the thread ends.
class BlockCache {
 public:
  static constexpr std::size_t kMin = std::size_t(1) << 16;
  static constexpr std::size_t kHuge = std::size_t(1) << 21;

  /// The size class of a block of `bytes` (at least kMin): at most an eighth more below 1 MiB,
  /// whole 2 MiB pages from there on.
  static std::size_t size_class(std::size_t bytes) {
    if (bytes < kHuge / 2) {
      const std::size_t step = (std::size_t(1) << (63 - __builtin_clzll(bytes))) / 8;
      const std::size_t rounded = (bytes + step - 1) / step * step;
      if (rounded < kHuge / 2) return rounded;
    }
    return (bytes + kHuge - 1) & ~(kHuge - 1);
  }
  /// The most recently kept block of exactly `size` bytes (a size class), or nullptr. The blocks
  /// stay in the order they were kept, oldest first.
  void* take(std::size_t size) {
    for (std::size_t i = blocks_.size(); i-- > 0;)
      if (blocks_[i].first == size) {
        void* p = blocks_[i].second;
        blocks_.erase(blocks_.begin() + static_cast<std::ptrdiff_t>(i));
        total_ -= size;
        return p;
      }
    return nullptr;
  }
  /// Keeps a block for later, freeing the oldest kept ones to make room (a thread whose sizes
  /// change keeps its recent ones); false (the caller frees it) for a block larger than the cache.
  bool keep(void* p, std::size_t size) {
    if (size > kMaxBytes) return false;
    std::size_t drop = 0;  // the oldest blocks, freed
    while (total_ + size > kMaxBytes || blocks_.size() - drop >= kMaxBlocks) {
      std::free(blocks_[drop].second);
      total_ -= blocks_[drop].first;
      ++drop;
    }
    blocks_.erase(blocks_.begin(), blocks_.begin() + static_cast<std::ptrdiff_t>(drop));
    blocks_.emplace_back(size, p);  // no allocation: room for kMaxBlocks is reserved
    total_ += size;
    return true;
  }
  /// A new block of `size` bytes (a size class): 2 MiB-aligned and hinted for huge pages (Linux)
  /// from 2 MiB on, so that first touching it faults 2 MiB at a time.
  static void* fresh(std::size_t size) {
    void* p = nullptr;
    if (posix_memalign(&p, size >= kHuge ? kHuge : 64, size) != 0) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if (size >= kHuge) madvise(p, size, MADV_HUGEPAGE);
#endif
    return p;
  }
  BlockCache() {
    blocks_.reserve(kMaxBlocks);
  }
  ~BlockCache() {
    for (const auto& b : blocks_) std::free(b.second);
  }
  BlockCache(const BlockCache&) = delete;
  BlockCache& operator=(const BlockCache&) = delete;
  /// Bytes kept.
  std::size_t kept_bytes() const {
    return total_;
  }
  /// The calling thread's cache. (An object holding such blocks must not outlive its thread's
  /// cache: a thread_local or static one destroyed after it would return blocks to a dead cache.
  /// The bit rows live within one call.)
  static BlockCache& of_this_thread() {
    thread_local BlockCache cache;
    return cache;
  }

 private:
  static constexpr std::size_t kMaxBytes = std::size_t(64) << 20;
  static constexpr std::size_t kMaxBlocks = 32;
  std::vector<std::pair<std::size_t, void*>> blocks_;  // (size class, block)
  std::size_t total_ = 0;
};

/// An allocator for large arrays built afresh on every call: blocks of 64 KiB and more come from
/// the thread's BlockCache (or are made in its size classes) and go back to it.
template <class T>
struct BlockAllocator {
  using value_type = T;
  BlockAllocator() = default;
  template <class U>
  BlockAllocator(const BlockAllocator<U>&) noexcept {}
  T* allocate(std::size_t n) {
    if (n > (std::size_t(-1) - BlockCache::kHuge) / sizeof(T)) throw std::bad_alloc();
    const std::size_t bytes = n * sizeof(T);
    if (bytes < BlockCache::kMin) return std::allocator<T>().allocate(n);
    const std::size_t size = BlockCache::size_class(bytes);
    void* p = BlockCache::of_this_thread().take(size);
    return static_cast<T*>(p ? p : BlockCache::fresh(size));
  }
  void deallocate(T* p, std::size_t n) noexcept {
    const std::size_t bytes = n * sizeof(T);
    if (bytes < BlockCache::kMin) {
      std::allocator<T>().deallocate(p, n);
      return;
    }
    if (!BlockCache::of_this_thread().keep(p, BlockCache::size_class(bytes))) std::free(p);
  }
  friend bool operator==(const BlockAllocator&, const BlockAllocator&) { return true; }
  friend bool operator!=(const BlockAllocator&, const BlockAllocator&) { return false; }
};

/// An allocator whose resize() leaves new elements of a trivial type uninitialised, for arrays
/// that are written in full right after (zeroing them first was a tenth of the clique step on
/// m = 5000).
template <class T>
struct UninitAllocator : std::allocator<T> {
  template <class U>
  struct rebind {
    using other = UninitAllocator<U>;
  };
  UninitAllocator() = default;
  template <class U>
  UninitAllocator(const UninitAllocator<U>&) noexcept {}
  template <class U>
  void construct(U* p) noexcept {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

/// A vector of a trivial type that resize() does not zero.
template <class T>
using UninitVector = std::vector<T, UninitAllocator<T>>;

}  // namespace pagor::detail
