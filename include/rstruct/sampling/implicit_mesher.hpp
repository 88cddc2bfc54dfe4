#pragma once
/// \file
/// Marching tetrahedra on a regular grid: a closed triangle mesh of the zero set of a
/// Surface's implicit function. Used to sample surfaces without a
/// parametrization uniformly by area and to check the genus of implicit surfaces
/// independently of any sample.
///
/// Each grid cube is split into the six tetrahedra of the Kuhn (Freudenthal) triangulation
/// (all sharing the cube's main diagonal), which match across neighbouring cubes. A node
/// is "inside" iff value < 0 (value = 0 counts as outside), which equals meshing the
/// piecewise-linear interpolant at a regular level just below 0: the output is a closed
/// 2-manifold whose vertices lie on grid edges with one inside and one outside end.
/// Triangles are oriented with normals pointing outside, decided exactly on the grid's
/// combinatorics (edge midpoints), never on interpolated coordinates.

#include <cstddef>

#include "rstruct/geometry/triangle_mesh.hpp"
#include "rstruct/sampling/mesh_topology.hpp"
#include "rstruct/sampling/surface.hpp"

namespace rstruct::sampling {

/// Meshes {value < 0} ∩ (the surface's bounding box grown by two steps) with grid step
/// `step`. Vertices are placed by linear interpolation on grid edges and, if
/// `project_vertices`, moved onto F by Newton steps along the gradient.
/// \throws InvalidInput if step is not finite and > 0 or the grid would exceed 2³¹ nodes.
TriangleMesh mesh_implicit_surface(const Surface& surface, double step, bool project_vertices);

/// Sum of the triangle areas.
double mesh_area(const TriangleMesh& mesh);

}  // namespace rstruct::sampling
