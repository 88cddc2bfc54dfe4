#pragma once
// The incremental construction of a RegularTriangulation3 (Bowyer–Watson with the perturbed
// power test). Private to src/triangulation.

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "rstruct/predicates/almost_static_filter.hpp"
#include "rstruct/triangulation/regular_triangulation_3.hpp"

namespace rstruct::triangulation {

/// A growable array of trivially copyable values that can append without a branch:
/// push_if(v, keep) writes v past the end and moves the end only when keep holds, so that
/// a sign that is hard to predict (is this cell in conflict?) costs no jump. make_room(k)
/// guarantees room for k such writes. The storage only grows; clear() keeps it.
template <class T>
class ScratchList {
 public:
  void clear() { size_ = 0; }
  std::size_t size() const { return size_; }
  T& operator[](std::size_t i) { return data_[i]; }
  const T& operator[](std::size_t i) const { return data_[i]; }
  T* begin() { return data_.data(); }
  T* end() { return data_.data() + size_; }
  const T* begin() const { return data_.data(); }
  const T* end() const { return data_.data() + size_; }
  void make_room(std::size_t k) {
    if (size_ + k > data_.size()) [[unlikely]] data_.resize(std::max(2 * data_.size(), size_ + k));
  }
  void push_back(const T& v) {
    make_room(1);
    data_[size_++] = v;
  }
  /// \pre make_room left room for this write.
  void push_if(const T& v, bool keep) {
    data_[size_] = v;
    size_ += static_cast<std::size_t>(keep);
  }

 private:
  std::vector<T> data_;
  std::size_t size_ = 0;
};

class Builder {
 public:
  /// How run() ends: with a triangulation ready for queries (input ids, vertex index,
  /// reports), or, for RegularTriangulation3::delaunay_cells, with the cells and reports
  /// still in ranks when the points were reordered (t.order_ kept: rank → input id; empty
  /// when the ids are input ids) and no vertex index.
  enum class Finish : std::uint8_t { queries, cells_only };
  Builder(RegularTriangulation3& t, const TriangulationOptions& options,
          Finish finish = Finish::queries);
  /// A helper thread's builder for the parallel passes of `main`: its own search state,
  /// marks, free list and statistics over main's triangulation.
  Builder(const Builder& main, std::uint8_t worker);
  /// Sorts, builds the first tetrahedron, inserts every other point, finalizes.
  /// \throws InvalidInput when the points do not span R³.
  void run();

 private:
  using Cell = RegularTriangulation3::Cell;
  struct BoundaryFacet {
    CellId cell;  // conflict cell
    int index;    // its facet on the cavity boundary
  };
  enum Mark : std::uint8_t { kNone = 0, kConflict = 1, kOutside = 2 };

  bool choose_first_tetrahedron();
  void permute_to_insertion_order();
  void reserve_for_projection(std::size_t k, std::size_t n, double margin);
  void restore_input_order();
  /// restore_input_order's permutation of the points (and weights): rank r to order_[r].
  void permute_points_to_input_order();
  /// Vertex id of the k-th point inserted.
  VertexId vertex_at(std::size_t k) const {
    return reorder_ ? static_cast<VertexId>(k) : t_.order_[k];
  }
  /// Input id (the perturbation's index) of vertex v.
  std::uint32_t input_id(VertexId v) const { return reorder_ ? t_.order_[v] : v; }
  void make_first_cells(const VertexId (&v)[4]);
  void insert(VertexId p);
  /// Inserts ranks [begin, end) sequentially (reserving as the construction grows).
  void insert_sequentially(std::size_t begin, std::size_t end, std::size_t n);
  /// Inserts the BRIO round of ranks [begin, end) with the helpers (parallel passes).
  void insert_round_in_parallel(std::size_t begin, std::size_t end);
  /// Parallel pass of one worker: inserts p if everything it touches is owned by this
  /// worker; false (nothing changed) otherwise.
  bool insert_owned(VertexId p);
  /// One parallel pass over lists[w] for worker w, `inserted` points being in already;
  /// returns the deferred points, sorted.
  std::vector<VertexId> parallel_pass(const std::array<std::vector<VertexId>, 8>& lists,
                                      std::size_t inserted, bool locking);
  /// Renumbers the live cells in the canonical order (see TriangulationOptions) and drops
  /// the free ones; the hidden records' hint cells follow.
  void canonicalize_cells();
  /// The worker's points list[from..] as it claims them, then (with a partner) some of the
  /// partner's from the back; those it cannot insert are appended to deferred_.
  void run_worker(const std::vector<VertexId>& list, std::size_t from, CellId start);
  /// In a pass with locks the workers go in pairs (2s, 2s + 1), each inserting its own
  /// stretch from the front; one that is done inserts its partner's remaining points from
  /// the back, towards the partner (see parallel_pass). A stretch's points are claimed
  /// kClaimBlock at a time, from either end.
  struct Claim {
    std::atomic<std::uint64_t> taken{0};  // points claimed from the front (low 32 bits)
                                          // and from the back (high 32 bits)
    std::size_t size = 0;                 // the stretch's points
  };
  static constexpr std::size_t kClaimBlock = 64;
  /// Claims the next block of `claim` from the front or (a partner's stretch) the back;
  /// `end` (this worker's count from that end so far) moves past it. False when every
  /// point is claimed, or from the back, when at most `gap` are left
  /// (TriangulationOptions::parallel_steal_gap).
  static bool claim_more(Claim& claim, bool back, std::size_t gap, std::size_t& end);
  /// Drops the pointers to a pass's claims (which live in parallel_pass).
  void forget_claims() {
    own_claim_ = nullptr;
    partner_claim_ = nullptr;
    partner_list_ = nullptr;
  }
  /// Walk through owned cells only (see walk()); `blocked` when the next cell is not owned.
  CellId walk_owned(const Point3& q, CellId start, bool& blocked);
  /// With locks: keeps only the locks of cell c, which becomes the start of the next walk.
  void keep_cell_locks(CellId c);
  /// The shared vertices (the infinite one and TriangulationOptions::insert_first's) count
  /// as every worker's; the passes keep out of cells where that would let two workers in
  /// (see facet_is_shared and insert_round_in_parallel). In a pass with locks, a vertex is
  /// the worker's once it holds its lock: owned() then tries to take it.
  bool owned(VertexId v) {
    if (is_shared(v)) return true;
    if (!locking_) return owner_[v] == worker_;
    return lock(v);
  }
  /// The infinite vertex, or one of the points inserted first (ranks below shared_end_).
  bool is_shared(VertexId v) const { return v < shared_end_ || v == kInfiniteVertex; }
  /// Whether the facet of cell c opposite its vertex i has only shared vertices: no
  /// worker may look across it in a parallel pass (nothing would keep another out of the
  /// cell beyond).
  bool facet_is_shared(const Cell& c, int i) const {
    bool all = true;
    for (int j = 0; j < 4; ++j) all = all && (j == i || is_shared(c.v[j]));
    return all;
  }
  /// Whether all four vertices of cell c are shared: no worker can hold it alone.
  bool cell_is_shared(const Cell& c) const {
    return is_shared(c.v[0]) && facet_is_shared(c, 0);
  }
  /// Takes the lock of vertex v for this worker (or finds it held by this worker already);
  /// false if another worker holds it. Never waits.
  bool lock(VertexId v) {
    std::atomic_ref<std::uint8_t> slot(owner_[v]);
    const auto me = static_cast<std::uint8_t>(worker_ + 1);
    std::uint8_t seen = slot.load(std::memory_order_relaxed);
    if (seen == me) return true;
    if (seen != 0 || !slot.compare_exchange_strong(seen, me, std::memory_order_acquire,
                                                   std::memory_order_relaxed)) {
      return false;
    }
    locked_.push_back(v);
    return true;
  }
  /// Releases the locks taken since the last kept star (an abandoned insertion).
  void unlock_attempt();
  /// Releases every lock of this worker (end of a pass).
  void unlock_all();
  /// A pass with locks: worker w's first point whose cell it can lock, from lists[w][..64].
  void choose_locked_start(const std::vector<VertexId>& list, std::size_t& from, CellId& hint);
  /// Clears the marks of an abandoned conflict search.
  void clear_conflict_marks();
  /// A cell in conflict with p (`conflict`), or else the cell containing p, which hides it.
  /// With `blocked` (a parallel pass) the walk stays in the worker's cells and sets it when
  /// it cannot.
  CellId locate_conflict(VertexId p, bool& conflict, bool* blocked);
  /// p is hidden, found in cell c.
  void record_hidden(VertexId p, CellId c);
  /// The finite cell of star_ whose centroid is nearest to q (fallback if none).
  CellId nearest_star_cell(const Point3& q, CellId fallback);
  /// Whether cell c conflicts with p (perturbed power test; insphere when unweighted).
  /// The common case, a finite cell decided by the filter, is inline (always: the conflict
  /// search calls it for every cell it visits); everything else goes to
  /// in_conflict_general. Calls are counted by the callers (stats_.power_test_calls).
  template <bool kWeighted>
#if defined(__GNUC__)
  __attribute__((always_inline))
#endif
  bool in_conflict(CellId c, VertexId p) {
    const int f = filtered_conflict<kWeighted>(c, p);
    if (f != predicates::detail::kUndecided) [[likely]] return f > 0;
    return in_conflict_general(c, p);
  }
  /// The filter's sign of the conflict test of a finite cell (1: conflict, −1: none), or
  /// kUndecided (also for an infinite cell): then in_conflict_general decides.
  template <bool kWeighted>
#if defined(__GNUC__)
  __attribute__((always_inline))
#endif
  int filtered_conflict(CellId c, VertexId p) {
    const Cell& k = t_.cells_[c];
    const bool finite = (k.v[0] != kInfiniteVertex) & (k.v[1] != kInfiniteVertex) &
                        (k.v[2] != kInfiniteVertex) & (k.v[3] != kInfiniteVertex);
    if (!finite) [[unlikely]] return predicates::detail::kUndecided;
    if constexpr (kWeighted) {
      return box_filter_->power_test_filter_two_stage(
          points_[k.v[0]], points_[k.v[1]], points_[k.v[2]], points_[k.v[3]], points_[p],
          weights_[k.v[0]], weights_[k.v[1]], weights_[k.v[2]], weights_[k.v[3]], weights_[p]);
    } else {
      return box_filter_->insphere_filter_two_stage(points_[k.v[0]], points_[k.v[1]],
                                                    points_[k.v[2]], points_[k.v[3]], points_[p]);
    }
  }
  bool in_conflict(CellId c, VertexId p) {
    return weights_ == nullptr ? in_conflict<false>(c, p) : in_conflict<true>(c, p);
  }
  bool in_conflict_general(CellId c, VertexId p);
  void find_conflict_region(CellId start, VertexId p);
  /// kOwned: returns false as soon as a cell in conflict is not owned (parallel pass).
  template <bool kWeighted, bool kOwned>
  bool find_conflict_region_impl(CellId start, VertexId p);
  void build_star(VertexId p);
  void link_star();
  /// Number of boundary vertex v (1..kLocal-1; the infinite vertex is 0), or 0 when the
  /// numbering is full. Without a branch on whether v is new (about one call in six, at
  /// random): build_star made room for kLocal pushes.
  std::uint8_t local_number(VertexId v) {
    if (v == kInfiniteVertex) return 0;
    const std::uint8_t current = vertex_local_[v];
    const bool fresh = (current == 0) & (local_vertices_.size() < kLocal - 1);
    local_vertices_.push_if(v, fresh);
    const std::uint8_t number =
        fresh ? static_cast<std::uint8_t>(local_vertices_.size()) : current;
    vertex_local_[v] = number;
    return number;
  }
  void link_star_hashed();
  /// The vertices p's insertion removed (reported with last_): a duplicate of p
  /// (Delaunay) or the vertices p hides (weighted). Reads the boundary numbering.
  void collect_hidden_vertices(VertexId duplicate_of);
  void release_conflict_region();
  CellId new_cell() {
    if (*free_head_ != kNoCell) [[likely]] {
      const CellId c = *free_head_;
      *free_head_ = t_.cells_[c].n[0];
      --*free_count_;
      return c;
    }
    if (in_region_) return region_next_++;  // room checked before the star is built
    return append_cell();
  }
  CellId append_cell();
  void after_insertion(VertexId p);

  RegularTriangulation3& t_;
  const TriangulationOptions& options_;
  const Point3* points_;
  const double* weights_;  // nullptr: Delaunay fast path
  /// The almost-static insphere / power-test filter over the points' bounding box (and
  /// weight range), tried before the semi-static bound on the same value (a decided sign is
  /// exact, and the perturbation only matters where the exact sign is zero, which the
  /// filter never claims). Engaged by run() before the first insertion.
  std::optional<predicates::AlmostStaticFilter> box_filter_;
  /// Two bits per cell (a Mark), 32 cells per word: 1/4 byte per cell of peak memory.
  std::vector<std::uint64_t> marks_;
  unsigned mark(CellId c) const {
    return static_cast<unsigned>(marks_[c >> 5] >> ((c & 31u) * 2)) & 3u;
  }
  void set_mark(CellId c, unsigned m) {
    std::uint64_t& w = marks_[c >> 5];
    const unsigned shift = (c & 31u) * 2;
    w = (w & ~(std::uint64_t{3} << shift)) | (std::uint64_t{m} << shift);
  }
  std::vector<std::uint8_t> vertex_mark_;  // per point (weighted only)
  ScratchList<CellId> conflict_;
  ScratchList<CellId> outside_;
  ScratchList<BoundaryFacet> boundary_;
  std::vector<CellId> star_;                // new cell of boundary_[k]
  /// The boundary numbers of new cell star_[k]'s vertices 1, 2, 3 (p is vertex 0).
  std::vector<std::array<std::uint8_t, 3>> star_local_;
  /// Whether star_ and star_local_ are build_star's, with every boundary vertex numbered
  /// (local_vertices_ still lists them): nearest_star_cell's shortcut.
  bool star_numbered_ = false;
  /// nearest_star_cell's scratch: boundary vertex k's coordinates minus the query.
  std::vector<Point3> star_offsets_ = std::vector<Point3>(kLocal);
  struct EdgeSlot {
    std::uint64_t key;    // the edge's two vertex ids, smaller first
    std::uint32_t face;   // new cell << 2 | facet index
    std::uint32_t stamp;  // slot in use iff stamp == stamp_
  };
  std::vector<EdgeSlot> edge_table_;        // open addressing, power-of-two size
  // Boundary vertices numbered 0..kLocal-1. Cavities of points on a surface have about 40
  // boundary vertices on average (10^6 points on a torus: 70% of the cavities had more
  // than 31), so the table has room for 127; it is never cleared (every entry read was
  // written by the same insertion), so only the entries in use reach the cache.
  static constexpr std::size_t kLocal = 128;
  std::vector<std::uint8_t> vertex_local_;   // per point: its number on the boundary, or 0
  ScratchList<VertexId> local_vertices_;
  std::vector<std::uint32_t> edge_faces_ = std::vector<std::uint32_t>(kLocal * kLocal);
  std::uint32_t stamp_ = 0;
  std::vector<VertexId> cavity_vertices_;
  std::vector<HiddenPoint> raw_hidden_;
  CellId last_ = 0;
  /// Whether star_ holds the cells of the latest insertion (false after a hidden point,
  /// whose cell is then last_, and before the first insertion).
  bool star_is_latest_ = false;
  /// Delaunay: the vertex with the inserted point's coordinates met by a conflict test of
  /// the current insertion, if any (it is removed when the point is in conflict).
  VertexId duplicate_of_ = kInfiniteVertex;
  bool reorder_ = false;
  Finish finish_ = Finish::queries;
  std::uint64_t rng_;

  // Free list and statistics: the triangulation's, or a helper's own during a pass.
  CellId* free_head_;
  std::size_t* free_count_;
  TriangulationStats* stats_;
  CellId own_free_head_ = kNoCell;
  std::size_t own_free_count_ = 0;
  TriangulationStats own_stats_;

  // Parallel passes (see insert_round_in_parallel).
  unsigned workers_ = 1;
  std::vector<std::uint32_t> keys_;        // per rank: Hilbert key (main builder only)
  std::vector<std::uint8_t> owner_store_;  // per rank: owning worker (main builder only)
  /// main's owner_store_: the owning worker of each vertex (a pass without locks), or 0
  /// (free) / holder + 1 (a pass with locks; atomic accesses only).
  std::uint8_t* owner_ = nullptr;
  /// Per rank, a cell made when the vertex was inserted (kNoCell before; it may have been
  /// destroyed since): where a deferred point's walk can start, next to the points before
  /// and after it on the curve (main's star_cell_store_, shared with the workers, each
  /// writing its own points' entries).
  std::vector<CellId> star_cell_store_;
  CellId* star_cell_ = nullptr;
  std::uint8_t worker_ = 0;
  VertexId shared_end_ = 0;                // ranks [0, shared_end_) are shared (insert_first)
  bool locking_ = false;                   // this pass takes vertex locks
  bool use_locks_ = false;                 // main: rounds after a futile pass take locks
  bool took_locks_ = false;                // main: a pass took locks (cell ids by timing)
  std::vector<VertexId> locked_;           // locks held, those of the kept star first
  std::size_t kept_locks_ = 0;             // locked_[0, kept_locks_): the kept star's
  VertexId next_point_ = kInfiniteVertex;  // the worker's next point, if any
  bool in_region_ = false;                 // new cells come from [region_next_, region_end_)
  CellId region_next_ = 0;
  CellId region_end_ = 0;
  bool exhausted_ = false;                 // the region ran out during this pass
  /// A pass with locks: the cell ids its workers take blocks of, as they need them (see
  /// parallel_pass).
  struct CellPool {
    std::atomic<std::uint64_t> next{0};
    std::uint64_t end = 0;
    std::uint64_t block = 0;
  };
  CellPool* pool_ = nullptr;
  /// The rest of the region to the worker's free list, and a new region from the pool;
  /// false when the pool is used up (or there is none).
  bool take_pool_block();
  /// The region's unused ids to the worker's free list.
  void free_region_rest();
  std::vector<std::pair<std::size_t, VertexId>> retry_;  // (attempt number, point) to retry
  Claim* own_claim_ = nullptr;        // the claims on the worker's stretch (during a pass)
  Claim* partner_claim_ = nullptr;    // the partner's, if any
  const std::vector<VertexId>* partner_list_ = nullptr;
  bool parallel_futile_ = false;           // a pass deferred too much: sequential from now
  double growth_rate_ = 0;                 // live cells per point over the last stretch
  /// A worker's deferred points, each with last_ when it was given up (near it: see
  /// insert_deferred); the main builder's gathers those of the current round's passes.
  std::vector<std::pair<VertexId, CellId>> deferred_;
  std::vector<std::pair<VertexId, CellId>> deferred_cells_;
  /// Inserts a round's remaining deferred points one by one, each walk starting at the cell
  /// where the point was given up when that is nearer than the previous star.
  void insert_deferred(const std::vector<VertexId>& deferred);
  /// Squared distance from 4q to the sum of finite cell c's vertices (16 times that from q
  /// to the centroid; floating point: it only chooses where a walk starts).
  double centroid_distance(CellId c, const Point3& q) const {
    const Cell& k = t_.cells_[c];
    double d2 = 0;
    for (std::size_t a = 0; a < 3; ++a) {
      const double d = points_[k.v[0]][a] + points_[k.v[1]][a] + points_[k.v[2]][a] +
                       points_[k.v[3]][a] - 4 * q[a];
      d2 += d * d;
    }
    return d2;
  }
  std::vector<std::unique_ptr<Builder>> helpers_;
};

}  // namespace rstruct::triangulation
