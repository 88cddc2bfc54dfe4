// The Hilbert index is a space-filling curve (consecutive keys are grid neighbours) and the
// BRIO order is a permutation.
#include <rapidcheck/catch.h>

#include <catch2/catch.hpp>
#include <bit>
#include <cstdlib>
#include <map>

#include "generators.hpp"
#include "rstruct/core/error.hpp"
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

TEST_CASE("the keys computed several at a time are the keys one at a time") {
  // Every lane of hilbert_indices_3d (and the last, partial group) against single keys, and
  // single keys against values of the one-at-a-time code the lanes replaced (2026-12-07):
  // the BRIO order, hence every construction's cell ids, stayed the same.
  const std::uint32_t known[4][3] = {{0x1u, 0x2u, 0x3u},
                                     {0x1FFFFFu, 0x0u, 0x12345u},
                                     {0xABCDEu, 0x15555Au, 0xF0F0Fu},
                                     {0x100000u, 0x100000u, 0x100000u}};
  const std::uint64_t known_keys[4] = {0x30ull, 0x7FF87712523ADB8Aull, 0x31A67C88DCF0623Dull,
                                       0x5000000000000000ull};
  for (int i = 0; i < 4; ++i) {
    CHECK(hilbert_index_3d(known[i][0], known[i][1], known[i][2]) == known_keys[i]);
  }
  std::vector<std::uint32_t> two(2, 1), one(1, 1);
  std::vector<std::uint64_t> out(2);
  CHECK_THROWS_AS(rstruct::triangulation::hilbert_indices_3d(two, one, two, out),
                  rstruct::InvalidInput);
  CHECK_THROWS_AS(rstruct::triangulation::hilbert_indices_3d(two, two, two, std::span(out).first(1)),
                  rstruct::InvalidInput);
  rc::prop("lanes", [] {
    const auto n = static_cast<std::size_t>(*rc::gen::inRange(0, 100));
    const auto coordinate = rc::gen::inRange<std::uint32_t>(0, 1u << 21);
    const auto x = *rc::gen::container<std::vector<std::uint32_t>>(n, coordinate);
    const auto y = *rc::gen::container<std::vector<std::uint32_t>>(n, coordinate);
    const auto z = *rc::gen::container<std::vector<std::uint32_t>>(n, coordinate);
    std::vector<std::uint64_t> keys(n);
    rstruct::triangulation::hilbert_indices_3d(x, y, z, keys);
    for (std::size_t i = 0; i < n; ++i) RC_ASSERT(keys[i] == hilbert_index_3d(x[i], y[i], z[i]));
  });
}

TEST_CASE("the sorting keys span the bounding box: its corners take the curve's octants in order") {
  // hilbert_keys (12 bits per axis over the box, the key's top 32 bits): the first level of
  // the curve visits the eight octants one after another, each next to the one before, so
  // the corners' top 3 bits are 0..7 and corners of consecutive octants share two
  // coordinates. Keys cut from the wrong bits of the index, or a grid not scaled to the
  // box, break this.
  std::vector<rstruct::Point3> corners;
  for (int i = 0; i < 8; ++i) corners.push_back({double(i & 1), double(i >> 1 & 1), double(i >> 2)});
  const std::vector<std::uint32_t> keys = rstruct::triangulation::hilbert_keys(corners);
  std::map<std::uint32_t, int> by_octant;
  for (int i = 0; i < 8; ++i) by_octant[keys[static_cast<std::size_t>(i)] >> 29] = i;
  REQUIRE(by_octant.size() == 8);
  CHECK(by_octant.begin()->first == 0);
  CHECK(by_octant.rbegin()->first == 7);
  for (auto it = std::next(by_octant.begin()); it != by_octant.end(); ++it) {
    CHECK(std::popcount(static_cast<unsigned>(it->second ^ std::prev(it)->second)) == 1);
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

TEST_CASE("the orders and keys do not depend on the threads computing them") {
  // 2^17 + 5 points: up to four stretches of 2^15 sorted side by side, and with three
  // threads a stretch left over at the first merge.
  namespace tr = rstruct::triangulation;
  const std::size_t n = (std::size_t{1} << 17) + 5;
  auto p = rstruct::test::uniform_points(n, 11);
  for (std::size_t i = 0; i < 1000; ++i) p[n - 1 - i] = p[i];  // equal keys: ties by index
  const std::vector<std::uint32_t> hilbert = tr::hilbert_order(p, 1);
  const std::vector<std::uint32_t> brio = tr::brio_order(p, 5, 4, 256, 1);
  const std::vector<std::uint32_t> keys = tr::hilbert_keys(p);
  for (const unsigned threads : {2u, 3u, 4u}) {
    CHECK(tr::hilbert_order(p, threads) == hilbert);
    std::vector<std::uint32_t> brio_keys;
    CHECK(tr::brio_order(p, 5, 4, 256, threads, &brio_keys) == brio);
    CHECK(brio_keys == keys);
  }
  // One round: the order is along the curve, so the keys never decrease.
  std::vector<std::uint32_t> one_round_keys;
  const auto one_round = tr::brio_order(p, 5, 4, n, 1, &one_round_keys);
  for (std::size_t r = 1; r < n; ++r) {
    if (one_round_keys[one_round[r - 1]] > one_round_keys[one_round[r]]) FAIL("keys decrease at " << r);
  }
  // The ties go by index: equal points are listed in increasing index order.
  std::vector<std::size_t> rank(n);
  for (std::size_t r = 0; r < n; ++r) rank[hilbert[r]] = r;
  for (std::size_t i = 0; i < 1000; ++i) CHECK(rank[i] < rank[n - 1 - i]);
}
