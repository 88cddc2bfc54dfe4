#include "rstruct/complex/triangulation_dual_complex.hpp"

#include <algorithm>
#include <bit>
#include <string>
#include <vector>

#include "rstruct/complex/orthosphere_predicates.hpp"
#include "rstruct/core/assert.hpp"
#include "rstruct/core/parallel.hpp"

namespace rstruct::complex {
namespace {

using triangulation::CellId;
using triangulation::kInfiniteVertex;
using triangulation::RegularTriangulation3;
using triangulation::VertexStars;

constexpr std::size_t kChunk = 2048;

/// A cell of a vertex's star, copied: its vertices, the position of the star's vertex
/// among them, and which of its facets are in K (bit a: the facet opposite vertex a).
struct StarCell {
  std::array<VertexId, 4> v{};
  std::uint8_t facets_in_k = 0;
  std::uint8_t iv = 0;
  std::uint8_t above = 0;  // bit j: v[j] is finite and greater than the star's vertex
};

/// What one worker found: simplices of K and counts of the triangulation.
struct WorkerLists {
  std::vector<Tetrahedron> tetrahedra;
  std::vector<Triangle> triangles;
  std::vector<Edge> edges;
  std::vector<VertexId> vertices;
  std::array<std::size_t, 4> finite{};
  std::array<std::size_t, 4> facet_classes{};
  // Scratch of classify_edges and classify_vertex.
  std::vector<StarCell> star;             // the current vertex's star
  std::vector<std::uint32_t> slot_of;     // vertex id → slot of an edge of the current vertex
  std::vector<std::uint8_t> edge_in_k;    // per slot: 1 in K by a coface, 2 not in K, 0 open
  std::vector<std::size_t> ring_offsets;  // per slot: its ring entries
  std::vector<std::size_t> ring_fill;
  std::vector<VertexId> ring;             // vertices opposite the edges (with repeats)
  std::vector<WeightedPoint> opposite;    // weighted points of one edge's ring
};

class Classifier {
 public:
  Classifier(const RegularTriangulation3& rt, const VertexStars& stars, unsigned threads)
      : rt_(rt), stars_(stars), threads_(threads) {
    const std::size_t cap = rt.cell_capacity();
    workers_ = std::max(thread_count(threads, cap, kChunk),
                        thread_count(threads, rt.number_of_points(), kChunk));
    lists_.resize(workers_);
    cell_in_k_.assign(cap, 0);
    facet_in_k_.assign(4 * cap, 0);
    vertex_has_edge_.assign(rt.number_of_points(), 0);
  }

  TriangulationDualComplex run() {
    const std::size_t cap = rt_.cell_capacity();
    const std::size_t n = rt_.number_of_points();
    parallel_chunks(cap, threads_, kChunk, [&](std::size_t b, std::size_t e, unsigned w) {
      for (std::size_t c = b; c < e; ++c) classify_cell(static_cast<CellId>(c), lists_[w]);
    });
    parallel_chunks(cap, threads_, kChunk, [&](std::size_t b, std::size_t e, unsigned w) {
      classify_facets(b, e, lists_[w]);
    });
    parallel_chunks(n, threads_, kChunk, [&](std::size_t b, std::size_t e, unsigned w) {
      for (std::size_t v = b; v < e; ++v) classify_edges(static_cast<VertexId>(v), lists_[w]);
    });
    for (const WorkerLists& l : lists_) {
      for (const Edge& edge : l.edges) vertex_has_edge_[edge[0]] = vertex_has_edge_[edge[1]] = 1;
    }
    parallel_chunks(n, threads_, kChunk, [&](std::size_t b, std::size_t e, unsigned w) {
      for (std::size_t v = b; v < e; ++v) classify_vertex(static_cast<VertexId>(v), lists_[w]);
    });
    return assemble();
  }

 private:
  WeightedPoint point(VertexId v) const { return rt_.weighted_point(v); }

  bool is_finite_cell(CellId c) const {
    for (int i = 0; i < 4; ++i) {
      if (rt_.vertex(c, i) == kInfiniteVertex) return false;
    }
    return true;
  }

  void classify_cell(CellId c, WorkerLists& out) {
    if (!rt_.is_cell(c) || !is_finite_cell(c)) return;
    const auto v = rt_.vertices(c);
    ++out.finite[3];
    const std::array<WeightedPoint, 4> sigma{point(v[0]), point(v[1]), point(v[2]), point(v[3])};
    if (orthosphere_power_sign(sigma) != Sign::positive) {
      cell_in_k_[c] = 1;
      out.tetrahedra.push_back(v);
    }
  }

  /// The facets of the cells [b, e), each from the cell with the smaller id; the flag is
  /// written on both sides (no other worker writes either byte). The neighbours' data are
  /// read for a block of cells first: neighbours are scattered in memory, and independent
  /// loads let the processor wait for several of them at once.
  void classify_facets(std::size_t b, std::size_t e, WorkerLists& out) {
    constexpr std::size_t kBlock = 16;
    struct Side {
      CellId n = 0;
      int m = 0;
      VertexId opposite = kInfiniteVertex;
      int n_in_k = 0;
    };
    std::array<std::array<Side, 4>, kBlock> sides;
    for (std::size_t start = b; start < e; start += kBlock) {
      const std::size_t end = std::min(e, start + kBlock);
      for (std::size_t c = start; c < end; ++c) {
        if (!rt_.is_cell(static_cast<CellId>(c))) continue;
        for (int i = 0; i < 4; ++i) {
          Side& side = sides[c - start][static_cast<std::size_t>(i)];
          side.n = rt_.neighbor(static_cast<CellId>(c), i);
          if (side.n < c) continue;
          side.m = rt_.mirror_index(static_cast<CellId>(c), i);
          side.opposite = rt_.vertex(side.n, side.m);
          side.n_in_k = cell_in_k_[side.n];
        }
      }
      for (std::size_t c = start; c < end; ++c) {
        if (rt_.is_cell(static_cast<CellId>(c))) {
          classify_facets_of(static_cast<CellId>(c), sides[c - start], out);
        }
      }
    }
  }

  template <class Sides>
  void classify_facets_of(CellId c, const Sides& sides, WorkerLists& out) {
    const auto v = rt_.vertices(c);
    for (int i = 0; i < 4; ++i) {
      const auto& side = sides[static_cast<std::size_t>(i)];
      if (side.n < c) continue;
      Triangle t{};
      bool finite = true;
      for (int j = 0, o = 0; j < 4; ++j) {
        if (j == i) continue;
        t[o++] = v[static_cast<std::size_t>(j)];
        finite = finite && v[static_cast<std::size_t>(j)] != kInfiniteVertex;
      }
      if (!finite) continue;
      ++out.finite[2];
      const int tets_in_k = cell_in_k_[c] + side.n_in_k;
      bool in_k = tets_in_k > 0;
      if (!in_k) {
        const std::array<WeightedPoint, 3> sigma{point(t[0]), point(t[1]), point(t[2])};
        std::array<WeightedPoint, 2> opposite;
        std::size_t count = 0;
        for (const VertexId p : {v[static_cast<std::size_t>(i)], side.opposite}) {
          if (p != kInfiniteVertex) opposite[count++] = point(p);
        }
        in_k = orthosphere_is_unattached_in_union(sigma, {opposite.data(), count});
      }
      if (!in_k) continue;
      facet_in_k_[4 * std::size_t{c} + static_cast<std::size_t>(i)] = 1;
      facet_in_k_[4 * std::size_t{side.n} + static_cast<std::size_t>(side.m)] = 1;
      out.triangles.push_back(t);
      ++out.facet_classes[static_cast<std::size_t>(1 + tets_in_k)];
    }
  }

  /// The edges (v, u) with u > v, in one pass over v's star: each cell c of the star and
  /// each of its vertices u > v give the two facets of c through v and u (cofaces of the
  /// edge) and their third vertices (the vertices p of the attachment test).
  void classify_edges(VertexId v, WorkerLists& out) {
    const auto cells = stars_.cells(v);
    const auto neighbors = stars_.neighbors(v);
    // Slots: the neighbours u > v, in order; slot_of[u] is a per-worker scratch map.
    const auto first = std::upper_bound(neighbors.begin(), neighbors.end(), v);
    const std::size_t slots = static_cast<std::size_t>(neighbors.end() - first);
    if (slots == 0) return;
    std::vector<std::uint32_t>& slot_of = out.slot_of;
    if (slot_of.size() < rt_.number_of_points()) slot_of.assign(rt_.number_of_points(), 0);
    for (std::size_t k = 0; k < slots; ++k) slot_of[first[k]] = static_cast<std::uint32_t>(k);
    // The neighbours' points (edge ends and ring vertices) are needed after the pass over
    // the star; they are scattered in memory.
    for (const VertexId u : neighbors) rt_.prefetch_point(u);
    out.edge_in_k.assign(slots, 0);
    out.ring_offsets.assign(slots + 1, 0);
    // The star's cells and facet flags, read once (independent loads, see
    // classify_facets) into a local copy that both passes use.
    out.star.resize(cells.size());
    for (std::size_t k = 0; k < std::min(cells.size(), kAhead); ++k) prefetch(cells[k]);
    for (std::size_t k = 0; k < cells.size(); ++k) {
      if (k + kAhead < cells.size()) prefetch(cells[k + kAhead]);
      StarCell& local = out.star[k];
      local.v = rt_.vertices(cells[k]);
      const std::uint8_t* flags = &facet_in_k_[4 * std::size_t{cells[k]}];
      local.facets_in_k = static_cast<std::uint8_t>(flags[0] | (flags[1] << 1) |
                                                    (flags[2] << 2) | (flags[3] << 3));
      local.iv = static_cast<std::uint8_t>(local.v[1] == v ? 1
                                           : local.v[2] == v ? 2
                                           : local.v[3] == v ? 3
                                                             : 0);
      unsigned above = 0;
      for (unsigned j = 0; j < 4; ++j) {
        const VertexId u = local.v[j];
        above |= static_cast<unsigned>(u > v && u != kInfiniteVertex) << j;
      }
      local.above = static_cast<std::uint8_t>(above);
    }
    // Pass 1: facet flags decide most edges; count the ring entries of the others. The
    // cofaces of edge (v, u) in a cell are its two facets through v and u: those opposite
    // the two other vertices.
    for (const StarCell& local : out.star) {
      for (unsigned m = local.above; m != 0; m &= m - 1) {
        const int j = std::countr_zero(m);
        const VertexId u = local.v[static_cast<std::size_t>(j)];
        const std::uint32_t slot = slot_of[u];
        const unsigned through = (1u << local.iv) | (1u << j);
        if ((local.facets_in_k & ~through & 0xfu) != 0) out.edge_in_k[slot] = 1;
        out.ring_offsets[slot + 1] += 2;
      }
    }
    for (std::size_t k = 0; k < slots; ++k) out.ring_offsets[k + 1] += out.ring_offsets[k];
    // An edge no coface puts in K whose orthocentre is outside the union (power sign
    // positive) is not in K whatever its ring: decided without the ring (state 2).
    for (std::size_t k = 0; k < slots; ++k) {
      if (out.edge_in_k[k] != 0) continue;
      const std::array<WeightedPoint, 2> sigma{point(v), point(first[k])};
      if (orthosphere_power_sign(sigma) == Sign::positive) out.edge_in_k[k] = 2;
    }
    // Pass 2: the ring vertices of every edge still undecided.
    out.ring.assign(out.ring_offsets[slots], kInfiniteVertex);
    out.ring_fill.assign(out.ring_offsets.begin(), out.ring_offsets.end() - 1);
    for (const StarCell& local : out.star) {
      for (unsigned m = local.above; m != 0; m &= m - 1) {
        const int j = std::countr_zero(m);
        const std::uint32_t slot = slot_of[local.v[static_cast<std::size_t>(j)]];
        if (out.edge_in_k[slot]) continue;
        // The two vertices other than v and u.
        unsigned others = 0xfu & ~((1u << local.iv) | (1u << j));
        const int a = std::countr_zero(others);
        others &= others - 1;
        const int b = std::countr_zero(others);
        out.ring[out.ring_fill[slot]++] = local.v[static_cast<std::size_t>(a)];
        out.ring[out.ring_fill[slot]++] = local.v[static_cast<std::size_t>(b)];
      }
    }
    for (std::size_t k = 0; k < slots; ++k) {
      const VertexId u = first[k];
      ++out.finite[1];
      if (out.edge_in_k[k] == 2) continue;
      bool in_k = out.edge_in_k[k] == 1;
      if (!in_k) {
        auto begin = out.ring.begin() + static_cast<std::ptrdiff_t>(out.ring_offsets[k]);
        auto end = out.ring.begin() + static_cast<std::ptrdiff_t>(out.ring_offsets[k + 1]);
        std::sort(begin, end);
        end = std::unique(begin, end);
        out.opposite.clear();
        for (auto it = begin; it != end; ++it) {
          if (*it != kInfiniteVertex) out.opposite.push_back(point(*it));
        }
        const std::array<WeightedPoint, 2> sigma{point(v), point(u)};
        in_k = orthosphere_is_unattached_in_union(sigma, out.opposite);
      }
      if (in_k) out.edges.push_back({v, u});
    }
  }

  /// Star cells read ahead of use: the stars' cells and their facet flags are scattered.
  static constexpr std::size_t kAhead = 8;
  void prefetch(CellId c) const {
    rt_.prefetch_cell(c);
    __builtin_prefetch(facet_in_k_.data() + 4 * std::size_t{c});
  }

  void classify_vertex(VertexId v, WorkerLists& out) {
    if (!rt_.is_vertex(v)) return;
    ++out.finite[0];
    bool in_k = vertex_has_edge_[v] != 0;
    if (!in_k) {
      out.opposite.clear();
      for (const VertexId u : stars_.neighbors(v)) out.opposite.push_back(point(u));
      const std::array<WeightedPoint, 1> sigma{point(v)};
      in_k = orthosphere_is_unattached_in_union(sigma, out.opposite);
    }
    if (in_k) out.vertices.push_back(v);
  }

  TriangulationDualComplex assemble() {
    TriangulationDualComplex result;
    SimplexLists lists;
    for (WorkerLists& l : lists_) {
      for (int d = 0; d < 4; ++d) result.triangulation_counts[d] += l.finite[d];
      for (int k = 1; k < 4; ++k) result.facet_classes[k] += l.facet_classes[k];
      lists.tetrahedra.insert(lists.tetrahedra.end(), l.tetrahedra.begin(), l.tetrahedra.end());
      lists.triangles.insert(lists.triangles.end(), l.triangles.begin(), l.triangles.end());
      lists.edges.insert(lists.edges.end(), l.edges.begin(), l.edges.end());
      lists.vertices.insert(lists.vertices.end(), l.vertices.begin(), l.vertices.end());
      l = WorkerLists{};  // frees the scratch as well
    }
    result.facet_classes[0] = result.triangulation_counts[2] - lists.triangles.size();
    // K is closed under faces by the top-down rule (a face of a simplex in K is in K).
    try {
      result.complex = SimplicialComplex::from_closed_lists(lists, threads_);
    } catch (const InvalidInput& e) {
      throw InvalidInput(std::string("dual complex: the simplices classified in K are not "
                                     "closed under faces (") + e.what() + ")");
    }
    const std::array<std::size_t, 4> listed = {lists.vertices.size(), lists.edges.size(),
                                               lists.triangles.size(), lists.tetrahedra.size()};
    for (int d = 0; d < 4; ++d) {
      RSTRUCT_ASSERT_MSG(result.complex.size(d) == listed[static_cast<std::size_t>(d)],
                         "dual complex: a simplex of dimension " + std::to_string(d) +
                             " was classified twice");
    }
    return result;
  }

  const RegularTriangulation3& rt_;
  const VertexStars& stars_;
  unsigned threads_;
  unsigned workers_ = 1;
  std::vector<WorkerLists> lists_;
  std::vector<std::uint8_t> cell_in_k_;
  std::vector<std::uint8_t> facet_in_k_;
  std::vector<std::uint8_t> vertex_has_edge_;
};

}  // namespace

TriangulationDualComplex classify_dual_complex(const triangulation::RegularTriangulation3& rt,
                                               const triangulation::VertexStars& stars,
                                               unsigned threads) {
  return Classifier(rt, stars, threads).run();
}

}  // namespace rstruct::complex
