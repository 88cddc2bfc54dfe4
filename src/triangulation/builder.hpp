#pragma once
// The incremental construction of a RegularTriangulation3 (Bowyer–Watson with the perturbed
// power test). Private to src/triangulation.

#include <cstdint>
#include <vector>

#include "rstruct/triangulation/regular_triangulation_3.hpp"

namespace rstruct::triangulation {

class Builder {
 public:
  Builder(RegularTriangulation3& t, const TriangulationOptions& options);
  /// Sorts, builds the first tetrahedron, inserts every other point, finalizes.
  /// \throws InvalidInput when the points do not span R³.
  void run();

 private:
  using Cell = RegularTriangulation3::Cell;
  struct BoundaryFacet {
    CellId cell;  // conflict cell
    int index;    // its facet on the cavity boundary
  };
  enum Mark : std::uint8_t { kNone = 0, kConflict = 1, kOutside = 2, kNew = 3 };

  void choose_first_tetrahedron();
  void make_first_cells(const VertexId (&v)[4]);
  void insert(VertexId p);
  bool in_conflict(CellId c, VertexId p);
  void find_conflict_region(CellId start, VertexId p);
  void build_star(VertexId p);
  void link_star_face(std::size_t s, int j);
  void collect_hidden_vertices(VertexId p, VertexId duplicate_of);
  void release_conflict_region();
  CellId new_cell();
  void after_insertion(VertexId p);

  RegularTriangulation3& t_;
  const TriangulationOptions& options_;
  const Point3* points_;
  const double* weights_;  // nullptr: Delaunay fast path
  std::vector<std::uint8_t> mark_;         // per cell, Mark
  std::vector<std::uint8_t> vertex_mark_;  // per point (weighted only)
  std::vector<CellId> conflict_;
  std::vector<CellId> stack_;
  std::vector<CellId> outside_;
  std::vector<BoundaryFacet> boundary_;
  std::vector<CellId> star_;                // new cell of boundary_[k]
  std::vector<VertexId> cavity_vertices_;
  std::vector<HiddenPoint> raw_hidden_;
  CellId last_ = 0;
  std::uint64_t rng_;
};

}  // namespace rstruct::triangulation
