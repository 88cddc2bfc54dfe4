#pragma once
/// \file
/// An abstract simplicial complex of dimension at most 3 (DESIGN.md §4, §5, §7): the
/// dual complex K of a union of balls, the seed polytope, and every complex whose Z₂
/// homology rstruct computes.
///
/// Vertices are arbitrary uint32 ids; an edge, triangle or tetrahedron is the sorted tuple
/// of its vertex ids. Each dimension is stored as a lexicographically sorted list without
/// duplicates, so a simplex is named by its *index* in that list. The face relation is
/// stored explicitly: face i of a k-simplex is the (k−1)-simplex that omits its i-th vertex
/// (vertices in increasing order), given as an index into the list of dimension k − 1.
/// The complex is always closed under taking faces.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace rstruct::complex {

using VertexId = std::uint32_t;
/// Index of a simplex in the sorted list of its dimension.
using SimplexIndex = std::uint32_t;
using Edge = std::array<VertexId, 2>;
using Triangle = std::array<VertexId, 3>;
using Tetrahedron = std::array<VertexId, 4>;

/// The four simplex lists of a complex, in any order, tuples in any vertex order,
/// duplicates allowed.
struct SimplexLists {
  std::vector<VertexId> vertices;
  std::vector<Edge> edges;
  std::vector<Triangle> triangles;
  std::vector<Tetrahedron> tetrahedra;
};

/// A finite abstract simplicial complex of dimension ≤ 3, closed under faces.
class SimplicialComplex {
 public:
  /// The empty complex (dimension −1).
  SimplicialComplex() = default;

  /// The smallest complex containing every given simplex (the closure under faces).
  /// \throws InvalidInput if a simplex repeats a vertex (names the list and position).
  static SimplicialComplex closure_of(const SimplexLists& simplices);

  /// Convenience: the closure of a list of tetrahedra (resp. triangles, edges).
  static SimplicialComplex closure_of(std::span<const Tetrahedron> tetrahedra);
  static SimplicialComplex closure_of(std::span<const Triangle> triangles);
  static SimplicialComplex closure_of(std::span<const Edge> edges);

  /// A complex given by explicit lists that must already be closed under faces; on
  /// `threads` threads (0: all cores). Faster than closure_of on the same lists.
  /// \throws InvalidInput if a simplex repeats a vertex or a face of a listed simplex is
  /// missing from the lists (names the simplex and the missing face).
  static SimplicialComplex from_closed_lists(const SimplexLists& simplices,
                                             unsigned threads = 1);

  /// The subcomplex made of the simplices whose flag is true (one flag vector per
  /// dimension, sizes equal to size(d)).
  /// \throws InvalidInput if the flag sizes do not match or the kept set is not closed
  /// under faces.
  SimplicialComplex subcomplex(const std::array<std::vector<bool>, 4>& keep) const;

  /// Largest dimension of a simplex, −1 for the empty complex.
  int dimension() const;
  /// Number of simplices of dimension d (0 ≤ d ≤ 3).
  std::size_t size(int d) const;
  /// Total number of simplices.
  std::size_t total_size() const { return size(0) + size(1) + size(2) + size(3); }
  bool empty() const { return vertices_.empty(); }

  const std::vector<VertexId>& vertices() const { return vertices_; }
  const std::vector<Edge>& edges() const { return edges_; }
  const std::vector<Triangle>& triangles() const { return triangles_; }
  const std::vector<Tetrahedron>& tetrahedra() const { return tetrahedra_; }

  /// Faces of a simplex as indices of dimension d − 1; face i omits vertex i.
  const std::array<SimplexIndex, 2>& edge_faces(SimplexIndex e) const { return edge_faces_[e]; }
  const std::array<SimplexIndex, 3>& triangle_faces(SimplexIndex t) const {
    return triangle_faces_[t];
  }
  const std::array<SimplexIndex, 4>& tetrahedron_faces(SimplexIndex t) const {
    return tetrahedron_faces_[t];
  }
  /// Faces (indices in dimension d − 1) of the simplex of dimension d (1 ≤ d ≤ 3) at index i.
  std::span<const SimplexIndex> faces(int d, SimplexIndex i) const;

  /// Index of a simplex given by its vertex ids in any order, if present.
  std::optional<SimplexIndex> find_vertex(VertexId v) const;
  std::optional<SimplexIndex> find(Edge e) const;
  std::optional<SimplexIndex> find(Triangle t) const;
  std::optional<SimplexIndex> find(Tetrahedron t) const;

  /// Euler characteristic Σ (−1)^d · size(d).
  long long euler_characteristic() const;

  /// Checks every invariant: lists sorted and strictly increasing, tuples strictly
  /// increasing, face indices in range and naming exactly the faces they should.
  bool is_valid() const;

 private:
  std::vector<VertexId> vertices_;
  std::vector<Edge> edges_;
  std::vector<Triangle> triangles_;
  std::vector<Tetrahedron> tetrahedra_;
  std::vector<std::array<SimplexIndex, 2>> edge_faces_;
  std::vector<std::array<SimplexIndex, 3>> triangle_faces_;
  std::vector<std::array<SimplexIndex, 4>> tetrahedron_faces_;
};

}  // namespace rstruct::complex
