// Fuzz target: the medial axis of a union of balls, and the .xyzr reader that feeds it.
// Input: if byte 0 is 't', the rest is .xyzr text (parsed; then, for at most 40 balls, the
// axis is built). Otherwise byte 0 = flags (bits 0-1 radius scale) and one 4-byte record
// per ball: 3 signed coordinates on a small grid (so cocircular, cospherical, tangent and
// nested balls are common) and a radius byte.
// Expected outcomes: InvalidInput for malformed text, or a valid axis whose vertices lie in
// the union (up to 1e-9 of its extent). Anything else (InternalError, an invalid axis)
// escapes and fails the run. Betti numbers are not compared: grid inputs hit the documented
// degenerate case (four spheres through one point).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "rstruct/core/error.hpp"
#include "rstruct/medial/medial_axis.hpp"
#include "rstruct/medial/xyzr_format.hpp"

namespace {

void check_axis(const std::vector<rstruct::Ball>& balls) {
  const rstruct::medial::MedialAxis axis = rstruct::medial::medial_axis_of_union(balls);
  std::string problem;
  if (!axis.is_valid(&problem)) throw std::logic_error("invalid medial axis: " + problem);
  double extent = 0;
  for (const auto& b : balls) {
    extent = std::max({extent, std::abs(b.c.x) + b.r, std::abs(b.c.y) + b.r,
                       std::abs(b.c.z) + b.r});
  }
  for (const auto& v : axis.vertices) {
    double depth = -HUGE_VAL;
    for (const auto& b : balls) depth = std::max(depth, b.r - rstruct::distance(v, b.c));
    if (depth < -1e-9 * extent) throw std::logic_error("medial vertex outside the union");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  if (data[0] == 't') {
    const std::string_view text(reinterpret_cast<const char*>(data) + 1, size - 1);
    try {
      const auto balls = rstruct::medial::parse_xyzr(text, "fuzz");
      if (balls.size() <= 40) check_axis(balls);
    } catch (const rstruct::InvalidInput&) {
      // Malformed text, or radii or coordinates out of the supported range.
    }
    return 0;
  }
  const double scale = std::ldexp(1.0, (data[0] & 3) - 1);
  const std::size_t n = std::min<std::size_t>((size - 1) / 4, 60);
  std::vector<rstruct::Ball> balls(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint8_t* r = data + 1 + i * 4;
    balls[i] = {{static_cast<double>(static_cast<std::int8_t>(r[0]) % 8),
                 static_cast<double>(static_cast<std::int8_t>(r[1]) % 8),
                 static_cast<double>(static_cast<std::int8_t>(r[2]) % 8)},
                scale * (1 + r[3] % 16) / 8.0};
  }
  check_axis(balls);
  return 0;
}
