#pragma once
// What dual_complex.cpp and alpha_filtration.cpp share: their input taken from a regular
// triangulation (its weighted points and finite cells), the check that a cell list names
// only existing points, and two helpers on sorted vertex tuples.

#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "rstruct/complex/simplicial_complex.hpp"
#include "rstruct/core/error.hpp"
#include "rstruct/geometry/vec3.hpp"
#include "rstruct/triangulation/regular_triangulation_3.hpp"

namespace rstruct::complex::detail {

struct BallCells {
  std::vector<WeightedPoint> points;  ///< every input point with its weight, by index
  std::vector<Tetrahedron> cells;     ///< the finite cells
};

inline BallCells ball_cells(const triangulation::RegularTriangulation3& t) {
  BallCells out;
  out.points.resize(t.number_of_points());
  for (std::size_t v = 0; v < out.points.size(); ++v) {
    out.points[v] = t.weighted_point(static_cast<triangulation::VertexId>(v));
  }
  out.cells.reserve(t.number_of_finite_cells());
  t.for_each_finite_cell([&](triangulation::CellId c) { out.cells.push_back(t.vertices(c)); });
  return out;
}

/// \throws InvalidInput naming `who`, the cell and the point if a cell names a point
/// index ≥ `points`.
inline void require_points_exist(std::span<const Tetrahedron> cells, std::size_t points,
                                 const char* who) {
  for (std::size_t c = 0; c < cells.size(); ++c) {
    for (const VertexId v : cells[c]) {
      if (v >= points) {
        throw InvalidInput(std::string(who) + ": cell #" + std::to_string(c) +
                           " names point " + std::to_string(v) + " but there are " +
                           std::to_string(points) + " points");
      }
    }
  }
}

/// The vertex of `coface` (sorted tuple) that is not in `face` (sorted, one shorter).
template <std::size_t K>
VertexId opposite_vertex(const std::array<VertexId, K + 1>& coface,
                         const std::array<VertexId, K>& face) {
  for (std::size_t i = 0; i < K; ++i) {
    if (coface[i] != face[i]) return coface[i];
  }
  return coface[K];
}

/// The weighted points of the simplex `s`.
template <std::size_t K>
std::array<WeightedPoint, K> weighted_simplex(std::span<const WeightedPoint> points,
                                              const std::array<VertexId, K>& s) {
  std::array<WeightedPoint, K> w;
  for (std::size_t i = 0; i < K; ++i) w[i] = points[s[i]];
  return w;
}

}  // namespace rstruct::complex::detail
