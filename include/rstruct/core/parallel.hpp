#pragma once
/// \file
/// A minimal parallel loop over an index range for the pipeline's embarrassingly parallel
/// stages (dual-complex classification, sample map, vertex stars): std::jthreads take
/// chunks of the range from a shared atomic counter, so uneven chunks (expensive exact
/// fallbacks, long walks) balance themselves. An exception thrown by any chunk stops the
/// other threads from taking new chunks and is rethrown in the caller (the first one wins).
/// Also cpu_relax(), the processor hint inside short busy waits (the parallel triangulation's
/// retries after another worker's vertex locks).

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace rstruct {

/// A hint to the processor inside a short busy wait (x86: pause, AArch64: yield, elsewhere
/// nothing).
inline void cpu_relax() noexcept {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();  // GCC and Clang; no <immintrin.h> in a header included everywhere
#elif defined(__aarch64__)
  asm volatile("yield");
#endif
}

/// Threads to use for `requested` (0: hardware concurrency), never more than one per
/// `min_chunk` items of `n` and never less than one.
inline unsigned thread_count(unsigned requested, std::size_t n, std::size_t min_chunk = 1) {
  unsigned t = requested != 0 ? requested : std::max(1u, std::thread::hardware_concurrency());
  const std::size_t useful = std::max<std::size_t>(1, n / std::max<std::size_t>(1, min_chunk));
  return static_cast<unsigned>(std::min<std::size_t>(t, useful));
}

/// Calls fn(begin, end, worker) for consecutive chunks [begin, end) covering [0, n), each
/// chunk at most `chunk` long, on `threads` threads (0: hardware concurrency; the caller's
/// thread is worker 0). fn must be safe to call concurrently on disjoint chunks.
template <class F>
void parallel_chunks(std::size_t n, unsigned threads, std::size_t chunk, F&& fn) {
  chunk = std::max<std::size_t>(1, chunk);
  const unsigned workers = thread_count(threads, n, chunk);
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr error;
  std::mutex mutex;
  auto work = [&](unsigned worker) {
    try {
      while (!failed.load(std::memory_order_relaxed)) {
        const std::size_t begin = next.fetch_add(chunk, std::memory_order_relaxed);
        if (begin >= n) break;
        fn(begin, std::min(n, begin + chunk), worker);
      }
    } catch (...) {
      failed.store(true, std::memory_order_relaxed);
      const std::lock_guard<std::mutex> lock(mutex);
      if (!error) error = std::current_exception();
    }
  };
  {
    std::vector<std::jthread> pool;
    pool.reserve(workers - 1);
    for (unsigned w = 1; w < workers; ++w) pool.emplace_back(work, w);
    work(0);
  }  // join
  if (error) std::rethrow_exception(error);
}

}  // namespace rstruct
