#pragma once
/// \file
/// Combinatorial checks of a triangle mesh (DESIGN.md §7): Euler characteristic, closed
/// 2-manifold (every edge in two triangles, every vertex link one cycle), components.

#include <cstddef>

#include "rstruct/geometry/triangle_mesh.hpp"

namespace rstruct::sampling {

/// Combinatorial summary of a triangle mesh.
struct MeshTopology {
  std::size_t vertices = 0;  ///< vertices used by at least one triangle
  std::size_t edges = 0;
  std::size_t faces = 0;
  long long euler_characteristic = 0;  ///< V − E + F
  std::size_t components = 0;          ///< connected components of the used vertices
  bool every_edge_in_two_faces = false;
  bool every_vertex_link_a_cycle = false;
  bool is_closed_manifold() const { return every_edge_in_two_faces && every_vertex_link_a_cycle; }
  /// Genus of a closed orientable connected surface: 1 − χ/2 (meaningful only then).
  long long genus() const { return 1 - euler_characteristic / 2; }
};

/// Computes the summary. \throws InvalidInput if a face refers to a missing vertex.
MeshTopology mesh_topology(const TriangleMesh& mesh);

}  // namespace rstruct::sampling
