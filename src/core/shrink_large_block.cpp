// shrink_large_block() where operator new is not large_block_new.cpp's: a weak definition,
// which the programs' strong one (in large_block_new.cpp) replaces at link time.

#include <cstdint>

#include "rstruct/core/large_blocks.hpp"

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace rstruct {

#if defined(__GNUC__)
__attribute__((weak))
#endif
bool shrink_large_block(void* p, std::size_t size, std::size_t used) noexcept {
#if defined(__linux__) && defined(MADV_DONTNEED)
  const long page_size = sysconf(_SC_PAGESIZE);
  if (page_size <= 0 || p == nullptr || used >= size) return false;
  const auto page = static_cast<std::uintptr_t>(page_size);
  const auto begin = reinterpret_cast<std::uintptr_t>(p);
  // Only whole pages inside the block: the allocator may keep other data around it.
  const std::uintptr_t first = (begin + used + page - 1) / page * page;
  const std::uintptr_t last = (begin + size) / page * page;
  if (last <= first) return false;
  return madvise(reinterpret_cast<void*>(first), last - first, MADV_DONTNEED) == 0;
#else
  (void)p;
  (void)size;
  (void)used;
  return false;
#endif
}

}  // namespace rstruct
