#pragma once
// A spatially coherent order of points (Morton / Z-order of a 21-bit grid over their
// bounding box). Used only to make memory access local (kd-tree leaves, query order);
// no result depends on it.

#include <cstdint>
#include <span>
#include <vector>

#include "rstruct/geometry/vec3.hpp"

namespace rstruct::poles::detail {

/// Indices of `points` sorted by Morton code (ties by index). Non-finite points sort last.
std::vector<std::uint32_t> morton_order(std::span<const Point3> points);

}  // namespace rstruct::poles::detail
