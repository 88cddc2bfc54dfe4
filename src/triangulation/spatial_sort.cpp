#include "rstruct/triangulation/spatial_sort.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

namespace rstruct::triangulation {

namespace {

constexpr int kBits = 21;
/// BRIO keys: a 16-bit-per-axis Hilbert index (2^48 cells: far finer than any point set we
/// triangulate) with the round above it.
constexpr int kSortBits = 16;
constexpr int kRoundShift = 3 * kSortBits;

/// splitmix64: a small, well-mixed generator for the shuffle (deterministic across
/// platforms, unlike std::shuffle's use of the standard distributions).
std::uint64_t next_random(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

std::uint64_t hilbert_index(std::uint32_t x, std::uint32_t y, std::uint32_t z, int bits);

struct KeyedIndex {
  std::uint64_t key;
  std::uint32_t index;
};

/// Maps every point to its Hilbert key on a 2^21 grid over the bounding box.
class HilbertKeyer {
 public:
  HilbertKeyer(std::span<const Point3> points, int bits)
      : bits_(bits), grid_(static_cast<double>((1u << bits) - 1)) {
    Box3 box;
    for (const Point3& p : points) box.add(p);
    lo_ = box.lo;
    for (std::size_t a = 0; a < 3; ++a) {
      const double extent = box.hi[a] - box.lo[a];
      scale_[a] = extent > 0 && std::isfinite(extent) ? grid_ / extent : 0.0;
    }
  }
  std::uint64_t key(const Point3& p) const {
    std::uint32_t g[3];
    for (std::size_t a = 0; a < 3; ++a) {
      const double t = (p[a] - lo_[a]) * scale_[a];
      g[a] = static_cast<std::uint32_t>(std::clamp(t, 0.0, grid_));
    }
    return hilbert_index(g[0], g[1], g[2], bits_);
  }

 private:
  int bits_;
  double grid_;
  Point3 lo_;
  double scale_[3] = {0, 0, 0};
};

void sort_by_key(std::vector<KeyedIndex>& items, std::size_t begin, std::size_t end) {
  std::sort(items.begin() + static_cast<std::ptrdiff_t>(begin),
            items.begin() + static_cast<std::ptrdiff_t>(end),
            [](const KeyedIndex& a, const KeyedIndex& b) {
              return a.key < b.key || (a.key == b.key && a.index < b.index);
            });
}

}  // namespace

std::uint64_t hilbert_index_3d(std::uint32_t x, std::uint32_t y, std::uint32_t z) {
  return hilbert_index(x, y, z, kBits);
}

namespace {

/// Bit k of x moved to bit 3k (k < 21).
std::uint64_t spread_bits(std::uint64_t x) {
  x &= 0x1FFFFF;
  x = (x | x << 32) & 0x1F00000000FFFFull;
  x = (x | x << 16) & 0x1F0000FF0000FFull;
  x = (x | x << 8) & 0x100F00F00F00F00Full;
  x = (x | x << 4) & 0x10C30C30C30C30C3ull;
  x = (x | x << 2) & 0x1249249249249249ull;
  return x;
}

// Skilling's transpose algorithm, written without data-dependent branches (the bit tests
// of the original are unpredictable and dominated the sort).
std::uint64_t hilbert_index(std::uint32_t x, std::uint32_t y, std::uint32_t z, int bits) {
  std::uint32_t v[3] = {x, y, z};
  const std::uint32_t top = 1u << (bits - 1);
  // Undo the excess work of the Gray code, from the top bit down: where bit q of v[i] is
  // set, invert the low bits of v[0]; otherwise exchange the low bits of v[0] and v[i].
  for (std::uint32_t q = top; q > 1; q >>= 1) {
    const std::uint32_t p = q - 1;
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t set = 0u - ((v[i] & q) != 0 ? 1u : 0u);
      const std::uint32_t t = (v[0] ^ v[i]) & p & ~set;
      v[0] ^= (p & set) | t;
      v[i] ^= t;
    }
  }
  // Gray encode.
  v[1] ^= v[0];
  v[2] ^= v[1];
  std::uint32_t t = 0;
  for (std::uint32_t q = top; q > 1; q >>= 1) t ^= (q - 1) & (0u - ((v[2] & q) != 0 ? 1u : 0u));
  for (std::uint32_t& c : v) c ^= t;
  // Interleave the transposed bits, most significant first: v[0] bit b -> key bit 3b + 2.
  return spread_bits(v[0]) << 2 | spread_bits(v[1]) << 1 | spread_bits(v[2]);
}

}  // namespace

std::vector<std::uint32_t> hilbert_order(std::span<const Point3> points) {
  const HilbertKeyer keyer(points, kBits);
  std::vector<KeyedIndex> items(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    items[i] = {keyer.key(points[i]), static_cast<std::uint32_t>(i)};
  }
  sort_by_key(items, 0, items.size());
  std::vector<std::uint32_t> order(items.size());
  for (std::size_t i = 0; i < items.size(); ++i) order[i] = items[i].index;
  return order;
}

std::vector<std::uint32_t> hilbert_keys(std::span<const Point3> points) {
  const HilbertKeyer keyer(points, kSortBits);
  std::vector<std::uint32_t> keys(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    keys[i] = static_cast<std::uint32_t>(keyer.key(points[i]) >> (3 * kSortBits - 32));
  }
  return keys;
}

std::vector<std::uint32_t> brio_order(std::span<const Point3> points, std::uint64_t seed,
                                      std::uint32_t ratio_divisor, std::size_t min_round) {
  const std::size_t n = points.size();
  const std::uint64_t divisor = std::max<std::uint32_t>(ratio_divisor, 2);
  // Rounds: the last holds each point with probability 1 − 1/divisor, the one before it
  // the same share of the rest, ..., so that the first expects at most min_round points.
  int rounds = 1;
  for (double expected = static_cast<double>(n); expected > static_cast<double>(min_round);
       expected /= static_cast<double>(divisor)) {
    ++rounds;
  }
  // One key per point, computed in input order (sequential memory): round in the top
  // bits, Hilbert index below; one sort then gives the rounds in order, each along the
  // curve.
  const HilbertKeyer keyer(points, kSortBits);
  std::vector<KeyedIndex> items(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::uint64_t state = seed ^ (static_cast<std::uint64_t>(i) * 0xD1B54A32D192ED03ull);
    int level = 0;
    while (level < rounds - 1 && next_random(state) % divisor == 0) ++level;
    const auto round = static_cast<std::uint64_t>(rounds - 1 - level);
    items[i] = {round << kRoundShift | keyer.key(points[i]), static_cast<std::uint32_t>(i)};
  }
  sort_by_key(items, 0, n);
  std::vector<std::uint32_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = items[i].index;
  return order;
}

}  // namespace rstruct::triangulation
