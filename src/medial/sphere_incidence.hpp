#pragma once
// Which spheres pass through each boundary vertex, and which boundary vertices are the same
// point, decided exactly on the input balls.
//
// A boundary vertex is constructed from three spheres and rounded. In degenerate unions
// (balls on a grid, cospherical or cocircular centres) four or more spheres pass through
// one point, which then comes from several facets of K with different roundings, or lies
// on a sphere its three tags do not name. The medial axis classifies Voronoi elements by
// the balls their sites share, so it needs every sphere through each vertex, and one site
// per point: both are decided here on the exact points (GMP rationals and one square root,
// handled by squaring), never by comparing rounded coordinates.

#include <gmpxx.h>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "rstruct/geometry/vec3.hpp"
#include "rstruct/medial/boundary_vertices.hpp"

namespace rstruct::triangulation {
class RegularTriangulation3;
}

namespace rstruct::medial {

/// The exact point of a boundary vertex: o + side·√h·n, o = c_i + z the point of the
/// centres' plane with equal power to the three balls, n = (c_j − c_i) × (c_k − c_i),
/// h = (r_i² − |z|²) / |n|² (the construction of boundary_vertices, in rationals).
struct ExactVertex {
  std::array<mpq_class, 3> o;
  std::array<mpq_class, 3> n;
  mpq_class h;
  int side = 0;
};

ExactVertex exact_vertex(const BoundaryVertex& v, std::span<const Ball> balls);

/// True iff the exact point of `v` (the point `v.side` of its three spheres) lies on the
/// sphere of `m`. Exact.
bool lies_on_sphere(const BoundaryVertex& v, std::span<const Ball> balls, const Ball& m);

/// The distinct points of V with every sphere through them.
struct DistinctVertices {
  std::vector<BoundaryVertex> vertex;          ///< one per exact point (its first rounding)
  std::vector<std::vector<std::uint32_t>> on;  ///< every ball whose sphere passes through it
};

/// Completes the sphere incidences of `bv` and merges the vertices that are one exact point.
/// Candidate spheres are the balls joined to a vertex's balls in `rt` (the regular
/// triangulation of `balls`, ids 0..n−1), searched breadth first through the balls found to
/// pass through the point: the balls whose spheres meet at a point of ∂U have zero power
/// there, the minimum, so they span a connected piece of rt. A double prefilter with a
/// generous tolerance (10⁻⁹ of the squared distances) skips the candidates that are far from
/// the point; every incidence is then decided exactly.
DistinctVertices distinct_vertices(std::span<const BoundaryVertex> bv, std::span<const Ball> balls,
                                   const triangulation::RegularTriangulation3& rt);

}  // namespace rstruct::medial
