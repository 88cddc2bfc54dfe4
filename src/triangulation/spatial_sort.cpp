#include "rstruct/triangulation/spatial_sort.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

namespace rstruct::triangulation {

namespace {

constexpr int kBits = 21;
constexpr double kGrid = static_cast<double>((1u << kBits) - 1);

/// splitmix64: a small, well-mixed generator for the shuffle (deterministic across
/// platforms, unlike std::shuffle's use of the standard distributions).
std::uint64_t next_random(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

struct KeyedIndex {
  std::uint64_t key;
  std::uint32_t index;
};

/// Maps every point to its Hilbert key on a 2^21 grid over the bounding box.
class HilbertKeyer {
 public:
  explicit HilbertKeyer(std::span<const Point3> points) {
    Box3 box;
    for (const Point3& p : points) box.add(p);
    lo_ = box.lo;
    for (std::size_t a = 0; a < 3; ++a) {
      const double extent = box.hi[a] - box.lo[a];
      scale_[a] = extent > 0 && std::isfinite(extent) ? kGrid / extent : 0.0;
    }
  }
  std::uint64_t key(const Point3& p) const {
    std::uint32_t g[3];
    for (std::size_t a = 0; a < 3; ++a) {
      const double t = (p[a] - lo_[a]) * scale_[a];
      g[a] = static_cast<std::uint32_t>(std::clamp(t, 0.0, kGrid));
    }
    return hilbert_index_3d(g[0], g[1], g[2]);
  }

 private:
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
  std::uint32_t v[3] = {x, y, z};
  const std::uint32_t top = 1u << (kBits - 1);
  // Skilling: undo the excess work of the Gray code, from the top bit down.
  for (std::uint32_t q = top; q > 1; q >>= 1) {
    const std::uint32_t p = q - 1;
    for (int i = 0; i < 3; ++i) {
      if (v[i] & q) {
        v[0] ^= p;
      } else {
        const std::uint32_t t = (v[0] ^ v[i]) & p;
        v[0] ^= t;
        v[i] ^= t;
      }
    }
  }
  // Gray encode.
  v[1] ^= v[0];
  v[2] ^= v[1];
  std::uint32_t t = 0;
  for (std::uint32_t q = top; q > 1; q >>= 1) {
    if (v[2] & q) t ^= q - 1;
  }
  for (std::uint32_t& c : v) c ^= t;
  // Interleave the transposed bits, most significant first.
  std::uint64_t key = 0;
  for (int b = kBits - 1; b >= 0; --b) {
    for (int i = 0; i < 3; ++i) key = (key << 1) | ((v[i] >> b) & 1u);
  }
  return key;
}

std::vector<std::uint32_t> hilbert_order(std::span<const Point3> points) {
  const HilbertKeyer keyer(points);
  std::vector<KeyedIndex> items(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    items[i] = {keyer.key(points[i]), static_cast<std::uint32_t>(i)};
  }
  sort_by_key(items, 0, items.size());
  std::vector<std::uint32_t> order(items.size());
  for (std::size_t i = 0; i < items.size(); ++i) order[i] = items[i].index;
  return order;
}

std::vector<std::uint32_t> brio_order(std::span<const Point3> points, std::uint64_t seed,
                                      std::uint32_t ratio_divisor, std::size_t min_round) {
  const std::size_t n = points.size();
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::uint64_t state = seed;
  for (std::size_t i = n; i > 1; --i) {
    const std::size_t j = static_cast<std::size_t>(next_random(state) % i);
    std::swap(order[i - 1], order[j]);
  }
  const HilbertKeyer keyer(points);
  std::vector<KeyedIndex> items(n);
  for (std::size_t i = 0; i < n; ++i) items[i] = {keyer.key(points[order[i]]), order[i]};
  const std::size_t divisor = std::max<std::uint32_t>(ratio_divisor, 2);
  std::size_t end = n;
  while (end > min_round) {
    const std::size_t begin = end / divisor;
    sort_by_key(items, begin, end);
    end = begin;
  }
  sort_by_key(items, 0, end);
  for (std::size_t i = 0; i < n; ++i) order[i] = items[i].index;
  return order;
}

}  // namespace rstruct::triangulation
