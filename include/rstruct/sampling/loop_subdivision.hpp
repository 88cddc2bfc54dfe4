#pragma once
/// \file
/// Loop subdivision of a closed triangle mesh: a smooth surface near a polyhedral model.
///
/// Why: a polyhedral surface has local feature size 0 on every edge whose dihedral angle is
/// not flat (the medial axis reaches the edge), so no finite sample of it is an r-sample,
/// and dense samples of a coarse mesh give tiny pole distances D̂ along its edges. Each
/// Loop step quarters the triangles and roughly halves the dihedral turning angle at the
/// edges; the limit surface is C² away from extraordinary vertices (C¹ at them). Sampling
/// a mesh subdivided 3–4 times gives samples whose D̂ follows the model's shape, not its
/// facets (measured in bench/bench_models.cpp). Subdivision keeps the topology (genus,
/// components); it moves vertices (the limit surface lies inside convex parts), so the
/// subdivided model is an approximation of the input, not the same surface.
///
/// Rules (Loop 1987, with Warren's vertex weight kept as Loop's original):
///   new vertex of an edge ab with opposite vertices c, d:  3/8 (a + b) + 1/8 (c + d)
///   updated vertex v of valence n with neighbours p_i:     (1 − nβ) v + β Σ p_i,
///     β = (5/8 − (3/8 + cos(2π/n)/4)²) / n.
/// Output vertices: the n input vertices (updated) first, then one per edge; each triangle
/// (a, b, c) becomes (a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca), orientation kept.

#include "rstruct/geometry/triangle_mesh.hpp"

namespace rstruct::sampling {

/// `levels` Loop steps of `mesh` (0: a copy of the vertices and faces). Vertex properties
/// are dropped.
/// \throws InvalidInput if a face refers to a missing vertex or repeats a vertex, a
/// vertex is not finite, an edge does not lie in exactly two faces (the mesh must be a
/// closed edge-manifold), or the result would exceed 2³¹ faces.
TriangleMesh loop_subdivide(const TriangleMesh& mesh, unsigned levels);

}  // namespace rstruct::sampling
