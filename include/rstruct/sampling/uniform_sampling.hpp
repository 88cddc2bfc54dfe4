#pragma once
/// \file
/// N points distributed uniformly by area, deterministic for a seed.
///  - Parametrized surfaces: exact, by rejection in parameter space — a chart is chosen
///    with probability ∝ (parameter area × max_area_element), a parameter point uniformly,
///    accepted with probability area_element / max_area_element.
///  - Other surfaces (double torus): a marching-tetrahedra mesh (implicit_mesher.hpp) with
///    its vertices on F; a triangle is chosen ∝ its area, a point uniformly in it, then
///    projected onto F along the gradient. The density is uniform up to the area distortion
///    of that projection, a relative O((hκ)²) with h the grid step and κ the curvature
///    (≈ 0.3 % at the default step h = a_min / 12).
///  - Triangle meshes: a triangle ∝ its area, then uniform barycentric coordinates.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "rstruct/geometry/triangle_mesh.hpp"
#include "rstruct/sampling/surface.hpp"

namespace rstruct::sampling {

/// `count` points uniform by area on `surface`. `mesh_step` (> 0) overrides the grid step
/// used for surfaces without a parametrization (default: Surface::meshing_step()).
/// \throws InvalidInput for count > 1e9 or a bad mesh_step.
std::vector<Point3> sample_uniform(const Surface& surface, std::size_t count, std::uint64_t seed,
                                   double mesh_step = 0.0);

/// `count` points uniform by area on the triangles of `mesh`. Degenerate (zero-area)
/// triangles are never chosen.
/// \throws InvalidInput if the mesh has no face of positive area, a face refers to a
/// missing vertex, a vertex is not finite, or count > 1e9.
std::vector<Point3> sample_mesh_uniform(const TriangleMesh& mesh, std::size_t count,
                                        std::uint64_t seed);

/// `count` points on the triangles of `mesh` with density ∝ `density[f]` (per unit area) on
/// face f: a face is chosen with probability ∝ area × density, then a point uniformly in it.
/// \throws InvalidInput as sample_mesh_uniform, or if `density` does not have one finite
/// value ≥ 0 per face, or all faces get weight 0.
std::vector<Point3> sample_mesh_weighted(const TriangleMesh& mesh,
                                         std::span<const double> density, std::size_t count,
                                         std::uint64_t seed);

}  // namespace rstruct::sampling
