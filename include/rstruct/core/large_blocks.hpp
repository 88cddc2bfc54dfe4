#pragma once
/// \file
/// Counters of the programs' replacement operator new (src/core/large_block_new.cpp): how
/// many large blocks came from fresh memory and how many from blocks freed earlier. Only
/// programs that link that file (the rstruct command, the benchmarks, its test) define
/// large_block_stats(). shrink_large_block() is defined everywhere.

#include <cstddef>
#include <cstdint>

namespace rstruct {

struct LargeBlockStats {
  std::uint64_t fresh = 0;     ///< large blocks taken from the system
  std::uint64_t reused = 0;    ///< large blocks served from the cache of freed ones
  std::uint64_t released = 0;  ///< cached blocks given back to the system
  /// Cached ranges whose pages were moved to the front of a fresh block (that block is
  /// counted in `fresh`).
  std::uint64_t moved = 0;
  std::size_t cached_blocks = 0;
  std::size_t cached_bytes = 0;
  std::size_t live_blocks = 0;  ///< tracked large blocks in use
};

LargeBlockStats large_block_stats();

/// Gives back the pages of a block from operator new (`size` bytes at p) beyond its first
/// `used` bytes, which stay valid; the block is still released by operator delete(p). In the
/// programs that link large_block_new.cpp, the pages of a large block go to its cache of
/// freed pages (the next large allocation may take them, already touched); elsewhere, on
/// Linux, to the system (madvise MADV_DONTNEED on the whole pages past `used`). Returns
/// whether any page was given back. \pre used <= size.
bool shrink_large_block(void* p, std::size_t size, std::size_t used) noexcept;

}  // namespace rstruct
