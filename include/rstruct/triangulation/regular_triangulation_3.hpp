#pragma once
/// \file
/// RegularTriangulation3: the regular (weighted Delaunay) triangulation of a set of weighted
/// points in R³, and with all weights zero the Delaunay triangulation.
///
/// Papers implemented:
///  - Bowyer (1981) / Watson (1981) incremental insertion: the cells whose orthosphere the new
///    point is in conflict with form a star-shaped cavity that is re-triangulated from it.
///  - Edelsbrunner & Shah, "Incremental topological flipping works for regular
///    triangulations" (1996): regular triangulations, hidden (redundant) points.
///  - Devillers & Teillaud, "Perturbations for Delaunay and weighted Delaunay 3D
///    triangulations" (CGTA 2011): symbolic perturbation of the weights, so the
///    triangulation is unique for any input, including cospherical and duplicate points.
///  - Amenta, Choi & Rote, "Incremental constructions con BRIO" (2003): biased randomized
///    insertion order, each round sorted along a Hilbert curve.
///  - Devillers, Pion & Teillaud, "Walking in a triangulation" (2002): remembering
///    stochastic walk for point location (terminates on degenerate input).
///
/// Structure: a triangulation of the 3-sphere. An *infinite vertex* (kInfiniteVertex) is
/// joined to every convex-hull facet, so every cell has exactly four neighbours. Cells are
/// 4 vertex ids + 4 neighbour links (32-bit ids) in one compact array; freed cells are
/// recycled. Vertex ids are the indices of the input points, so an input point that is
/// hidden or an exact duplicate simply has no incident cell.
///
/// Orientation: every finite cell (v0, v1, v2, v3) is positively oriented,
/// predicates::orient3d(v0, v1, v2, v3) > 0. In an infinite cell, replacing the infinite
/// vertex by a point beyond its (hull) facet gives a positively oriented tetrahedron.
/// Facet i of a cell is the triangle opposite its vertex i.
///
/// Every combinatorial decision goes through rstruct/predicates (exact, perturbed). The
/// constructions (circumcentre, orthocentre, radii) are plain double arithmetic: measurements
/// for output and later stages, never used to decide anything here.
///
/// Thread-compatibility: after construction every const member function may be called
/// concurrently from several threads (no mutable state, no caches).

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "rstruct/core/huge_page_allocator.hpp"
#include "rstruct/geometry/vec3.hpp"

namespace rstruct::predicates {
class AlmostStaticFilter;
}

namespace rstruct::triangulation {

/// A vertex: the index of its input point.
using VertexId = std::uint32_t;
/// A cell (tetrahedron, possibly infinite).
using CellId = std::uint32_t;

/// The vertex at infinity closing the convex hull.
inline constexpr VertexId kInfiniteVertex = 0xFFFFFFFFu;
/// "No cell" (e.g. incident_cell() of a hidden point).
inline constexpr CellId kNoCell = 0xFFFFFFFFu;
/// Largest number of input points supported (ids kInfiniteVertex − 1 and above are reserved).
inline constexpr std::size_t kMaxPoints = 0xFFFFFFF0u;

/// A facet: the triangle of `cell` opposite its vertex `index` (0..3).
struct Facet {
  CellId cell = kNoCell;
  int index = 0;
  friend bool operator==(const Facet&, const Facet&) = default;
};

/// An edge: the segment between local vertices `i` and `j` (i != j) of `cell`.
struct Edge {
  CellId cell = kNoCell;
  int i = 0;
  int j = 1;
};

/// An input point that is not a vertex because its power cell is empty (Edelsbrunner–Shah:
/// redundant point). `cell` is a cell of the final triangulation containing the point (in
/// its closure) whose orthosphere the point is *not* in conflict with, i.e. the point's
/// power against that orthosphere is positive (after perturbation).
struct HiddenPoint {
  VertexId point = 0;
  CellId cell = kNoCell;
};

/// An input point with exactly the coordinates of the vertex `vertex`: merged into it. The
/// vertex kept is the one with the larger weight; equal weights are decided by the symbolic
/// perturbation (see predicates.hpp), so the choice does not depend on insertion order.
struct DuplicatePoint {
  VertexId point = 0;
  VertexId vertex = 0;
};

/// The dual of a facet in the power diagram: the segment between the orthocentres of its two
/// cells, or, when one cell is infinite, the ray from the finite cell's orthocentre along the
/// outward normal of the hull facet. Double constructions.
struct DualSegment {
  Point3 source;
  Point3 target;      ///< meaningful iff !is_ray
  Vec3 direction;     ///< ray direction (outward hull-facet normal, not normalised) iff is_ray
  bool is_ray = false;
};

/// How the triangulation is built.
struct TriangulationOptions {
  /// BRIO rounds, each sorted along a Hilbert curve. false: insert in input order.
  bool spatial_sort = true;
  /// BRIO's round sizes: the last round takes each point with probability
  /// 1 − 1/brio_divisor, the round before it the same share of the rest, and so on down
  /// to a first round of at most 256 expected points (values below 2 act as 2). Only the
  /// speed depends on it. Points in a volume: 4 (10^6 uniform points, one thread, 16 was
  /// 1 % slower, within the noise). Points on a surface: 16 (see for_surface_points).
  std::uint32_t brio_divisor = 4;
  /// Seed of the BRIO shuffle and of the walk's random choices (the result, being the
  /// unique perturbed regular triangulation, does not depend on it; only the speed does).
  std::uint64_t seed = 0x9E3779B97F4A7C15ull;
  /// Called after each input point has been processed (inserted, hidden or merged) with
  /// the id of that point. Tests use it to call is_valid() after every insertion.
  std::function<void(const class RegularTriangulation3&, VertexId)> after_insertion;
  /// Threads inserting points (0: hardware concurrency; at most 8 are used). With more
  /// than one, every BRIO round of at least `parallel_min_round` points is split along the
  /// Hilbert curve into one stretch per thread; a thread inserts a point only if every cell
  /// it visits has all its vertices in its stretch of the curve (cells it alone can change),
  /// and leaves the others to a sequential pass. Where that defers too many points (points
  /// on a surface, whose long cells cross every border), the later rounds take vertex
  /// locks instead: a thread inserts a point if it can lock every vertex of the cells it
  /// visits (see builder.cpp). The triangulation is the same (it is unique); the cell ids
  /// depend on the number of threads, and after a round with locks on timing too: set
  /// canonical_order for a numbering that does not. Ignored with after_insertion or
  /// without spatial_sort.
  unsigned threads = 1;
  std::size_t parallel_min_round = 10000;
  /// The last `insert_first` input points are inserted before all the others (with
  /// spatial_sort; one by one), and parallel workers share them as they share the infinite
  /// vertex: no worker locks or owns them. For far sites enclosing the others, such as the
  /// pole analysis's bounding-box corners: inserted last, each of them conflicts with the
  /// hundreds of thousands of flat cells along the hull of a large sample (10^6 points on
  /// a torus: 1.7 s for the 8 corners); inserted among the others and locked, they are
  /// vertices of the cells around every point on the hull, and workers with locks keep
  /// deferring each other's points there (double torus: 6 % to 40 % deferred).
  std::size_t insert_first = 0;
  /// How the parallel passes share the work (with threads > 1): `automatic` starts with
  /// fixed borders and turns to locks after a pass that defers a quarter of a large round;
  /// `borders` and `locks` keep to one (tests and benchmarks compare them, and callers
  /// whose points are known to lie on a surface, such as the pipeline's, skip the border
  /// pass that `automatic` would find futile).
  enum class ParallelScheme : std::uint8_t { automatic, borders, locks };
  ParallelScheme parallel_scheme = ParallelScheme::automatic;
  /// With locks, the threads go in pairs: one that is done with its stretch inserts its
  /// partner's remaining points from the far end, and stops this many points before the
  /// partner (two threads that near each other keep each other out; the partner inserts
  /// the gap alone, one core idle meanwhile). Tests set 0. A number of points, not a
  /// share: the gap's extent on a surface, in units of the point spacing, and so the
  /// chance that the two threads' cavities meet, does not depend on the number of points.
  std::size_t parallel_steal_gap = 1024;
  /// Number the cells in the canonical order at the end: by their smallest vertex id, then
  /// by their other vertex ids (within a cell: the two smallest ids first, increasing, then
  /// the order that keeps the orientation). The cell array then depends only on the
  /// triangulation, not on the insertion order, the number of threads or timing. Costs a
  /// counting sort of the cells (85,237 points on a double torus, 1.17·10^6 cells: about
  /// 0.08 s; 10^6 points on a torus, 2·10^7 cells: about 5 s and twice the cells' memory,
  /// most of it first-touch page faults on this VM) and frees the free cells.
  bool canonical_order = false;
  /// The canonical order only where the cell ids would otherwise depend on timing: if a
  /// parallel pass took locks (what `rstruct delaunay` uses, so that its .ele file is the
  /// same on every run without paying for the renumbering where it is not needed).
  bool canonical_order_after_locks = false;

  /// Options for points sampled on a surface, as the pipeline's triangulations (the pole
  /// analysis's Delaunay, the surface balls' regular triangulation), on `threads` threads:
  /// - vertex locks from the first parallel pass: the automatic scheme's first pass with
  ///   fixed borders would defer about half of its round before turning to locks (see
  ///   builder.cpp). Double torus (bench_seed, 5 pairs, steal gap 256 in both): Delaunay
  ///   0.425 / 0.358 / 0.354 / 0.377 / 0.373 -> 0.324 / 0.319 / 0.324 / 0.360 / 0.355 s
  ///   (that round alone, rstruct delaunay, 4 pairs: 0.091 / 0.059 / 0.064 / 0.063 ->
  ///   0.049 / 0.042 / 0.046 / 0.051 s); level 1's regular triangulation 0.400 / 0.366 /
  ///   0.381 / 0.410 / 0.402 -> 0.351 / 0.374 / 0.373 / 0.391 / 0.411 s;
  /// - BRIO rounds of 1/16 instead of 1/4 (a last round of 15/16 of the points along the
  ///   curve: shorter walks, the cavities about as large). 10^6-sample torus (bench_seed
  ///   --torus 1000000, 4 interleaved pairs): Delaunay 6.34 / 6.09 / 6.09 / 6.38 -> 5.34 /
  ///   5.65 / 5.89 / 5.76 s; 5 more interleaved rounds, medians: 1/4 5.96, 1/8 5.69, 1/16
  ///   5.58, 1/32 5.80 s. Double torus (5 pairs, medians): Delaunay 0.288 -> 0.282 s,
  ///   level 1's regular triangulation 0.311 -> 0.293 s.
  static TriangulationOptions for_surface_points(unsigned threads) {
    TriangulationOptions o;
    o.threads = threads;
    o.parallel_scheme = ParallelScheme::locks;
    o.brio_divisor = 16;
    return o;
  }
};

/// Counts and seconds of the construction.
struct TriangulationStats {
  double sort_seconds = 0;
  double insertion_seconds = 0;
  std::uint64_t walk_steps = 0;          ///< cells visited by point location
  std::uint64_t conflict_cells = 0;      ///< cells destroyed by insertions (total)
  std::uint64_t orient_calls = 0;        ///< orient3d calls of the walk
  std::uint64_t power_test_calls = 0;    ///< insphere / power tests of the conflict search
  /// Those of them on finite cells that the almost-static filter's two floating-point
  /// stages left undecided (the dynamic filter, the exact stage and the perturbation then
  /// decide): the filter's failures, counted in every build (the predicate counters of
  /// -Dcounters=true also tell which later stage decided).
  std::uint64_t filter_misses = 0;
  std::uint64_t large_cavities = 0;      ///< cavities with more than 127 boundary vertices (hashed linking)
  unsigned threads = 1;                  ///< threads that inserted points
  std::uint64_t parallel_points = 0;     ///< points processed by the parallel passes
  std::uint64_t deferred_points = 0;     ///< points the parallel passes left to the sequential one
  std::uint64_t taken_points = 0;        ///< points a thread took from its partner's stretch
  std::uint64_t border_passes = 0;       ///< parallel passes with fixed borders
  std::uint64_t lock_passes = 0;         ///< parallel passes with vertex locks
  std::uint64_t exhausted_workers = 0;   ///< workers of a pass that ran out of room for new cells
};

/// The result of is_valid(): ok, or the first violated property in words.
struct ValidityReport {
  bool ok = true;
  std::string message;
  explicit operator bool() const { return ok; }
};

/// The vertex quadruples of a triangulation's finite cells, stored in the memory of its
/// cell array (RegularTriangulation3::take_finite_cells): for callers that need only the
/// tetrahedra, without a second array of their size (10^6 points on a torus: 330 MB that
/// would be allocated and written for the first time).
class CellQuadruples {
 public:
  CellQuadruples();
  CellQuadruples(CellQuadruples&&) noexcept;
  CellQuadruples& operator=(CellQuadruples&&) noexcept;
  ~CellQuadruples();

  std::size_t size() const { return size_; }
  std::span<std::array<VertexId, 4>> quadruples() { return {data_, size_}; }
  std::span<const std::array<VertexId, 4>> quadruples() const { return {data_, size_}; }

 private:
  friend class RegularTriangulation3;
  struct Storage;  // the cell array
  std::unique_ptr<Storage> storage_;
  std::array<VertexId, 4>* data_ = nullptr;
  std::size_t size_ = 0;
};

/// What RegularTriangulation3::delaunay_cells gives: a Delaunay triangulation's finite
/// cells and reports, without the triangulation.
struct DelaunayCells {
  /// The finite cells' vertex ids (input ids), each quadruple sorted increasingly (so no
  /// longer oriented), in increasing cell id.
  CellQuadruples cells;
  /// As RegularTriangulation3::duplicate_points(). (A Delaunay triangulation hides no
  /// point: every input point is a vertex or a duplicate.)
  std::vector<DuplicatePoint> duplicates;
  TriangulationStats stats;
};

/// Regular triangulation of weighted points in R³ (Delaunay when unweighted).
class RegularTriangulation3 {
 public:
  /// Delaunay triangulation of `points` (all weights zero; in-sphere fast path).
  /// \throws InvalidInput if a coordinate is not finite, if there are more than kMaxPoints
  ///   points, or if the points do not span R³ (fewer than 4 affinely independent points,
  ///   or all coplanar), or if more than 2^30 cells would be needed (neighbour links are
  ///   32-bit: about 1.5·10^8 uniform points); the message names the case.
  explicit RegularTriangulation3(std::vector<Point3> points,
                                 const TriangulationOptions& options = {});

  /// Regular triangulation of the weighted points (points[i], weights[i]); a ball B(c, r) is
  /// the weighted point (c, r²). Weights may be negative.
  /// \throws InvalidInput as above, or if the sizes differ or a weight is not finite.
  RegularTriangulation3(std::vector<Point3> points, std::vector<double> weights,
                        const TriangulationOptions& options = {});

  RegularTriangulation3(RegularTriangulation3&&) noexcept;
  RegularTriangulation3& operator=(RegularTriangulation3&&) noexcept;
  RegularTriangulation3(const RegularTriangulation3&) = default;
  RegularTriangulation3& operator=(const RegularTriangulation3&) = default;
  ~RegularTriangulation3();

  // ---- input -------------------------------------------------------------------------

  /// Number of input points (vertices, hidden and duplicates).
  std::size_t number_of_points() const { return points_.size(); }
  /// True iff built from weighted points (even if all weights happen to be zero).
  bool is_weighted() const { return !weights_.empty(); }
  /// The input point of id `v`. \pre v < number_of_points().
  const Point3& point(VertexId v) const { return points_[v]; }
  /// The weight of input point `v` (0 when unweighted).
  double weight(VertexId v) const { return weights_.empty() ? 0.0 : weights_[v]; }
  WeightedPoint weighted_point(VertexId v) const { return {points_[v], weight(v)}; }
  std::span<const Point3> points() const { return points_; }

  // ---- sizes -------------------------------------------------------------------------

  /// Finite vertices (input points that are vertices).
  std::size_t number_of_vertices() const { return number_of_vertices_; }
  /// Live cells, finite and infinite.
  std::size_t number_of_cells() const { return cells_.size() - free_count_; }
  /// Live finite cells.
  std::size_t number_of_finite_cells() const { return number_of_cells() - infinite_count_; }
  /// One past the largest cell id in use: CellId values below this may be live or free.
  std::size_t cell_capacity() const { return cells_.size(); }

  // ---- combinatorics -------------------------------------------------------------------

  /// True iff `c` is a live cell id. O(1).
  bool is_cell(CellId c) const { return c < cells_.size() && cells_[c].v[0] != kFreeMark; }
  /// True iff input point v is a vertex (not hidden, not merged).
  bool is_vertex(VertexId v) const { return v < vertex_cell_.size() && vertex_cell_[v] != kNoCell; }
  static bool is_infinite_vertex(VertexId v) { return v == kInfiniteVertex; }
  bool is_infinite(CellId c) const;
  bool is_infinite(const Facet& f) const;
  bool is_infinite(const Edge& e) const;

  /// Starts loading cell c into the cache (a hint; any id is allowed). Loops that read
  /// the cells of a list (a star) at random call it some iterations ahead.
  void prefetch_cell(CellId c) const { __builtin_prefetch(cells_.data() + c); }
  /// Starts loading the point (and weight) of input point v. \pre v < number_of_points().
  void prefetch_point(VertexId v) const {
    __builtin_prefetch(points_.data() + v);
    if (!weights_.empty()) __builtin_prefetch(weights_.data() + v);
  }
  /// Vertex i (0..3) of cell c. \pre is_cell(c).
  VertexId vertex(CellId c, int i) const { return cells_[c].v[i]; }
  std::array<VertexId, 4> vertices(CellId c) const {
    const Cell& k = cells_[c];
    return {k.v[0], k.v[1], k.v[2], k.v[3]};
  }
  /// The neighbour of c across its facet i.
  CellId neighbor(CellId c, int i) const { return cells_[c].n[i] >> 2; }
  /// The index of c's facet i in neighbor(c, i): neighbor(neighbor(c,i), mirror_index(c,i)) == c.
  int mirror_index(CellId c, int i) const { return static_cast<int>(cells_[c].n[i] & 3u); }
  /// The same facet seen from the other cell.
  Facet mirror_facet(const Facet& f) const {
    return {neighbor(f.cell, f.index), mirror_index(f.cell, f.index)};
  }
  /// Local index of vertex v in cell c, or −1.
  int index(CellId c, VertexId v) const;
  /// The three vertices of facet f, ordered so that (vertex opposite f, a, b, c) keeps the
  /// orientation of the cell, i.e. for a finite facet of a finite cell the triangle is
  /// counter-clockwise seen from outside the cell.
  std::array<VertexId, 3> facet_vertices(const Facet& f) const;

  /// Some cell incident to vertex v, or kNoCell if v is not a vertex.
  CellId incident_cell(VertexId v) const { return is_vertex(v) ? vertex_cell_[v] : kNoCell; }
  /// All cells (finite and infinite) incident to vertex v. \pre is_vertex(v).
  std::vector<CellId> incident_cells(VertexId v) const;
  /// Appends to `out` (cleared first); reuse the vector to avoid allocations.
  void incident_cells(VertexId v, std::vector<CellId>& out) const;
  /// The finite vertices adjacent to v by an edge (plus nothing for the infinite vertex).
  std::vector<VertexId> adjacent_vertices(VertexId v) const;
  /// True iff v lies on the convex hull (its power/Voronoi cell is unbounded).
  bool is_on_convex_hull(VertexId v) const;
  /// The cells around edge e, in cyclic order, starting with e.cell.
  std::vector<CellId> cells_around_edge(const Edge& e) const;

  /// Calls f(CellId) for every live finite cell, in increasing id order.
  template <class F>
  void for_each_finite_cell(F&& f) const {
    for (CellId c = 0; c < cells_.size(); ++c) {
      const Cell& k = cells_[c];
      if (k.v[0] == kFreeMark || k.v[0] == kInfiniteVertex || k.v[1] == kInfiniteVertex ||
          k.v[2] == kInfiniteVertex || k.v[3] == kInfiniteVertex) {
        continue;
      }
      f(c);
    }
  }
  /// Calls f(CellId) for every live cell, finite or infinite.
  template <class F>
  void for_each_cell(F&& f) const {
    for (CellId c = 0; c < cells_.size(); ++c) {
      if (cells_[c].v[0] != kFreeMark) f(c);
    }
  }
  /// The live finite cells, in increasing id order.
  std::vector<CellId> finite_cells() const;
  /// Convex-hull facets as facets of finite cells (facet.index opposite the interior vertex);
  /// facet_vertices() of each is counter-clockwise seen from outside the hull.
  std::vector<Facet> convex_hull_facets() const;

  // ---- constructions (double arithmetic: measurements, not decisions) -------------------

  /// Circumcentre of finite cell c (centre of the sphere through its vertices' points,
  /// ignoring weights), a rounded double: double arithmetic relative to the cell's first
  /// vertex for well-shaped cells, exact rationals rounded once for slivers and nearly flat
  /// cells (|det| < 2⁻²⁶ of the edge-length product). \pre c finite.
  Point3 circumcenter(CellId c) const;
  /// Squared circumradius of finite cell c (double).
  double squared_circumradius(CellId c) const;
  /// Orthocentre of finite cell c: the centre of the sphere orthogonal to its four weighted
  /// vertices (the power-diagram vertex dual to c). Equals circumcenter() when unweighted.
  /// A rounded double, computed as circumcenter(). \pre c finite.
  Point3 orthocenter(CellId c) const;
  /// Squared radius of the orthosphere (its weight; may be negative). Double arithmetic.
  double squared_orthoradius(CellId c) const;

  // ---- power diagram ---------------------------------------------------------------------

  /// The finite cells incident to v: their orthocentres are the vertices of v's power cell
  /// (Voronoi cell when unweighted). The cell is unbounded iff is_on_convex_hull(v).
  /// \pre is_vertex(v).
  std::vector<CellId> power_cell_vertices(VertexId v) const;
  /// The dual power edge of a facet (segment or ray), see DualSegment.
  DualSegment dual(const Facet& f) const;
  /// The dual power face of an edge: the cells around the edge in cyclic order (each finite
  /// one contributes its orthocentre; an infinite one means the face is unbounded).
  std::vector<CellId> dual(const Edge& e) const { return cells_around_edge(e); }

  // ---- point queries ---------------------------------------------------------------------

  /// A cell whose closure contains q (an infinite cell if q is outside the hull or on it),
  /// found by a walk from `hint` (any live cell; kNoCell: a default start). Exact.
  CellId locate(const Point3& q, CellId hint = kNoCell) const;
  /// The vertex v minimising the power distance |q − p_v|² − w_v (Euclidean distance when
  /// unweighted), i.e. whose power cell contains q. Ties are broken arbitrarily. Exact.
  VertexId nearest_power_vertex(const Point3& q, CellId hint = kNoCell) const;

  // ---- reports ---------------------------------------------------------------------------

  std::span<const HiddenPoint> hidden_points() const { return hidden_; }
  std::span<const DuplicatePoint> duplicate_points() const { return duplicates_; }
  const TriangulationStats& stats() const { return stats_; }

  /// Full check, geometry with exact predicates only: neighbour symmetry and mirror indices,
  /// exactly one infinite vertex per infinite cell, Euler characteristic of the 3-sphere
  /// (V − E + F − C = 0), every finite cell positively oriented, every facet locally regular
  /// (perturbed power test), every processed input point a vertex, hidden (positive power
  /// against the orthosphere of a cell containing it) or merged (same coordinates as its
  /// vertex, and not in conflict with it). Cost O(cells · degree).
  ValidityReport is_valid() const;

  // ---- giving up the cells ---------------------------------------------------------------

  /// The vertices of every finite cell, in increasing cell id, as the cells store them
  /// (positively oriented), written over the cell array, which the result takes; the
  /// triangulation keeps its points and reports but has no cells left (only its points,
  /// weights, hidden and duplicate reports and stats may be used after). On `threads`
  /// threads (0: hardware concurrency); the result does not depend on their number.
  CellQuadruples take_finite_cells(unsigned threads = 1);

  /// The Delaunay triangulation of `points` (\throws as the constructor), given up at
  /// once: the same cells, duplicates and statistics as constructing it and calling
  /// take_finite_cells(options.threads) (on options.threads threads), with each quadruple
  /// then sorted. For callers that need only the tetrahedra (the pole analysis): the cells
  /// are renamed from the insertion order to input ids as they are compacted, and neither
  /// the renaming pass over every cell, the points' permutation back to input order nor
  /// the vertex index (one more pass, on one thread) is made. 10^6 torus samples (the pole
  /// analysis's), from the last insertion to the sorted quadruples: two threads 0.21-0.23
  /// -> 0.08-0.09 s, one thread 0.27-0.38 -> 0.14-0.16 s. With options.after_insertion or
  /// a canonical order, the triangulation is constructed and given up as above.
  static DelaunayCells delaunay_cells(std::vector<Point3> points,
                                      const TriangulationOptions& options = {});

 private:
  struct Cell {
    VertexId v[4];
    std::uint32_t n[4];  // neighbour id << 2 | mirror index
  };
  static constexpr VertexId kFreeMark = 0xFFFFFFFEu;

  friend class Builder;
  friend class CellQuadruples;

  /// Construction for delaunay_cells: the builder stops before renaming the cells to
  /// input ids and indexing the vertices (see Builder::run).
  struct CellsOnly {};
  RegularTriangulation3(std::vector<Point3> points, const TriangulationOptions& options,
                        CellsOnly);
  /// take_finite_cells, each quadruple's ids renamed through `rename` (if not null: the
  /// insertion order, rank → input id) and then, with `sort_each`, sorted increasingly.
  CellQuadruples take_finite_cells(unsigned threads, const VertexId* rename, bool sort_each);

  /// Index (0..3) of the infinite vertex in c, or −1.
  int infinite_index(CellId c) const {
    const Cell& k = cells_[c];
    for (int i = 0; i < 4; ++i) {
      if (k.v[i] == kInfiniteVertex) return i;
    }
    return -1;
  }
  /// Sign of orient3d of cell c with its vertex i replaced by q (the other three finite).
  /// With `filter` (a box holding q and every point), its orient3d_two_stage is used.
  int orient_replaced(CellId c, int i, const Point3& q,
                      const predicates::AlmostStaticFilter* filter = nullptr) const;
  /// Walk from `start` (a live cell) to a cell whose closure contains q; an infinite cell
  /// iff q is strictly outside the hull. It follows the segment from the start cell's
  /// centroid to q where it can, and otherwise takes the facets in a random order (`rng`
  /// is the caller's state); every move is decided by exact orientations.
  CellId walk(const Point3& q, CellId start, std::uint64_t& rng, std::uint64_t& steps,
              std::uint64_t& orients,
              const predicates::AlmostStaticFilter* filter = nullptr) const;
  /// The facet of finite cell c, other than the one shared with `previous`, that the line
  /// through o with direction (wx, wy, wz) crosses, or −1 (floating point: a preference).
  int segment_exit_facet(CellId c, const Point3& o, double wx, double wy, double wz,
                         CellId previous) const;
  /// Some live cell, for walks without a usable hint.
  CellId any_cell() const;
  /// Rebuilds vertex_cell_, the counts and the hidden/duplicate reports from the cells and
  /// the raw hidden records (point, hint cell).
  void finalize(std::span<const HiddenPoint> raw_hidden);
  /// The hidden/duplicate reports alone, in the ids the cells and points use.
  void resolve_hidden(std::span<const HiddenPoint> raw_hidden);

  std::vector<Point3> points_;
  std::vector<double> weights_;
  /// Huge pages: the cells are hundreds of MiB, filled in order and read at random.
  std::vector<Cell, HugePageAllocator<Cell>> cells_;
  std::vector<CellId> vertex_cell_;   // per input point: an incident cell or kNoCell
  std::vector<HiddenPoint> hidden_;
  std::vector<DuplicatePoint> duplicates_;
  std::vector<VertexId> order_;       // insertion order (only during construction)
  std::size_t processed_ = 0;         // points of order_ processed so far
  CellId free_head_ = kNoCell;        // free list through Cell::n[0]
  std::size_t free_count_ = 0;
  std::size_t infinite_count_ = 0;
  std::size_t number_of_vertices_ = 0;
  TriangulationStats stats_;
};

}  // namespace rstruct::triangulation
