#pragma once
/// \file
/// Counters of the programs' replacement operator new (src/core/large_block_new.cpp): how
/// many large blocks came from fresh memory and how many from blocks freed earlier. Only
/// programs that link that file (the rstruct command, the benchmarks, its test) define
/// large_block_stats().

#include <cstddef>
#include <cstdint>

namespace rstruct {

struct LargeBlockStats {
  std::uint64_t fresh = 0;     ///< large blocks taken from the system
  std::uint64_t reused = 0;    ///< large blocks served from the cache of freed ones
  std::uint64_t released = 0;  ///< cached blocks given back to the system
  std::size_t cached_blocks = 0;
  std::size_t cached_bytes = 0;
  std::size_t live_blocks = 0;  ///< tracked large blocks in use
};

LargeBlockStats large_block_stats();

}  // namespace rstruct
