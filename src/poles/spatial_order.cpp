#include "spatial_order.hpp"

#include <algorithm>
#include <cmath>

namespace rstruct::poles::detail {
namespace {

/// Spreads the low 21 bits of x to every third bit.
std::uint64_t spread(std::uint64_t x) {
  x &= 0x1fffffULL;
  x = (x | x << 32) & 0x1f00000000ffffULL;
  x = (x | x << 16) & 0x1f0000ff0000ffULL;
  x = (x | x << 8) & 0x100f00f00f00f00fULL;
  x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
  x = (x | x << 2) & 0x1249249249249249ULL;
  return x;
}

}  // namespace

std::vector<std::uint32_t> morton_order(std::span<const Point3> points) {
  Box3 box;
  for (const Point3& p : points) {
    if (is_finite(p)) box.add(p);
  }
  const double extent = box.empty() ? 0.0 : box.max_extent();
  const double scale = extent > 0 ? static_cast<double>((1U << 21) - 1) / extent : 0.0;
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    std::uint64_t key = ~0ULL;
    if (is_finite(points[i])) {
      key = 0;
      for (std::size_t d = 0; d < 3; ++d) {
        const double t = std::clamp((points[i][d] - box.lo[d]) * scale, 0.0, 2097151.0);
        key |= spread(static_cast<std::uint64_t>(t)) << d;
      }
    }
    keyed[i] = {key, static_cast<std::uint32_t>(i)};
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<std::uint32_t> order(points.size());
  for (std::size_t i = 0; i < keyed.size(); ++i) order[i] = keyed[i].second;
  return order;
}

}  // namespace rstruct::poles::detail
