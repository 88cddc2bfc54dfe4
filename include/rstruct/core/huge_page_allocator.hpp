#pragma once
// An allocator for large, randomly accessed arrays (the cells of a triangulation): blocks of
// 2 MiB and more are advised for transparent huge pages (their whole 2 MiB pages), so that
// filling them takes one page fault per 2 MiB instead of per 4 KiB, and random access misses
// the TLB far less. Smaller blocks come from operator new. Pages never touched still cost no
// memory (the kernel backs a huge page only when it is first written).

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <new>
#include <utility>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace rstruct {

template <class T>
class HugePageAllocator {
 public:
  using value_type = T;

  HugePageAllocator() noexcept = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>& /*other*/) noexcept {}

  T* allocate(std::size_t n) {
    const std::size_t bytes = n * sizeof(T);
    if (n > static_cast<std::size_t>(-1) / sizeof(T)) throw std::bad_array_new_length();
    if (bytes < kHuge) return static_cast<T*>(::operator new(bytes, std::align_val_t{alignof(T)}));
    // Through the global operator new: in the programs that replace it
    // (src/core/large_block_new.cpp) the block is 2 MiB aligned, advised, and may reuse
    // pages a previous stage freed. Elsewhere it is malloc's, and the advice covers its
    // whole 2 MiB pages.
    void* p = ::operator new(bytes);
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    const auto first = (reinterpret_cast<std::uintptr_t>(p) + kHuge - 1) / kHuge * kHuge;
    const auto last = (reinterpret_cast<std::uintptr_t>(p) + bytes) / kHuge * kHuge;
    // Advice only: without transparent huge pages the block works as ordinary memory.
    if (last > first) (void)madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
#endif
    return static_cast<T*>(p);
  }

  void deallocate(T* p, std::size_t n) noexcept {
    if (n * sizeof(T) < kHuge) {
      ::operator delete(p, std::align_val_t{alignof(T)});
    } else {
      ::operator delete(p);
    }
  }

  /// Default-initialises: resize() leaves new elements of a trivial T unwritten, so
  /// growing the array touches no page (the parallel triangulation sizes its cell array
  /// before its threads fill it).
  template <class U>
  void construct(U* p) noexcept(noexcept(::new(static_cast<void*>(p)) U)) {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }

  template <class U>
  bool operator==(const HugePageAllocator<U>& /*other*/) const noexcept {
    return true;
  }

 private:
  static constexpr std::size_t kHuge = std::size_t{2} << 20;
};

}  // namespace rstruct
