// Fuzz target: insertion sequences into RegularTriangulation3 with all checks on.
// Input bytes: byte 0 = flags (bit 0 weighted, bit 1 BRIO order, bits 2-4 exponent shift,
// bit 5 parallel insertion with 2 threads, 3 with bit 6 too; then up to 400 points and the
// cells are compared with a one-thread build's; bit 7 with bit 5: vertex locks and the
// canonical order, and the whole cell array is compared),
// then one record per point: 3 signed bytes of coordinates (a small grid, so cospherical,
// coplanar and duplicate points are common), plus one unsigned weight byte when weighted.
// Expected outcomes: a valid triangulation after every insertion, or InvalidInput for flat
// input. Anything else (InternalError, an invalid state) escapes and fails the run.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <set>
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
  const bool parallel = (data[0] & 32) != 0;
  const std::size_t n = std::min<std::size_t>((size - 1) / record, parallel ? 400 : 200);
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
  if (parallel) {
    options.threads = 2 + ((data[0] >> 6) & 1);
    options.parallel_min_round = 1;  // every round of 64 points per thread
    if ((data[0] & 128) != 0) {
      options.parallel_scheme = rstruct::triangulation::TriangulationOptions::ParallelScheme::locks;
      options.canonical_order = true;
    }
  } else if (n <= 60) {
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
    if (parallel) {
      // The triangulation is unique: one thread must give the same cells.
      rstruct::triangulation::TriangulationOptions one;
      one.spatial_sort = options.spatial_sort;
      one.canonical_order = options.canonical_order;
      const RegularTriangulation3 s = weighted ? RegularTriangulation3(points, weights, one)
                                               : RegularTriangulation3(points, one);
      const auto cells = [](const RegularTriangulation3& x) {
        std::set<std::array<std::uint32_t, 4>> out;
        x.for_each_finite_cell([&](std::uint32_t c) {
          auto v = x.vertices(c);
          std::sort(v.begin(), v.end());
          out.insert(v);
        });
        return out;
      };
      if (cells(s) != cells(t) || s.hidden_points().size() != t.hidden_points().size()) {
        throw std::logic_error("parallel insertion differs from one thread");
      }
      if (options.canonical_order) {
        bool same = s.cell_capacity() == t.cell_capacity();
        for (std::uint32_t c = 0; same && c < s.cell_capacity(); ++c) {
          same = s.is_cell(c) && t.is_cell(c) && s.vertices(c) == t.vertices(c);
          for (int i = 0; same && i < 4; ++i) same = s.neighbor(c, i) == t.neighbor(c, i);
        }
        if (!same) throw std::logic_error("canonical cell arrays differ");
      }
      // The last BRIO round (3/4 of the points expected) is large enough for the passes.
      if (options.spatial_sort && n >= 300 && t.stats().parallel_points == 0) {
        throw std::logic_error("the parallel passes did not run");
      }
    }
  } catch (const rstruct::InvalidInput&) {
    // Flat or too small input: the documented outcome.
  }
  return 0;
}
