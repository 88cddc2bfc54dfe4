// The Hilbert index is a space-filling curve (consecutive keys are grid neighbours) and the
// BRIO order is a permutation.
#include <rapidcheck/catch.h>

#include <catch2/catch.hpp>
#include <cstdlib>
#include <map>

#include "generators.hpp"
#include "rstruct/triangulation/spatial_sort.hpp"

using rstruct::triangulation::hilbert_index_3d;

TEST_CASE("the Hilbert curve fills the corner block 8^3 with unit steps") {
  // The curve starts at the origin, so its first 8^k keys fill the block [0, 2^k)^3.
  std::map<std::uint64_t, std::array<int, 3>> by_key;
  for (int x = 0; x < 8; ++x) {
    for (int y = 0; y < 8; ++y) {
      for (int z = 0; z < 8; ++z) by_key[hilbert_index_3d(x, y, z)] = {x, y, z};
    }
  }
  REQUIRE(by_key.size() == 512);
  CHECK(by_key.begin()->first == 0);
  CHECK(by_key.rbegin()->first == 511);
  std::array<int, 3> prev = by_key.begin()->second;
  for (auto it = std::next(by_key.begin()); it != by_key.end(); ++it) {
    const auto& c = it->second;
    const int step = std::abs(c[0] - prev[0]) + std::abs(c[1] - prev[1]) + std::abs(c[2] - prev[2]);
    CHECK(step == 1);
    prev = c;
  }
}

TEST_CASE("orders are permutations") {
  rc::prop("hilbert_order and brio_order", [] {
    const auto seed = *rc::gen::arbitrary<std::uint64_t>();
    const auto n = static_cast<std::size_t>(*rc::gen::inRange(0, 3000));
    const auto p = rstruct::test::uniform_points(n, seed);
    for (const auto& order : {rstruct::triangulation::hilbert_order(p),
                              rstruct::triangulation::brio_order(p, seed)}) {
      std::vector<char> seen(n, 0);
      RC_ASSERT(order.size() == n);
      for (const auto i : order) {
        RC_ASSERT(i < n);
        RC_ASSERT(!seen[i]);
        seen[i] = 1;
      }
    }
  });
}
