#include "rstruct/complex/triangulation_dual_complex.hpp"

#include <algorithm>
#include <bit>
#include <span>
#include <string>
#include <vector>

#include "rstruct/complex/disjoint_balls.hpp"
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

/// Bit of the vertex pair (i, j), i ≠ j, of a cell in a mask of its six pairs.
constexpr std::uint8_t kPairBit[4][4] = {
    {0, 1 << 0, 1 << 1, 1 << 2}, {1 << 0, 0, 1 << 3, 1 << 4},
    {1 << 1, 1 << 3, 0, 1 << 5}, {1 << 2, 1 << 4, 1 << 5, 0}};
/// The pairs of the facet opposite vertex i (those not involving i).
constexpr std::uint8_t kFacetPairs[4] = {
    (1 << 3) | (1 << 4) | (1 << 5), (1 << 1) | (1 << 2) | (1 << 5),
    (1 << 0) | (1 << 2) | (1 << 4), (1 << 0) | (1 << 1) | (1 << 3)};

/// A cell of a vertex's star, copied: its vertices, the position of the star's vertex
/// among them, and which of its facets are in K (bit a: the facet opposite vertex a).
struct StarCell {
  std::array<VertexId, 4> v{};
  std::uint8_t facets_in_k = 0;
  std::uint8_t iv = 0;
  std::uint8_t above = 0;  // bit j: v[j] is finite and greater than the star's vertex
  std::uint8_t disjoint = 0;  // the cell's pairs of certainly disjoint balls (kPairBit)
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
  std::vector<WeightedPoint> opposite;    // weighted points of one vertex's neighbours
  std::vector<VertexId> seen;             // vertex id → v + 1 once listed as v's neighbour
  std::vector<VertexId> found;            // the current vertex's higher neighbours (deferred)
};

/// The neighbour lists the edge pass builds for deferred VertexStars: per chunk of
/// kChunk vertices, their lists of higher neighbours (u > v, sorted) one after the other
/// and each one's length. The lower ones are the transpose (install_neighbors).
struct NeighborChunk {
  std::vector<VertexId> lists;
  std::vector<std::uint32_t> counts;
};

class Classifier {
 public:
  Classifier(const RegularTriangulation3& rt, VertexStars& stars, unsigned threads)
      : rt_(rt), stars_(stars), threads_(threads) {
    const std::size_t cap = rt.cell_capacity();
    workers_ = std::max(thread_count(threads, cap, kChunk),
                        thread_count(threads, rt.number_of_points(), kChunk));
    lists_.resize(workers_);
    cell_in_k_.assign(cap, 0);
    cell_disjoint_.assign(cap, 0);
    radius_.resize(rt.number_of_points());
    facet_in_k_.assign(4 * cap, 0);
    vertex_has_edge_.assign(rt.number_of_points(), 0);
  }

  TriangulationDualComplex run() {
    const std::size_t cap = rt_.cell_capacity();
    const std::size_t n = rt_.number_of_points();
    parallel_chunks(n, threads_, kChunk, [&](std::size_t b, std::size_t e, unsigned) {
      for (std::size_t v = b; v < e; ++v) {
        radius_[v] = radius_upper_bound(rt_.weight(static_cast<VertexId>(v)));
      }
    });
    parallel_chunks(cap, threads_, kChunk, [&](std::size_t b, std::size_t e, unsigned w) {
      for (std::size_t c = b; c < e; ++c) classify_cell(static_cast<CellId>(c), lists_[w]);
    });
    parallel_chunks(cap, threads_, kChunk, [&](std::size_t b, std::size_t e, unsigned w) {
      classify_facets(b, e, lists_[w]);
    });
    if (!stars_.has_neighbors()) neighbor_chunks_.resize((n + kChunk - 1) / kChunk);
    parallel_chunks(n, threads_, kChunk, [&](std::size_t b, std::size_t e, unsigned w) {
      NeighborChunk* chunk = neighbor_chunks_.empty() ? nullptr : &neighbor_chunks_[b / kChunk];
      for (std::size_t v = b; v < e; ++v) {
        classify_edges(static_cast<VertexId>(v), lists_[w], chunk);
      }
    });
    if (!neighbor_chunks_.empty()) install_neighbors();
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
    // A pair of disjoint balls decides the cell (not in K) and, through the masks, the
    // facets and edges of the pair (see disjoint_balls.hpp). Double torus level 1: 1.5 of
    // 6.9 million orthosphere predicates saved, dual complex about 5 % less CPU (4
    // interleaved pairs, 0.75-1.07 -> 0.75-0.98 s).
    unsigned disjoint = 0;
    for (int i = 0; i < 4; ++i) {
      for (int j = i + 1; j < 4; ++j) {
        if (balls_certainly_disjoint(sigma[i].c, radius_[v[i]], sigma[j].c, radius_[v[j]])) {
          disjoint |= kPairBit[i][j];
        }
      }
    }
    cell_disjoint_[c] = static_cast<std::uint8_t>(disjoint);
    if (disjoint == 0 && orthosphere_power_sign(sigma) != Sign::positive) {
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
      if (!in_k && (cell_disjoint_[c] & kFacetPairs[i]) != 0) continue;  // not in K
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
  /// edge) and their third vertices (the vertices p of the attachment test). With
  /// `chunk` (deferred neighbour lists), v's higher neighbours are listed from the star's
  /// copy and appended to the chunk: the stars are read once instead of twice (double
  /// torus level 1, 6 interleaved pairs: vertex stars + dual complex, median CPU
  /// 1.17 -> 1.03 s; the stars alone 0.27-0.36 -> 0.08-0.11 s).
  void classify_edges(VertexId v, WorkerLists& out, NeighborChunk* chunk) {
    const auto cells = stars_.cells(v);
    // v's neighbours: with built lists all of them, and a vertex with no higher neighbour
    // has nothing to do; with deferred ones only the higher, listed below (the star is read
    // to find whether there are any).
    std::span<const VertexId> neighbors;
    if (chunk == nullptr) {
      neighbors = stars_.neighbors(v);
      if (neighbors.empty() || neighbors.back() < v) return;
    }
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
      local.disjoint = cell_disjoint_[cells[k]];
    }
    if (chunk != nullptr) {
      const std::size_t n = rt_.number_of_points();
      if (out.seen.size() < n) out.seen.assign(n, 0);
      out.found.clear();
      const VertexId mark = v + 1;
      for (const StarCell& local : out.star) {
        for (unsigned m = local.above; m != 0; m &= m - 1) {
          const VertexId u = local.v[static_cast<std::size_t>(std::countr_zero(m))];
          if (out.seen[u] != mark) {
            out.seen[u] = mark;
            out.found.push_back(u);
          }
        }
      }
      std::sort(out.found.begin(), out.found.end());
      chunk->lists.insert(chunk->lists.end(), out.found.begin(), out.found.end());
      chunk->counts.push_back(static_cast<std::uint32_t>(out.found.size()));
      neighbors = out.found;
    }
    // Slots: the neighbours u > v, in order; slot_of[u] is a per-worker scratch map.
    const auto first = std::upper_bound(neighbors.begin(), neighbors.end(), v);
    const std::size_t slots = static_cast<std::size_t>(neighbors.end() - first);
    if (slots == 0) return;
    std::vector<std::uint32_t>& slot_of = out.slot_of;
    if (slot_of.size() < rt_.number_of_points()) slot_of.assign(rt_.number_of_points(), 0);
    for (std::size_t k = 0; k < slots; ++k) slot_of[first[k]] = static_cast<std::uint32_t>(k);
    // The higher neighbours' points (the edges' other ends) are needed by the tests below;
    // they are scattered in memory.
    for (auto it = first; it != neighbors.end(); ++it) rt_.prefetch_point(*it);
    out.edge_in_k.assign(slots, 0);
    // Pass 1: facet flags and disjoint balls decide most edges. The
    // cofaces of edge (v, u) in a cell are its two facets through v and u: those opposite
    // the two other vertices.
    for (const StarCell& local : out.star) {
      for (unsigned m = local.above; m != 0; m &= m - 1) {
        const int j = std::countr_zero(m);
        const VertexId u = local.v[static_cast<std::size_t>(j)];
        const std::uint32_t slot = slot_of[u];
        const unsigned through = (1u << local.iv) | (1u << j);
        if ((local.disjoint & kPairBit[local.iv][j]) != 0) {
          RSTRUCT_DEBUG_ASSERT(out.edge_in_k[slot] != 1);  // disjoint balls: not in K
          out.edge_in_k[slot] = 2;
        } else if ((local.facets_in_k & ~through & 0xfu) != 0) {
          RSTRUCT_DEBUG_ASSERT(out.edge_in_k[slot] != 2);
          out.edge_in_k[slot] = 1;
        }
      }
    }
    // An edge no coface puts in K whose orthocentre is outside the union (power sign
    // positive) is not in K whatever its ring: decided without the ring (state 2).
    for (std::size_t k = 0; k < slots; ++k) {
      if (out.edge_in_k[k] != 0) continue;
      const std::array<WeightedPoint, 2> sigma{point(v), point(first[k])};
      if (orthosphere_power_sign(sigma) == Sign::positive) out.edge_in_k[k] = 2;
    }
    // Pass 2: every edge still undecided has its orthocentre in the union (power sign not
    // positive); it is in K iff no vertex of its ring (the vertices opposite it in its
    // star's cells) attaches it. The ring is tested in the star's order, each edge
    // dropping out at its first attaching vertex (a vertex met twice gives the same sign).
    // On the double torus's level 1 all 655,000 such edges are attached; gathering, sorting
    // and deduplicating each ring first (10.8 entries per edge) cost more than the tests
    // it saved: dual complex 1.21-1.23 -> 0.85-0.97 s CPU (3 interleaved pairs).
    for (const StarCell& local : out.star) {
      for (unsigned m = local.above; m != 0; m &= m - 1) {
        const int j = std::countr_zero(m);
        const VertexId u = local.v[static_cast<std::size_t>(j)];
        const std::uint32_t slot = slot_of[u];
        if (out.edge_in_k[slot]) continue;
        const std::array<WeightedPoint, 2> sigma{point(v), point(u)};
        // The two vertices other than v and u.
        for (unsigned others = 0xfu & ~((1u << local.iv) | (1u << j)); others != 0;
             others &= others - 1) {
          const VertexId x = local.v[static_cast<std::size_t>(std::countr_zero(others))];
          if (x != kInfiniteVertex && orthosphere_attachment_sign(sigma, point(x)) == Sign::negative) {
            out.edge_in_k[slot] = 2;
            break;
          }
        }
      }
    }
    for (std::size_t k = 0; k < slots; ++k) {
      ++out.finite[1];
      if (out.edge_in_k[k] != 2) out.edges.push_back({v, first[k]});
    }
  }

  /// Star cells read ahead of use: the stars' cells and their facet flags are scattered.
  static constexpr std::size_t kAhead = 8;
  void prefetch(CellId c) const {
    rt_.prefetch_cell(c);
    __builtin_prefetch(facet_in_k_.data() + 4 * std::size_t{c});
    __builtin_prefetch(cell_disjoint_.data() + c);
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

  /// The full neighbour lists from the higher ones of neighbor_chunks_, installed in the
  /// stars: v's list is its lower neighbours (the u < v listing v), then its higher ones.
  /// Going through the u in increasing order writes every lower list sorted.
  void install_neighbors() {
    const std::size_t n = rt_.number_of_points();
    std::vector<std::size_t> offsets(n + 1, 0);
    {
      std::size_t u = 0;
      for (const NeighborChunk& c : neighbor_chunks_) {
        const VertexId* higher = c.lists.data();
        for (const std::uint32_t count : c.counts) {
          offsets[u + 1] += count;
          for (std::uint32_t k = 0; k < count; ++k) ++offsets[higher[k] + 1];
          higher += count;
          ++u;
        }
      }
      RSTRUCT_ASSERT(u == n);
    }
    for (std::size_t v = 0; v < n; ++v) offsets[v + 1] += offsets[v];
    std::vector<VertexId> lists(offsets[n]);
    std::vector<std::size_t> fill(offsets.begin(), offsets.end() - 1);
    std::size_t u = 0;
    for (NeighborChunk& c : neighbor_chunks_) {
      const VertexId* higher = c.lists.data();
      for (const std::uint32_t count : c.counts) {
        for (std::uint32_t k = 0; k < count; ++k) lists[fill[higher[k]]++] = static_cast<VertexId>(u);
        higher += count;
        ++u;
      }
    }
    u = 0;
    for (NeighborChunk& c : neighbor_chunks_) {
      const VertexId* higher = c.lists.data();
      for (const std::uint32_t count : c.counts) {
        std::copy(higher, higher + count, lists.begin() + static_cast<std::ptrdiff_t>(fill[u]));
        higher += count;
        ++u;
      }
      c = NeighborChunk{};
    }
    stars_.set_neighbors(rt_, std::move(offsets), std::move(lists));
  }

  const RegularTriangulation3& rt_;
  VertexStars& stars_;
  unsigned threads_;
  unsigned workers_ = 1;
  std::vector<WorkerLists> lists_;
  std::vector<std::uint8_t> cell_in_k_;
  std::vector<std::uint8_t> cell_disjoint_;  // per cell: its pairs of disjoint balls
  std::vector<double> radius_;               // per vertex: radius_upper_bound of its weight
  std::vector<std::uint8_t> facet_in_k_;
  std::vector<std::uint8_t> vertex_has_edge_;
  std::vector<NeighborChunk> neighbor_chunks_;  // deferred neighbour lists, per chunk
};

}  // namespace

TriangulationDualComplex classify_dual_complex(const triangulation::RegularTriangulation3& rt,
                                               triangulation::VertexStars& stars,
                                               unsigned threads) {
  return Classifier(rt, stars, threads).run();
}

}  // namespace rstruct::complex
