// Fuzz target: insertion sequences into RegularTriangulation3 with all checks on.
// Input bytes: byte 0 = flags (bit 0 weighted, bit 1 BRIO order, bits 2-4 exponent shift),
// then one record per point: 3 signed bytes of coordinates (a small grid, so cospherical,
// coplanar and duplicate points are common), plus one unsigned weight byte when weighted.
// Expected outcomes: a valid triangulation after every insertion, or InvalidInput for flat
// input. Anything else (InternalError, an invalid state) escapes and fails the run.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "rstruct/core/error.hpp"
#include "rstruct/triangulation/regular_triangulation_3.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using rstruct::triangulation::RegularTriangulation3;
  if (size < 1) return 0;
  const bool weighted = (data[0] & 1) != 0;
  const int shift = (data[0] >> 2) & 7;
  const std::size_t record = weighted ? 4 : 3;
  const std::size_t n = std::min<std::size_t>((size - 1) / record, 200);
  std::vector<rstruct::Point3> points(n);
  std::vector<double> weights;
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint8_t* r = data + 1 + i * record;
    points[i] = {std::ldexp(static_cast<std::int8_t>(r[0]) % 8, shift * 40 - 120),
                 std::ldexp(static_cast<std::int8_t>(r[1]) % 8, shift * 40 - 120),
                 std::ldexp(static_cast<std::int8_t>(r[2]) % 8, shift * 40 - 120)};
    if (weighted) weights.push_back(std::ldexp(r[3] % 16, 2 * (shift * 40 - 120)));
  }
  rstruct::triangulation::TriangulationOptions options;
  options.spatial_sort = (data[0] & 2) != 0;
  if (n <= 60) {
    options.after_insertion = [](const RegularTriangulation3& t, std::uint32_t) {
      const auto r = t.is_valid();
      if (!r.ok) throw std::logic_error("invalid after insertion: " + r.message);
    };
  }
  try {
    const RegularTriangulation3 t = weighted ? RegularTriangulation3(points, weights, options)
                                             : RegularTriangulation3(points, options);
    const auto r = t.is_valid();
    if (!r.ok) throw std::logic_error("invalid: " + r.message);
    if (t.number_of_vertices() + t.hidden_points().size() + t.duplicate_points().size() != n) {
      throw std::logic_error("points lost");
    }
  } catch (const rstruct::InvalidInput&) {
    // Flat or too small input: the documented outcome.
  }
  return 0;
}
