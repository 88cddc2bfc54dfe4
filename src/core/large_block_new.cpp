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
//
// Freed large blocks are kept (at most 256 ranges, at most a quarter of physical memory,
// adjacent ones merged), and a request takes the front of the smallest cached range that
// holds it: those pages are already there, so the next stage neither faults them in nor
// waits while the kernel zeroes them (a 2 MiB huge page is zeroed on its first touch:
// 10-15 % of the set cover's time on 10^6 torus samples). A request that no cached range
// holds gets fresh pages with cached ranges moved to their front, as many as fit (largest
// first), and every other cached range goes back to the system, so the cache never raises
// the peak: resident memory is at most what it would be without the cache. shrink_large_block() gives the
// unused end of a live block to the cache.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <mutex>
#include <new>

#include "rstruct/core/large_blocks.hpp"

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace {

constexpr std::size_t kHugePage = std::size_t{2} << 20;
constexpr std::size_t kLargeBlock = std::size_t{8} << 20;

#if defined(__linux__)

constexpr std::size_t kMaxLive = 4096;  // large blocks tracked at once (beyond: plain malloc)
constexpr std::size_t kMaxCached = 256;  // free ranges kept

struct Range {
  char* p = nullptr;
  std::size_t bytes = 0;  // whole 2 MiB pages
};

/// The large blocks handed out (so that delete knows their size) and the free ranges of
/// pages kept for reuse. Plain arrays: this code must not allocate through operator new.
struct LargeBlocks {
  std::mutex mutex;
  Range live[kMaxLive];
  std::size_t live_count = 0;
  Range cached[kMaxCached];
  std::size_t cached_count = 0;
  std::size_t cached_bytes = 0;
  std::size_t cache_limit = 0;  // 0: not read yet
  rstruct::LargeBlockStats stats;

  /// A quarter of physical memory (1 GiB where it cannot be read).
  std::size_t limit() {
    if (cache_limit == 0) {
      cache_limit = std::size_t{1} << 30;
      const long pages = sysconf(_SC_PHYS_PAGES);
      const long page = sysconf(_SC_PAGESIZE);
      if (pages > 0 && page > 0) {
        cache_limit = static_cast<std::size_t>(pages) / 4 * static_cast<std::size_t>(page);
      }
    }
    return cache_limit;
  }

  /// Fresh pages from the system: a 2 MiB aligned mapping advised for huge pages.
  static char* map(std::size_t bytes) {
    void* raw = mmap(nullptr, bytes + kHugePage, PROT_READ | PROT_WRITE,
                     MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (raw == MAP_FAILED) return nullptr;
    char* const base = static_cast<char*>(raw);
    const std::size_t skip = (kHugePage - reinterpret_cast<std::uintptr_t>(base) % kHugePage) % kHugePage;
    if (skip > 0) munmap(base, skip);
    if (kHugePage - skip > 0) munmap(base + skip + bytes, kHugePage - skip);
#if defined(MADV_HUGEPAGE)
    (void)madvise(base + skip, bytes, MADV_HUGEPAGE);  // advice only
#endif
    return base + skip;
  }

  void release_cache() {
    for (std::size_t k = 0; k < cached_count; ++k) munmap(cached[k].p, cached[k].bytes);
    stats.released += cached_count;
    cached_count = 0;
    cached_bytes = 0;
  }

  /// Keeps the free range r (merged with its neighbours), or unmaps it.
  void keep(Range r) {
    for (std::size_t k = 0; k < cached_count;) {
      const Range c = cached[k];
      if (c.p + c.bytes == r.p || r.p + r.bytes == c.p) {
        r = Range{c.p < r.p ? c.p : r.p, c.bytes + r.bytes};
        cached[k] = cached[--cached_count];
        cached_bytes -= c.bytes;
      } else {
        ++k;
      }
    }
    if (cached_count < kMaxCached && cached_bytes + r.bytes <= limit()) {
      cached[cached_count++] = r;
      cached_bytes += r.bytes;
    } else {
      munmap(r.p, r.bytes);
      ++stats.released;
    }
  }

  /// A block of `bytes` (more than any cached range holds) from fresh pages, with cached
  /// ranges moved to its front one after the other (mremap moves the pages, already
  /// touched, without copying them): the largest first, then each next largest that still
  /// fits. The cached ranges that do not fit go back to the system, so the cache never adds
  /// to the peak (see the file comment). Moving only the largest range and giving the others
  /// back threw away pages the next stage then faulted in again.
  char* map_with_cached(std::size_t bytes) {
    if (cached_count == 0) return map(bytes);
    std::sort(cached, cached + cached_count,
              [](const Range& a, const Range& b) { return a.bytes > b.bytes; });
    Range moving[kMaxCached];
    std::size_t moving_count = 0;
    std::size_t filled = 0;
    std::size_t kept = 0;
    for (std::size_t k = 0; k < cached_count; ++k) {
      if (filled + cached[k].bytes <= bytes) {
        moving[moving_count++] = cached[k];
        filled += cached[k].bytes;
      } else {
        cached[kept++] = cached[k];
      }
    }
    cached_count = kept;
    cached_bytes -= filled;
    release_cache();
    char* const p = map(bytes);
    // Both 2 MiB aligned, so the huge pages move whole. On failure the fresh pages stay.
    std::size_t offset = 0;
    for (std::size_t k = 0; k < moving_count; ++k) {
      const Range r = moving[k];
      if (p == nullptr ||
          mremap(r.p, r.bytes, r.bytes, MREMAP_MAYMOVE | MREMAP_FIXED, p + offset) == MAP_FAILED) {
        munmap(r.p, r.bytes);
        ++stats.released;
      } else {
        ++stats.moved;
      }
      offset += r.bytes;
    }
    return p;
  }

  /// Carves `bytes` from the front of the smallest cached range that holds them.
  char* take_cached(std::size_t bytes) {
    std::size_t best = kMaxCached;
    for (std::size_t k = 0; k < cached_count; ++k) {
      if (cached[k].bytes >= bytes && (best == kMaxCached || cached[k].bytes < cached[best].bytes)) {
        best = k;
      }
    }
    if (best == kMaxCached) return nullptr;
    char* const p = cached[best].p;
    cached[best].p += bytes;
    cached[best].bytes -= bytes;
    cached_bytes -= bytes;
    if (cached[best].bytes == 0) cached[best] = cached[--cached_count];
    return p;
  }
};

constinit LargeBlocks g_blocks;  // constant-initialised: usable before any constructor runs

void* allocate_large(std::size_t n) noexcept {
  if (n > static_cast<std::size_t>(-1) / 2) return nullptr;
  const std::size_t rounded = (n + kHugePage - 1) / kHugePage * kHugePage;
  LargeBlocks& b = g_blocks;
  const std::lock_guard lock(b.mutex);
  if (b.live_count == kMaxLive) {
    // Untracked: malloc's block, released by free() (delete finds no record of it).
    void* p = std::aligned_alloc(kHugePage, rounded);
#if defined(MADV_HUGEPAGE)
    if (p != nullptr) (void)madvise(p, rounded, MADV_HUGEPAGE);
#endif
    return p;
  }
  char* p = b.take_cached(rounded);
  if (p != nullptr) {
    ++b.stats.reused;
  } else {
    p = b.map_with_cached(rounded);
    if (p == nullptr) return nullptr;
    ++b.stats.fresh;
  }
  b.live[b.live_count++] = Range{p, rounded};
  return p;
}

/// Gives the whole 2 MiB pages of tracked block p past its first `used` bytes to the cache.
bool shrink(void* p, std::size_t used) noexcept {
  if (p == nullptr || reinterpret_cast<std::uintptr_t>(p) % kHugePage != 0) return false;
  // At least one page stays: delete(p) must still find the block.
  const std::size_t kept = std::max(kHugePage, (used + kHugePage - 1) / kHugePage * kHugePage);
  LargeBlocks& b = g_blocks;
  const std::lock_guard lock(b.mutex);
  for (std::size_t k = 0; k < b.live_count; ++k) {
    Range& r = b.live[k];
    if (r.p != p) continue;
    if (kept >= r.bytes) return false;
    const Range tail{r.p + kept, r.bytes - kept};
    r.bytes = kept;
    b.keep(tail);
    return true;
  }
  return false;
}

void deallocate(void* p) noexcept {
  if (p == nullptr) return;
  // malloc's blocks are rarely 2 MiB aligned: only such a pointer may be one of ours.
  if (reinterpret_cast<std::uintptr_t>(p) % kHugePage == 0) {
    LargeBlocks& b = g_blocks;
    const std::lock_guard lock(b.mutex);
    for (std::size_t k = 0; k < b.live_count; ++k) {
      if (b.live[k].p != p) continue;
      const Range r = b.live[k];
      b.live[k] = b.live[--b.live_count];
      b.keep(r);
      return;
    }
  }
  std::free(p);
}

#else  // not Linux: aligned blocks from the C library, no cache

void* allocate_large(std::size_t n) noexcept {
  if (n > static_cast<std::size_t>(-1) / 2) return nullptr;
  return std::aligned_alloc(kHugePage, (n + kHugePage - 1) / kHugePage * kHugePage);
}

void deallocate(void* p) noexcept { std::free(p); }

#endif

void* allocate(std::size_t n) noexcept {
  if (n >= kLargeBlock) return allocate_large(n);
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

namespace rstruct {

LargeBlockStats large_block_stats() {
#if defined(__linux__)
  LargeBlocks& b = g_blocks;
  const std::lock_guard lock(b.mutex);
  LargeBlockStats s = b.stats;
  s.cached_blocks = b.cached_count;
  s.cached_bytes = b.cached_bytes;
  s.live_blocks = b.live_count;
  return s;
#else
  return {};
#endif
}

bool shrink_large_block(void* p, std::size_t /*size*/, std::size_t used) noexcept {
#if defined(__linux__)
  return shrink(p, used);
#else
  (void)p;
  (void)used;
  return false;
#endif
}

}  // namespace rstruct

// Small blocks and untracked large ones are released with free(), tracked large ones go
// to the cache (or free()).
void* operator new(std::size_t n) { return allocate_or_throw(n); }
void* operator new[](std::size_t n) { return allocate_or_throw(n); }
void* operator new(std::size_t n, const std::nothrow_t& /*tag*/) noexcept {
  return allocate_or_null(n);
}
void* operator new[](std::size_t n, const std::nothrow_t& /*tag*/) noexcept {
  return allocate_or_null(n);
}
void operator delete(void* p) noexcept { deallocate(p); }
void operator delete[](void* p) noexcept { deallocate(p); }
void operator delete(void* p, std::size_t /*n*/) noexcept { deallocate(p); }
void operator delete[](void* p, std::size_t /*n*/) noexcept { deallocate(p); }
void operator delete(void* p, const std::nothrow_t& /*tag*/) noexcept { deallocate(p); }
void operator delete[](void* p, const std::nothrow_t& /*tag*/) noexcept { deallocate(p); }
