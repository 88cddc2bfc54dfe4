#pragma once
/// \file
/// The vertices V of the boundary of a union of balls (Amenta & Kolluri, "The medial axis of
/// a union of balls", CGTA 20 (2001); DESIGN.md §6), read off its dual complex K
/// (Edelsbrunner 1995): each singular facet (i, j, k) of K gives both points of
/// S_i ∩ S_j ∩ S_k, each regular facet the one of them on the side away from its
/// tetrahedron of K. Every point is tagged with its three ball ids; the points are never
/// identified by their coordinates.
///
/// Constructions (documented approximations): the points are rounded doubles (the foot of
/// the common power line in the centres' plane, plus ± the height). Which facets give
/// points, and which of the two points a regular facet gives, are decided by the exact
/// predicates of the dual complex and by orient3d on the input centres.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "rstruct/complex/dual_complex.hpp"
#include "rstruct/geometry/vec3.hpp"

namespace rstruct::triangulation {
class RegularTriangulation3;
}

namespace rstruct::medial {

/// A vertex of ∂U: a point on the three spheres `balls` (increasing ids).
struct BoundaryVertex {
  Point3 point;
  std::array<std::uint32_t, 3> balls{};
  /// Index of its twin (the other point of the same singular facet), or kNoTwin.
  std::uint32_t twin = 0xffffffffu;
  /// Which of the two points of the three spheres it is: +1 on the side of the centres'
  /// plane where orient3d(c_i, c_j, c_k, ·) > 0 (i < j < k the balls), −1 on the other.
  /// With the balls it names the exact point, of which `point` is the rounding.
  int side = 0;
};

inline constexpr std::uint32_t kNoTwin = 0xffffffffu;

/// True iff the two tags share ball `ball`.
bool has_ball(const BoundaryVertex& v, std::uint32_t ball);

/// The boundary vertices of the union of `balls` from its regular triangulation `rt`
/// (built from the balls' weighted points, possibly with extra far points of larger ids,
/// which are ignored) and its dual complex `k`.
/// \pre k == complex::dual_complex(rt), balls.size() ≤ rt.number_of_points().
std::vector<BoundaryVertex> boundary_vertices(std::span<const Ball> balls,
                                              const triangulation::RegularTriangulation3& rt,
                                              const complex::DualComplex& k);

/// The same, building the regular triangulation (with four far points) and K itself.
/// \throws InvalidInput if a centre or radius is not finite or a radius is not positive.
std::vector<BoundaryVertex> boundary_vertices_of_union(std::span<const Ball> balls);

}  // namespace rstruct::medial
