#pragma once
/// \file
/// VertexStars: for every vertex of a RegularTriangulation3, the cells incident to it (its
/// star, finite and infinite cells) and its finite neighbours, built once in two compact
/// arrays (compressed rows). The dual-complex classification, the sample map's downhill
/// walks and anything else that asks "what is around v" many times read these instead of
/// walking the cell graph each time (RegularTriangulation3::incident_cells).
///
/// Thread-compatibility: immutable after construction; every const member function may be
/// called concurrently.

#include <cstddef>
#include <span>
#include <vector>

#include "rstruct/core/huge_page_allocator.hpp"
#include "rstruct/triangulation/regular_triangulation_3.hpp"

namespace rstruct::triangulation {

class VertexStars {
 public:
  /// Stars and neighbour lists of every vertex of `rt` (`threads` 0: hardware concurrency).
  /// Input points that are not vertices (hidden, merged) get empty lists. The stars are
  /// filled by one thread per `cells_per_thread` cells at the most (each thread reads all
  /// cells; see vertex_stars.cpp); the result does not depend on it.
  explicit VertexStars(const RegularTriangulation3& rt, unsigned threads = 0,
                       std::size_t cells_per_thread = std::size_t{4} << 20);

  /// Number of input points of the triangulation (the valid arguments of the queries).
  std::size_t size() const { return cell_offsets_.size() - 1; }
  /// The live cells incident to v (finite and infinite), in increasing id order.
  std::span<const CellId> cells(VertexId v) const {
    return {cells_.data() + cell_offsets_[v], cells_.data() + cell_offsets_[v + 1]};
  }
  /// The finite vertices joined to v by an edge, in increasing order.
  std::span<const VertexId> neighbors(VertexId v) const {
    return {neighbors_.data() + neighbor_offsets_[v],
            neighbors_.data() + neighbor_offsets_[v + 1]};
  }
  /// Total number of finite edges (each counted once).
  std::size_t number_of_finite_edges() const { return neighbors_.size() / 2; }

 private:
  std::vector<std::size_t> cell_offsets_;
  /// Huge pages, and not zeroed on resize (every entry is written by the parallel fill).
  std::vector<CellId, HugePageAllocator<CellId>> cells_;
  std::vector<std::size_t> neighbor_offsets_;
  std::vector<VertexId> neighbors_;
};

}  // namespace rstruct::triangulation
