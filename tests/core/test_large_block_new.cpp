// The replacement operator new of the programs (src/core/large_block_new.cpp, linked into
// this test as into the rstruct command and the benchmarks).
#include <catch2/catch.hpp>
#include <cstdint>
#include <fstream>
#include <limits>
#include <memory>
#include <new>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "rstruct/core/large_blocks.hpp"

namespace {

constexpr std::size_t kHugePage = std::size_t{2} << 20;

std::uintptr_t address(const void* p) { return reinterpret_cast<std::uintptr_t>(p); }

/// The VmFlags line of the mapping of /proc/self/smaps holding address a ("" if none).
std::string vm_flags_of(std::uintptr_t a) {
  std::ifstream smaps("/proc/self/smaps");
  std::string line;
  bool inside = false;
  while (std::getline(smaps, line)) {
    std::uintptr_t lo = 0, hi = 0;
    char dash = 0;
    std::istringstream head(line);
    if (head >> std::hex >> lo >> dash >> hi && dash == '-') {
      inside = lo <= a && a < hi;
      continue;
    }
    if (inside && line.rfind("VmFlags:", 0) == 0) return line;
  }
  return "";
}

bool transparent_huge_pages_available() {
  std::ifstream f("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string s;
  std::getline(f, s);
  return !s.empty() && s.find("[never]") == std::string::npos;
}

}  // namespace

TEST_CASE("large blocks are 2 MiB aligned, usable to their end, advised for huge pages") {
  for (const std::size_t bytes : {std::size_t{8} << 20, (std::size_t{8} << 20) + 1,
                                  std::size_t{37'000'001}}) {
    std::unique_ptr<unsigned char[]> block(new unsigned char[bytes]);
    CHECK(address(block.get()) % kHugePage == 0);
    for (std::size_t i = 0; i < bytes; i += 4096) block[i] = static_cast<unsigned char>(i >> 12);
    block[bytes - 1] = 7;
    CHECK(block[bytes - 1] == 7);
    CHECK(block[4096 * 5] == 5);
    if (transparent_huge_pages_available()) {
      const std::string flags = vm_flags_of(address(block.get()));
      INFO(flags);
      CHECK(flags.find(" hg") != std::string::npos);
    }
  }
}

TEST_CASE("vectors grow through large blocks and keep their contents") {
  std::vector<std::uint64_t> v;
  for (std::uint64_t i = 0; i < 3'000'000; ++i) v.push_back(i * i);
  CHECK(address(v.data()) % kHugePage == 0);
  std::uint64_t wrong = 0;
  for (std::uint64_t i = 0; i < v.size(); ++i) wrong += v[i] != i * i;
  CHECK(wrong == 0);
}

TEST_CASE("small blocks come from malloc, aligned for any fundamental type") {
  for (const std::size_t bytes : {std::size_t{0}, std::size_t{1}, std::size_t{24}, std::size_t{4096},
                                  (std::size_t{8} << 20) - 1}) {
    void* p = ::operator new(bytes);
    CHECK(address(p) % alignof(std::max_align_t) == 0);
    ::operator delete(p);
  }
}

// AddressSanitizer's allocator aborts on such a request instead of failing it (unless
// ASAN_OPTIONS=allocator_may_return_null=1), so the sanitizer build leaves this case out.
#if !defined(__SANITIZE_ADDRESS__)
TEST_CASE("an impossible size throws bad_alloc, or gives null without throwing") {
  // Read through a volatile: a constant would draw the compiler's size warning.
  volatile std::size_t source = std::numeric_limits<std::size_t>::max() - 1000;
  const std::size_t absurd = source;
  CHECK_THROWS_AS(::operator new(absurd), std::bad_alloc);
  CHECK_THROWS_AS(::operator new[](absurd / 2), std::bad_alloc);
  CHECK(::operator new(absurd, std::nothrow) == nullptr);
  CHECK(::operator new[](absurd, std::nothrow) == nullptr);
}
#endif

#if defined(__linux__)
namespace {

constexpr std::size_t kMiB = std::size_t{1} << 20;

/// Frees every cached range: a request no cached range can hold takes fresh pages, and
/// gives every cached range back first.
void empty_cache() {
  // 1 TiB: whether the mapping then fails or not, the cache was emptied first; if it
  // succeeds, delete unmaps it (it exceeds the cache's limit).
  ::operator delete(::operator new(std::size_t{1} << 40, std::nothrow));
}

}  // namespace

TEST_CASE("freed large blocks are served again, carved to size, and merged when adjacent") {
  empty_cache();
  const rstruct::LargeBlockStats s0 = rstruct::large_block_stats();
  CHECK(s0.cached_bytes == 0);
  auto* a = static_cast<unsigned char*>(::operator new(64 * kMiB));
  a[0] = 1;
  a[64 * kMiB - 1] = 2;
  ::operator delete(a);
  const rstruct::LargeBlockStats s1 = rstruct::large_block_stats();
  CHECK(s1.fresh == s0.fresh + 1);
  CHECK(s1.cached_bytes == 64 * kMiB);

  // A smaller request takes the front of the freed block; a second one the next pages.
  auto* b = static_cast<unsigned char*>(::operator new(20 * kMiB));
  auto* c = static_cast<unsigned char*>(::operator new(10 * kMiB + 1));
  CHECK(b == a);
  CHECK(c == a + 20 * kMiB);
  const rstruct::LargeBlockStats s2 = rstruct::large_block_stats();
  CHECK(s2.reused == s1.reused + 2);
  CHECK(s2.fresh == s1.fresh);
  CHECK(s2.cached_bytes == (64 - 20 - 12) * kMiB);  // 10 MiB + 1 byte takes 12 MiB
  // Writable to the end, and independent of each other.
  for (std::size_t i = 0; i < 20 * kMiB; i += 4096) b[i] = 3;
  for (std::size_t i = 0; i < 10 * kMiB + 1; i += 4096) c[i] = 4;
  c[10 * kMiB] = 5;
  CHECK(b[20 * kMiB - 4096] == 3);
  CHECK(c[0] == 4);

  // Freed again, the three ranges merge into the whole block: a 64 MiB request fits.
  ::operator delete(c);
  ::operator delete(b);
  CHECK(rstruct::large_block_stats().cached_blocks == 1);
  auto* d = static_cast<unsigned char*>(::operator new(64 * kMiB));
  CHECK(d == a);
  CHECK(rstruct::large_block_stats().fresh == s1.fresh);
  ::operator delete(d);
}

TEST_CASE("a request no cached range holds takes the cached ranges that fit, largest first") {
  empty_cache();
  // a, gap, c, gap2 and e carved in this order from one freed block: a, c and e are not
  // adjacent (sizes 16, 24 and 20 MiB).
  ::operator delete(::operator new(76 * kMiB));
  auto* a = static_cast<unsigned char*>(::operator new(16 * kMiB));
  auto* gap = static_cast<unsigned char*>(::operator new(8 * kMiB));
  auto* c = static_cast<unsigned char*>(::operator new(24 * kMiB));
  auto* gap2 = static_cast<unsigned char*>(::operator new(8 * kMiB));
  auto* e = static_cast<unsigned char*>(::operator new(20 * kMiB));
  REQUIRE(c == a + 24 * kMiB);
  REQUIRE(e == a + 56 * kMiB);
  for (std::size_t i = 0; i < 16 * kMiB; i += 4096) a[i] = static_cast<unsigned char>(i >> 12 | 1);
  for (std::size_t i = 0; i < 24 * kMiB; i += 4096) c[i] = static_cast<unsigned char>(i >> 12 | 2);
  for (std::size_t i = 0; i < 20 * kMiB; i += 4096) e[i] = static_cast<unsigned char>(i >> 12 | 3);
  ::operator delete(a);
  ::operator delete(c);
  ::operator delete(e);
  const rstruct::LargeBlockStats s0 = rstruct::large_block_stats();
  CHECK(s0.cached_bytes == 60 * kMiB);
  CHECK(s0.cached_blocks == 3);
  // 42 MiB: c's range (24) first, then e's (20) does not fit beside it, a's (16) does.
  auto* big = static_cast<unsigned char*>(::operator new(42 * kMiB));
  const rstruct::LargeBlockStats s1 = rstruct::large_block_stats();
  CHECK(address(big) % kHugePage == 0);
  CHECK(s1.cached_bytes == 0);
  CHECK(s1.fresh == s0.fresh + 1);
  CHECK(s1.moved == s0.moved + 2);
  CHECK(s1.released == s0.released + 1);  // e's range
  // c's pages, then a's, moved with their contents to the front; fresh pages after them.
  std::size_t wrong = 0;
  for (std::size_t i = 0; i < 24 * kMiB; i += 4096) {
    wrong += big[i] != static_cast<unsigned char>(i >> 12 | 2);
  }
  for (std::size_t i = 0; i < 16 * kMiB; i += 4096) {
    wrong += big[24 * kMiB + i] != static_cast<unsigned char>(i >> 12 | 1);
  }
  CHECK(wrong == 0);
  for (std::size_t i = 0; i < 42 * kMiB; i += 4096) big[i] = 9;
  big[42 * kMiB - 1] = 8;
  CHECK(big[42 * kMiB - 1] == 8);
  CHECK(big[40 * kMiB] == 9);
  if (transparent_huge_pages_available()) {
    const std::string flags = vm_flags_of(address(big));
    INFO(flags);
    CHECK(flags.find(" hg") != std::string::npos);
  }
  ::operator delete(big);
  ::operator delete(gap);
  ::operator delete(gap2);
}

TEST_CASE("shrink_large_block gives a live block's end to the cache") {
  empty_cache();
  auto* a = static_cast<unsigned char*>(::operator new(32 * kMiB));
  for (std::size_t i = 0; i < 32 * kMiB; i += 4096) a[i] = 5;
  CHECK(rstruct::shrink_large_block(a, 32 * kMiB, 10 * kMiB + 1));  // keeps 12 MiB
  CHECK(rstruct::large_block_stats().cached_bytes == 20 * kMiB);
  CHECK_FALSE(rstruct::shrink_large_block(a, 32 * kMiB, 12 * kMiB));  // nothing more to give
  CHECK(rstruct::shrink_large_block(a, 32 * kMiB, 0));  // one page stays with the block
  CHECK(rstruct::large_block_stats().cached_bytes == 30 * kMiB);
  CHECK(a[0] == 5);
  CHECK(a[kHugePage - 4096] == 5);
  // The end, cached, serves the next request; the block is still released by delete.
  auto* b = static_cast<unsigned char*>(::operator new(30 * kMiB));
  CHECK(b == a + kHugePage);
  CHECK(b[0] == 5);
  ::operator delete(b);
  ::operator delete(a);
  CHECK(rstruct::large_block_stats().cached_bytes == 32 * kMiB);
  CHECK(rstruct::large_block_stats().cached_blocks == 1);
  int local = 0;
  CHECK_FALSE(rstruct::shrink_large_block(&local, sizeof local, 0));  // not a large block
}

TEST_CASE("large blocks from two threads at once stay intact") {
  empty_cache();
  const auto work = [](unsigned char tag, std::size_t* bad) {
    for (int round = 0; round < 40; ++round) {
      const std::size_t bytes = (8 + static_cast<std::size_t>((round * 7 + tag) % 13)) * kMiB + 123;
      std::unique_ptr<unsigned char[]> block(new unsigned char[bytes]);
      for (std::size_t i = 0; i < bytes; i += 4096) block[i] = tag;
      block[bytes - 1] = tag;
      for (std::size_t i = 0; i < bytes; i += 4096) *bad += block[i] != tag;
      *bad += block[bytes - 1] != tag;
    }
  };
  std::size_t bad1 = 0, bad2 = 0;
  {
    std::thread t(work, static_cast<unsigned char>(1), &bad1);
    work(2, &bad2);
    t.join();
  }
  CHECK(bad1 == 0);
  CHECK(bad2 == 0);
  CHECK(rstruct::large_block_stats().live_blocks == 0);
}
#endif
