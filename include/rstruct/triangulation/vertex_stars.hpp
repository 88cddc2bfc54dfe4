#pragma once
/// \file
/// VertexStars: for every vertex of a RegularTriangulation3, the cells incident to it (its
/// star, finite and infinite cells) and its finite neighbours, built once in two compact
/// arrays (compressed rows). The dual-complex classification, the sample map's downhill
/// walks and anything else that asks "what is around v" many times read these instead of
/// walking the cell graph each time (RegularTriangulation3::incident_cells).
///
/// The neighbour lists may be deferred: a pass that reads every star anyway (the dual
/// complex's edge pass) then computes them on the way and installs them (set_neighbors),
/// which saves a second pass of scattered reads over the stars.
///
/// Thread-compatibility: immutable after construction (and set_neighbors); every const
/// member function may be called concurrently.

#include <cstddef>
#include <span>
#include <vector>

#include "rstruct/core/huge_page_allocator.hpp"
#include "rstruct/triangulation/regular_triangulation_3.hpp"

namespace rstruct::triangulation {

class VertexStars {
 public:
  /// Whether the constructor builds the neighbour lists or leaves them to set_neighbors.
  enum class Neighbors { build, deferred };
  /// The default of the constructor's cells_per_thread (see vertex_stars.cpp).
  static constexpr std::size_t kCellsPerThread = std::size_t{4} << 20;

  /// Stars and neighbour lists of every vertex of `rt` (`threads` 0: hardware concurrency).
  /// Input points that are not vertices (hidden, merged) get empty lists. The stars are
  /// filled by one thread per `cells_per_thread` cells at the most (each thread reads all
  /// cells; see vertex_stars.cpp); the result does not depend on it.
  explicit VertexStars(const RegularTriangulation3& rt, unsigned threads = 0,
                       std::size_t cells_per_thread = kCellsPerThread,
                       Neighbors neighbors = Neighbors::build);

  /// Whether the neighbour lists are there (built, or installed by set_neighbors).
  bool has_neighbors() const { return !neighbor_offsets_.empty(); }
  /// Installs the neighbour lists of a deferred VertexStars: vertex v's list is
  /// lists[offsets[v] .. offsets[v + 1]), sorted, without repeats.
  /// \pre they are the lists the constructor would have built from `rt` (checked in builds
  ///   with expensive checks); offsets has size() + 1 entries.
  void set_neighbors(const RegularTriangulation3& rt, std::vector<std::size_t> offsets,
                     std::vector<VertexId> lists);

  /// Number of input points of the triangulation (the valid arguments of the queries).
  std::size_t size() const { return cell_offsets_.size() - 1; }
  /// The live cells incident to v (finite and infinite), in increasing id order.
  std::span<const CellId> cells(VertexId v) const {
    return {cells_.data() + cell_offsets_[v], cells_.data() + cell_offsets_[v + 1]};
  }
  /// The finite vertices joined to v by an edge, in increasing order.
  /// \pre has_neighbors().
  std::span<const VertexId> neighbors(VertexId v) const {
    return {neighbors_.data() + neighbor_offsets_[v],
            neighbors_.data() + neighbor_offsets_[v + 1]};
  }
  /// Total number of finite edges (each counted once).
  std::size_t number_of_finite_edges() const { return neighbors_.size() / 2; }

 private:
  void build_neighbors(const RegularTriangulation3& rt, unsigned threads);

  std::vector<std::size_t> cell_offsets_;
  /// Huge pages, and not zeroed on resize (every entry is written by the parallel fill).
  std::vector<CellId, HugePageAllocator<CellId>> cells_;
  std::vector<std::size_t> neighbor_offsets_;
  std::vector<VertexId> neighbors_;
};

}  // namespace rstruct::triangulation
