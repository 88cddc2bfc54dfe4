#pragma once
/// \file
/// The medial axis of a finite union of balls U (Amenta & Kolluri, "The medial axis of a
/// union of balls", CGTA 20 (2001); DESIGN.md §6; paper §3 "Medial axis approximation").
///
/// Algorithm:
///  1. Regular triangulation of the balls plus four far points of weight 0 (so any number of
///     balls, coplanar centres included, spans R³), and its dual complex K at α = 0. Balls
///     inside another ball (exact rational test on the pairs of K's edges) are dropped.
///  2. The boundary vertices V of ∂U, tagged with their ball ids (boundary_vertices.hpp).
///  3. Delaunay triangulation of V plus four far points. A Voronoi vertex (Delaunay cell)
///     is medial iff its Voronoi ball lies in U. We accept it when its centre lies in U and
///     in the normal cone of each of its four sites a, cone(a) = a + cone(c_i − a, c_j − a,
///     c_k − a) for a's balls i, j, k (both necessary: a nearest boundary point a forces the
///     centre into cone(a); not proven sufficient, but the Betti checks on random unions
///     found no case where they differ).
///     A Voronoi vertex whose four sites share a ball is that ball's centre (inner); cells
///     whose five points are exactly cospherical share one Voronoi vertex.
///  4. The Voronoi face F(a, b) of a Delaunay edge ab of V is cut by the faces of cone(a)
///     that contain an axis c_i c_j lying in F(a, b), i.e. for the pairs {i, j} of balls a
///     and b share ("cut at ball centres": two such cuts meet at a centre); the cut face is
///     kept iff its remaining Voronoi vertices are medial.
///  5. Plus what V does not produce: the segment c_i c_j of every singular edge of K and the
///     centre of every singular vertex.
/// The medial axis is homotopy equivalent to U, hence to K (checked by the tests on random
/// unions of up to 200 balls).
///
/// Elements are identified combinatorially, never by comparing coordinates: a Voronoi
/// vertex by its (merged) Delaunay cell or by the ball whose centre it is; a point where a
/// Voronoi edge is cut by the Delaunay triangle and the centres of the cutting plane; two
/// cutting planes through the same shared centre meet at that centre.
///
/// Decisions: the regular triangulation, K and the facet classes use the exact predicates;
/// which points of V a facet gives, the cone and side-of-plane tests use exact orient3d,
/// point-in-union exact power tests and cospherical merging exact insphere, all on double
/// points. Constructions (documented approximations): the points of V, the circumcentres
/// and the cut points are rounded doubles; the Delaunay triangulation of V is the exact one
/// of those rounded points (perturbed where they are cospherical).
///
/// Four or more spheres through one boundary point (e.g. equal balls on a grid) give one
/// point of V per facet of K around it. When these round to the same doubles (the exact
/// grids of the tests) they are one Delaunay vertex on all those spheres and the axis is
/// right. Known limitation: nearly degenerate inputs (such a grid perturbed by 2⁻⁴⁵) have
/// points of V closer together than the rounding of their constructions; the Delaunay
/// structure of the rounded points is then not the true one and the axis may miss or gain
/// small cycles or cavities (test "[.degenerate]").

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "rstruct/complex/homology.hpp"
#include "rstruct/complex/simplicial_complex.hpp"
#include "rstruct/geometry/vec3.hpp"

namespace rstruct::medial {

/// Where a medial-axis vertex comes from.
enum class MedialVertexKind : std::uint8_t {
  voronoi_vertex,  ///< circumcentre of a Delaunay tetrahedron of V (inside U)
  ball_centre,     ///< the centre of an input ball
  cut,             ///< where a Voronoi edge or face of V is cut by a face of a normal cone
};

/// A polyhedral complex with a radius per vertex.
struct MedialAxis {
  std::vector<Point3> vertices;
  std::vector<double> radius;          ///< distance to ∂U (ball radius at a centre)
  std::vector<MedialVertexKind> kind;
  std::vector<std::uint32_t> source;   ///< ball id for ball_centre, else unspecified
  /// Edges not on any face (segments of singular edges of K, degenerate cut faces).
  std::vector<std::array<std::uint32_t, 2>> edges;
  /// Convex polygons (vertex cycles, ≥ 3 distinct vertices).
  std::vector<std::vector<std::uint32_t>> faces;
  /// Vertices on no edge and no face (centres of isolated balls).
  std::vector<std::uint32_t> isolated_vertices;

  /// Every edge: polygon sides and the free edges, each once, (i < j), sorted.
  std::vector<std::array<std::uint32_t, 2>> all_edges() const;
  /// The polygons fan-triangulated from their first vertex.
  std::vector<std::array<std::uint32_t, 3>> triangles() const;
  /// The simplicial complex of vertices, all edges and the triangles (for homology).
  complex::SimplicialComplex simplicial_complex() const;
  /// Index bounds, no repeated vertex in a polygon or an edge, finite coordinates and radii.
  bool is_valid(std::string* problem = nullptr) const;
};

/// Counts of a run.
struct MedialAxisStats {
  std::size_t balls = 0;
  std::size_t hidden_balls = 0;           ///< hidden (no power cell) or inside another ball
  std::array<std::size_t, 4> k_counts{};  ///< simplices of K by dimension (far points out)
  complex::BettiNumbers betti_k;          ///< of K, equal to those of U
  std::size_t boundary_vertices = 0;      ///< |V|
  std::size_t delaunay_cells = 0;         ///< finite cells of Del(V ∪ far points)
  std::size_t singular_edges = 0;
  std::size_t singular_vertices = 0;
  double triangulation_seconds = 0;       ///< regular triangulation + K
  double voronoi_seconds = 0;             ///< V, its Delaunay triangulation and the clipping
};

/// The medial axis of the union of `balls`.
/// \throws InvalidInput if a centre or radius is not finite or a radius is not positive.
/// An empty input gives an empty axis.
MedialAxis medial_axis_of_union(std::span<const Ball> balls, MedialAxisStats* stats = nullptr);

/// Betti numbers of the dual complex K of the balls (without the far points): the homotopy
/// type the medial axis must have.
complex::BettiNumbers union_betti_numbers(std::span<const Ball> balls);

}  // namespace rstruct::medial
