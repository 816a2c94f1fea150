#pragma once
// Internal: storage for the dense graphs' large arrays (tens of MiB on thousands of
// correspondences), where first touching the memory costs more than the work on it.

#include <cstdint>
#include <cstdlib>
#include <memory>
#include <new>
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

/// An allocator for arrays of megabytes built afresh on every call (a dense level's bit rows):
/// storage from 1 MiB on is aligned to 2 MiB and hinted for huge pages (Linux), so first touching
/// it faults 2 MiB at a time. Each call's first touch of 4 KiB pages was a third of the first
/// clique step on m = 5000 (hint_huge_pages above covers only a buffer's aligned middle).
template <class T>
struct HugePageAllocator {
  using value_type = T;
  HugePageAllocator() = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>&) noexcept {}
  T* allocate(std::size_t n) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if (n >= kLarge / sizeof(T)) {
      if (n > (std::size_t(-1) - kHuge) / sizeof(T)) throw std::bad_alloc();
      const std::size_t bytes = (n * sizeof(T) + kHuge - 1) & ~(kHuge - 1);
      void* p = nullptr;
      if (posix_memalign(&p, kHuge, bytes) != 0) throw std::bad_alloc();
      madvise(p, bytes, MADV_HUGEPAGE);
      return static_cast<T*>(p);
    }
#endif
    return std::allocator<T>().allocate(n);
  }
  void deallocate(T* p, std::size_t n) noexcept {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if (n >= kLarge / sizeof(T)) {
      std::free(p);
      return;
    }
#endif
    std::allocator<T>().deallocate(p, n);
  }
  friend bool operator==(const HugePageAllocator&, const HugePageAllocator&) {
    return true;
  }
  friend bool operator!=(const HugePageAllocator&, const HugePageAllocator&) {
    return false;
  }

 private:
  static constexpr std::size_t kLarge = std::size_t(1) << 20;
  static constexpr std::size_t kHuge = std::size_t(1) << 21;
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
