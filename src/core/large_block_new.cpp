// Replaces the global operator new / delete of the programs that link this file (the
// rstruct command and the benchmarks; not the library, which leaves allocation to its
// host): blocks of kLargeBlock bytes and more are 2 MiB aligned, rounded up to whole
// 2 MiB pages and advised for transparent huge pages, so that filling them takes one page
// fault per 2 MiB instead of one per 4 KiB. Smaller blocks come from malloc as usual.
//
// Why: the pipeline's stages allocate, fill and free large arrays one after the other
// (cells, stars, facet flags, sorted simplex lists), and glibc returns blocks above its
// mmap threshold to the system on free, so every stage faults its memory in again. On
// this project's virtual machines a 4 KiB page fault costs about 10 µs (1 GiB touched:
// 2.5–3.3 s with 4 KiB pages, 0.06–1.4 s with huge pages); a 10^6-sample torus level
// took 1.07·10^6 minor faults and 9 s of system time.
//
// Memory: a block is backed by whole 2 MiB pages as it is touched, so it may hold up to
// 2 MiB more than it uses; with kLargeBlock = 8 MiB that is at most a quarter of the
// block. Where transparent huge pages are off (or "never"), the advice is ignored and the
// blocks behave as ordinary memory.

#include <cstddef>
#include <cstdlib>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace {

constexpr std::size_t kHugePage = std::size_t{2} << 20;
constexpr std::size_t kLargeBlock = std::size_t{8} << 20;

void* allocate(std::size_t n) noexcept {
  if (n >= kLargeBlock) {
    if (n > static_cast<std::size_t>(-1) - kHugePage) return nullptr;
    const std::size_t rounded = (n + kHugePage - 1) / kHugePage * kHugePage;
    void* p = std::aligned_alloc(kHugePage, rounded);
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if (p != nullptr) (void)madvise(p, rounded, MADV_HUGEPAGE);  // advice only
#endif
    return p;
  }
  return std::malloc(n == 0 ? 1 : n);
}

void* allocate_or_throw(std::size_t n) {
  for (;;) {
    if (void* p = allocate(n)) return p;
    const std::new_handler handler = std::get_new_handler();
    if (handler == nullptr) throw std::bad_alloc();
    handler();
  }
}

void* allocate_or_null(std::size_t n) noexcept {
  try {
    return allocate_or_throw(n);
  } catch (...) {
    return nullptr;
  }
}

}  // namespace

// Every block from these functions is released with free(): malloc's and aligned_alloc's
// blocks alike.
void* operator new(std::size_t n) { return allocate_or_throw(n); }
void* operator new[](std::size_t n) { return allocate_or_throw(n); }
void* operator new(std::size_t n, const std::nothrow_t& /*tag*/) noexcept {
  return allocate_or_null(n);
}
void* operator new[](std::size_t n, const std::nothrow_t& /*tag*/) noexcept {
  return allocate_or_null(n);
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t /*n*/) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t /*n*/) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t& /*tag*/) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t& /*tag*/) noexcept { std::free(p); }
