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
#include <vector>

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
