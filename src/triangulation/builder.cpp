#include "builder.hpp"

#include <algorithm>
#include <bit>
#include <limits>
#include <new>
#include <numeric>
#include <string>
#include <thread>
#include <exception>

#include "rstruct/core/assert.hpp"
#include "rstruct/core/error.hpp"
#include "rstruct/core/parallel.hpp"
#include "rstruct/core/stopwatch.hpp"
#include "rstruct/predicates/predicates.hpp"
#include "rstruct/triangulation/spatial_sort.hpp"

namespace rstruct::triangulation {

namespace pr = rstruct::predicates;

namespace {

/// Neighbour links hold cell << 2 | mirror index in 32 bits.
constexpr std::size_t kMaxCells = std::size_t{1} << 30;

/// kOther[i][j]: the two indices of {0, 1, 2, 3} other than i and j (i != j).
constexpr int kOther[4][4][2] = {
    {{-1, -1}, {2, 3}, {1, 3}, {1, 2}},
    {{2, 3}, {-1, -1}, {0, 3}, {0, 2}},
    {{1, 3}, {0, 3}, {-1, -1}, {0, 1}},
    {{1, 2}, {0, 2}, {0, 1}, {-1, -1}},
};
/// kFacetOrder[i]: the three indices of {0, 1, 2, 3} other than i, in an order that makes
/// (i, kFacetOrder[i][0], kFacetOrder[i][1], kFacetOrder[i][2]) an even permutation: a
/// cell with vertex i replaced by p and moved to slot 0 keeps its orientation.
constexpr int kFacetOrder[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

constexpr bool even_permutation(const int (&v)[4]) {
  int inversions = 0;
  for (int a = 0; a < 4; ++a) {
    for (int b = a + 1; b < 4; ++b) inversions += v[a] > v[b] ? 1 : 0;
  }
  return inversions % 2 == 0;
}
static_assert(even_permutation({0, kFacetOrder[0][0], kFacetOrder[0][1], kFacetOrder[0][2]}) &&
              even_permutation({1, kFacetOrder[1][0], kFacetOrder[1][1], kFacetOrder[1][2]}) &&
              even_permutation({2, kFacetOrder[2][0], kFacetOrder[2][1], kFacetOrder[2][2]}) &&
              even_permutation({3, kFacetOrder[3][0], kFacetOrder[3][1], kFacetOrder[3][2]}));

/// Exact orientation of the projection of a, b, c on the coordinate plane (axis0, axis1),
/// through orient3d on exactly representable lifted points (the projections with third
/// coordinate 0, and a's projection raised to 1): det equals the 2D orientation.
Sign projected_orientation(const Point3& a, const Point3& b, const Point3& c, int axis0,
                           int axis1) {
  const auto project = [&](const Point3& p, double up) {
    Point3 q{0, 0, 0};
    q[0] = p[static_cast<std::size_t>(axis0)];
    q[1] = p[static_cast<std::size_t>(axis1)];
    q[2] = up;
    return q;
  };
  return pr::orient3d(project(a, 0), project(b, 0), project(c, 0), project(a, 1));
}

bool collinear(const Point3& a, const Point3& b, const Point3& c) {
  return projected_orientation(a, b, c, 0, 1) == Sign::zero &&
         projected_orientation(a, b, c, 1, 2) == Sign::zero &&
         projected_orientation(a, b, c, 2, 0) == Sign::zero;
}

}  // namespace

Builder::Builder(RegularTriangulation3& t, const TriangulationOptions& options, Finish finish)
    : t_(t),
      options_(options),
      points_(t.points_.data()),
      weights_(t.weights_.empty() ? nullptr : t.weights_.data()),
      finish_(finish),
      rng_(options.seed | 1u),
      free_head_(&t.free_head_),
      free_count_(&t.free_count_),
      stats_(&t.stats_) {
  const unsigned requested =
      options.threads == 0 ? std::max(1u, std::thread::hardware_concurrency()) : options.threads;
  workers_ = std::min(requested, 8u);
}

Builder::Builder(const Builder& main, std::uint8_t worker)
    : t_(main.t_),
      options_(main.options_),
      points_(main.points_),
      weights_(main.weights_),
      box_filter_(main.box_filter_),
      reorder_(main.reorder_),
      rng_((main.options_.seed ^ (0xD1B54A32D192ED03ull * worker)) | 1u),
      free_head_(&own_free_head_),
      free_count_(&own_free_count_),
      stats_(&own_stats_),
      worker_(worker) {
  shared_end_ = main.shared_end_;
  vertex_local_.assign(t_.points_.size(), 0);
  if (weights_ != nullptr) vertex_mark_.assign(t_.points_.size(), 0);
}

void Builder::run() {
  const std::size_t n = t_.points_.size();
  Stopwatch clock;
  // Input ids from first_shared on are inserted before all the others (insert_first).
  const std::size_t shared = std::min(options_.insert_first, n);
  const std::size_t first_shared = n - shared;
  // Points stored in insertion order make the construction's memory accesses local
  // (vertex ids are then ranks; input ids come back at the end). Not while a caller
  // observes the intermediate triangulations, which must speak in input ids.
  reorder_ = options_.spatial_sort && !options_.after_insertion;
  // The Hilbert keys that partition the parallel rounds (by input id until the points are
  // in insertion order), from the sort.
  std::vector<std::uint32_t> input_keys;
  if (options_.spatial_sort) {
    t_.order_ = brio_order(t_.points_, options_.seed, options_.brio_divisor, 256, workers_,
                           reorder_ && workers_ > 1 ? &input_keys : nullptr);
    if (shared > 0) {
      std::stable_partition(t_.order_.begin(), t_.order_.end(),
                            [&](VertexId v) { return v >= first_shared; });
    }
  } else {
    t_.order_.resize(n);
    std::iota(t_.order_.begin(), t_.order_.end(), 0u);
  }
  if (n > 0) {
    Point3 lo = t_.points_[0], hi = t_.points_[0];
    for (const Point3& q : t_.points_) {
      for (std::size_t i = 0; i < 3; ++i) {
        lo[i] = std::min(lo[i], q[i]);
        hi[i] = std::max(hi[i], q[i]);
      }
    }
    box_filter_.emplace(lo, hi);
    if (weights_ != nullptr) {
      const auto [wlo, whi] = std::minmax_element(t_.weights_.begin(), t_.weights_.end());
      box_filter_->set_weight_range(*wlo, *whi);
    }
  }
  const bool swap_first = choose_first_tetrahedron();
  if (reorder_) permute_to_insertion_order();
  t_.stats_.sort_seconds = clock.seconds();
  clock.reset();
  // Delaunay of uniform points has about 6.7 cells per point, of points on a surface up to
  // about 20 (10^6 on a torus: 20.6). Pages never touched cost nothing (address space
  // only), so room for 24 per point is reserved: no reallocation, which would copy the
  // cells and touch their pages a second time. Where the system refuses that much address
  // space, 7.5 per point, and reserve_for_projection() extrapolates as it goes.
  try {
    t_.cells_.reserve(std::min(kMaxCells, n * 24 + 64));
  } catch (const std::bad_alloc&) {
    t_.cells_.reserve(n * 7 + n / 2 + 64);
  }
  marks_.reserve(t_.cells_.capacity() / 32 + 1);
  if (weights_ != nullptr) vertex_mark_.assign(n, 0);
  vertex_local_.assign(n, 0);
  VertexId first[4] = {vertex_at(0), vertex_at(1), vertex_at(2), vertex_at(3)};
  if (swap_first) std::swap(first[0], first[1]);
  make_first_cells(first);
  t_.processed_ = 4;
  for (std::size_t k = 0; k < 4; ++k) after_insertion(vertex_at(k));
  if (reorder_ && workers_ > 1) {
    // The shared points (insert_first) before the rounds; with the points in insertion
    // order, ranks [0, shared_end_) are theirs (choose_first_tetrahedron keeps the order
    // of the others; should it take a point from beyond them, a rank below shared_end_ is
    // not one of them: still correct, see owned()).
    shared_end_ = static_cast<VertexId>(shared);
    const std::size_t rounds_begin = std::max<std::size_t>(shared, 4);
    insert_sequentially(4, rounds_begin, n);
    // Rounds are the maximal stretches of non-decreasing Hilbert keys (a round may merge
    // with the next: still one stretch along the curve).
    keys_.resize(n);
    for (std::size_t r = 0; r < n; ++r) keys_[r] = input_keys[t_.order_[r]];
    input_keys = {};
    owner_store_.assign(n, 0);
    owner_ = owner_store_.data();
    star_cell_store_.assign(n, kNoCell);
    star_cell_ = star_cell_store_.data();
    use_locks_ = options_.parallel_scheme == TriangulationOptions::ParallelScheme::locks;
    t_.stats_.threads = workers_;
    for (std::size_t k = rounds_begin; k < n;) {
      std::size_t end = k + 1;
      while (end < n && keys_[end] >= keys_[end - 1]) ++end;
      const std::size_t live = t_.cells_.size() - t_.free_count_;
      if (!parallel_futile_ &&
          end - k >= std::max<std::size_t>(options_.parallel_min_round, 64 * workers_)) {
        insert_round_in_parallel(k, end);
      } else {
        insert_sequentially(k, end, n);
      }
      growth_rate_ = static_cast<double>(t_.cells_.size() - t_.free_count_ - live) /
                     static_cast<double>(end - k);
      k = end;
    }
    helpers_.clear();
    keys_ = {};
    owner_store_ = {};
    owner_ = nullptr;
    star_cell_store_ = {};
    star_cell_ = nullptr;
  } else {
    insert_sequentially(4, n, n);
  }
  marks_.clear();
  marks_.shrink_to_fit();
  vertex_local_.clear();
  vertex_local_.shrink_to_fit();
  vertex_mark_.clear();
  vertex_mark_.shrink_to_fit();
  if (finish_ == Finish::cells_only) {
    // The cells are about to be compacted (delaunay_cells), which renames them through
    // order_ on all threads as it goes: neither the renaming pass over every cell, the
    // points' permutation back to input order, nor the vertex index (one thread, one more
    // pass over every cell) is needed. The reports are resolved in ranks.
    if (!reorder_) t_.order_.clear();
    t_.resolve_hidden(raw_hidden_);
    t_.stats_.insertion_seconds = clock.seconds();
    return;
  }
  if (reorder_) restore_input_order();
  if (options_.canonical_order || (options_.canonical_order_after_locks && took_locks_)) {
    canonicalize_cells();
  }
  // order_'s memory (4 bytes per point, touched) becomes the vertex index's, which would
  // otherwise take fresh pages (finalize fills it).
  t_.vertex_cell_ = std::move(t_.order_);
  t_.order_ = {};
  t_.finalize(raw_hidden_);
  t_.stats_.insertion_seconds = clock.seconds();
}

void Builder::insert_sequentially(std::size_t begin, std::size_t end, std::size_t n) {
  for (std::size_t k = begin; k < end; ++k) {
    if (k == n / 64 || k == n / 8) reserve_for_projection(k, n, 1.3);
    if (k == n / 2) reserve_for_projection(k, n, 1.1);
    insert(vertex_at(k));
    t_.processed_ = k + 1;
    after_insertion(vertex_at(k));
  }
}

// Parallel insertion of one BRIO round (after Marot, Pellerin & Remacle, "One machine, one
// minute, three billion tetrahedra", 2019). The round, sorted along the Hilbert curve, is
// cut into one stretch of the curve per worker; every vertex inserted so far (and every
// point of the round) belongs to the worker whose stretch its key falls in, and the
// infinite vertex to every worker. A worker inserts a point only if the walk, every cell
// in conflict and therefore every new cell have all four vertices its own; otherwise the
// point is deferred, unchanged, to a second pass with other borders and then to a
// sequential pass. Why no locks are needed: a worker writes only cells with four vertices
// of its own (cavity and new cells) and the neighbour link of a cell across a facet with
// three of its own vertices; it reads only cells with at least three vertices of its own
// (it steps from a cell of its own across a facet to the next). No two workers own three
// vertices of one cell each (a finite cell would need six vertices; an infinite one, whose
// infinite vertex both own, five), so no cell one of them writes is read or written by
// another, and each worker's run depends only on cells nobody else touches: the result
// (cell ids included) depends on the number of workers, not on timing (ThreadSanitizer
// finds no race in tests/triangulation/test_parallel_insertion). New cells come from the
// worker's free list and then from a range of ids reserved for it.
//
// Shared vertices (TriangulationOptions::insert_first: the pole analysis's box corners)
// are every worker's too, like the infinite vertex; then a cell can have more than one
// vertex that no ownership keeps to one worker. The argument holds with "three of its own
// vertices" read as "the unshared vertices of a facet, at least one": a worker never looks
// across a facet of three shared vertices (facet_is_shared; the point is deferred) nor
// starts in a cell of four. A cell's vertices are rewritten only by a worker holding all
// its unshared vertices, anyone else reaches the cell across a facet with an unshared
// vertex of its own, and a neighbour link is written only by the worker replacing the cell
// on the other side, which holds that cell's unshared vertices: two workers never touch
// the same field (TSan finds races when facet_is_shared is dropped: test "many shared
// points").
//
// Passes with locks (points on a surface). Fixed borders defer too much there (3·10^5
// points on a torus: 47 %), so once a pass defers a quarter of a round, that round's
// deferred points and every later round go to passes where ownership is taken, not
// given: a worker owns a vertex while it holds its lock (a byte per vertex, taken by
// compare-and-swap, never waited for). owned() takes the lock of every vertex the walk
// steps to and of every conflict cell's vertices; if another worker holds one, the point
// is deferred and the locks taken for it released. The same argument as above shows that
// no cell is accessed by two workers at once, now at every moment instead of for the
// whole pass: a cell is read only with three of its vertices locked, written only with
// four (or three, for the neighbour link of a cell outside the cavity), and a lock is
// released only between two insertions, with release/acquire ordering. Between two
// points a worker keeps only the locks of the cell where its next walk starts (see
// keep_cell_locks). Double torus, 85,237 points and the pole analysis's box corners
// (inserted first, shared), two workers: 0.3-0.5 % deferred (fixed borders: 53 %; box
// corners inserted among the points and locked: 6-40 %). The cell ids then
// depend on timing (the triangulation does not): TriangulationOptions::canonical_order
// renumbers them.
void Builder::insert_round_in_parallel(std::size_t begin, std::size_t end) {
  const unsigned k = workers_;
  // Pass 1: stretches of the Hilbert curve (the round is sorted along it).
  std::array<std::uint32_t, 8> threshold{};
  std::array<std::size_t, 9> first{};
  first[0] = begin;
  first[k] = end;
  for (unsigned w = 1; w < k; ++w) {
    threshold[w] = keys_[begin + (end - begin) * w / k];
    first[w] = static_cast<std::size_t>(
        std::lower_bound(keys_.begin() + static_cast<std::ptrdiff_t>(begin),
                         keys_.begin() + static_cast<std::ptrdiff_t>(end), threshold[w]) -
        keys_.begin());
  }
  for (std::size_t v = 0; v < end; ++v) {
    std::uint8_t o = 0;
    while (o + 1u < k && keys_[v] >= threshold[o + 1u]) ++o;
    owner_store_[v] = o;
  }
  std::array<std::vector<VertexId>, 8> lists;
  for (unsigned w = 0; w < k; ++w) {
    lists[w].resize(first[w + 1] - first[w]);
    for (std::size_t r = first[w]; r < first[w + 1]; ++r) lists[w][r - first[w]] = vertex_at(r);
  }
  // Surfaces, after a pass with fixed borders deferred too much: locks (see above).
  const bool locking = use_locks_;
  took_locks_ = took_locks_ || locking;
  if (locking) {
    std::fill(owner_store_.begin(), owner_store_.begin() + static_cast<std::ptrdiff_t>(end),
              std::uint8_t{0});
  }
  std::vector<VertexId> deferred = parallel_pass(lists, begin, locking);
  t_.stats_.parallel_points += end - begin;
  // Points on a surface make long cells (their Delaunay balls approximate medial balls:
  // cells across the hole of a torus join points all around it), which cross every border:
  // 3·10^5 points on a torus, two workers, deferred 47 % in pass 1 and 97 % of those again
  // in pass 2, slower than one thread. So after a pass deferring a quarter, this round's
  // deferred points and the later rounds take locks instead (and if even those defer a
  // quarter, the remaining rounds are sequential). Points in a volume defer a few percent
  // (10^6 uniform: 5 %), more in small rounds (the borders are a larger share): those are
  // not judged.
  if (deferred.size() * 4 > end - begin && end - begin >= 4096 * k) {
    if (locking || options_.parallel_scheme == TriangulationOptions::ParallelScheme::borders) {
      parallel_futile_ = true;
    } else {
      use_locks_ = true;
      took_locks_ = true;
      for (unsigned w = 0; w < k; ++w) lists[w].clear();
      for (const VertexId p : deferred) lists[owner_store_[p]].push_back(p);  // rank order
      std::fill(owner_store_.begin(), owner_store_.begin() + static_cast<std::ptrdiff_t>(end),
                std::uint8_t{0});
      deferred = parallel_pass(lists, end - deferred.size(), true);
    }
  }
  // Pass 2: the deferred points lie near the borders of pass 1; they are cut again across
  // them, by planes perpendicular to the axis along which they spread most (10^6 uniform
  // points: 5 % -> 0.3 % deferred).
  if (!use_locks_ && !parallel_futile_ &&
      deferred.size() >= std::max<std::size_t>(options_.parallel_min_round, 64 * workers_) / 4) {
    std::array<double, 3> lo{}, hi{};
    lo.fill(std::numeric_limits<double>::infinity());
    hi.fill(-std::numeric_limits<double>::infinity());
    for (const VertexId p : deferred) {
      for (std::size_t a = 0; a < 3; ++a) {
        lo[a] = std::min(lo[a], points_[p][a]);
        hi[a] = std::max(hi[a], points_[p][a]);
      }
    }
    std::size_t axis = 0;
    for (std::size_t a = 1; a < 3; ++a) {
      if (hi[a] - lo[a] > hi[axis] - lo[axis]) axis = a;
    }
    std::vector<double> coordinate(deferred.size());
    for (std::size_t i = 0; i < deferred.size(); ++i) coordinate[i] = points_[deferred[i]][axis];
    std::array<double, 8> cut{};
    for (unsigned w = 1; w < k; ++w) {
      const auto at = coordinate.begin() + static_cast<std::ptrdiff_t>(coordinate.size() * w / k);
      std::nth_element(coordinate.begin(), at, coordinate.end());
      cut[w] = *at;
    }
    for (std::size_t v = 0; v < end; ++v) {
      std::uint8_t o = 0;
      while (o + 1u < k && points_[v][axis] >= cut[o + 1u]) ++o;
      owner_store_[v] = o;
    }
    for (unsigned w = 0; w < k; ++w) lists[w].clear();
    for (const VertexId p : deferred) lists[owner_store_[p]].push_back(p);  // rank order
    deferred = parallel_pass(lists, end - deferred.size(), false);
  }
  insert_deferred(deferred);
  t_.stats_.deferred_points += deferred.size();
  t_.processed_ = end;
}

// The rest, in rank order (along the curve), one by one. The points are sparse (10^6
// points on a torus, two workers: about 10^4 in the last round), so the walk from the
// previous one is long. Nearer starts: where a point's last attempt gave up, its walk had
// come near it, and that cell, if it still exists (a cell since reused lies near the
// worker's later points: its free cells are reused first), is often nearer; nearer still,
// as a rule, a cell made with the point before or after it on the curve (star_cell_), if
// that cell still exists.
void Builder::insert_deferred(const std::vector<VertexId>& deferred) {
  // The latest cell of each point (a point can be deferred by several passes).
  std::stable_sort(deferred_cells_.begin(), deferred_cells_.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::size_t h = 0;
  for (const VertexId p : deferred) {
    CellId hint = kNoCell;
    while (h < deferred_cells_.size() && deferred_cells_[h].first <= p) {
      if (deferred_cells_[h].first == p) hint = deferred_cells_[h].second;
      ++h;
    }
    const Point3& q = points_[p];
    CellId best = star_is_latest_ ? nearest_star_cell(q, last_) : last_;
    double best_distance = t_.is_cell(best) && t_.infinite_index(best) < 0
                               ? centroid_distance(best, q)
                               : std::numeric_limits<double>::infinity();
    const auto consider = [&](CellId c) {
      if (c == kNoCell || !t_.is_cell(c) || t_.infinite_index(c) >= 0) return;
      const double d = centroid_distance(c, q);
      if (d < best_distance) {
        best_distance = d;
        best = c;
      }
    };
    consider(hint);
    if (star_cell_ != nullptr) {
      // A cell that still has the neighbour as a vertex lies next to it (a cell id reused
      // for a cell without it could be anywhere).
      const auto neighbour = [&](VertexId v) {
        const CellId c = star_cell_[v];
        if (c == kNoCell || !t_.is_cell(c)) return;
        const Cell& k = t_.cells_[c];
        if (k.v[0] == v || k.v[1] == v || k.v[2] == v || k.v[3] == v) consider(c);
      };
      if (p > 0) neighbour(p - 1);
      if (static_cast<std::size_t>(p) + 1 < t_.points_.size()) neighbour(p + 1);
    }
    if (best != kNoCell) {
      last_ = best;
      star_is_latest_ = false;
    }
    insert(p);
  }
  deferred_cells_.clear();
}

// One parallel pass: worker w inserts lists[w] (increasing ranks) with owner_store_ telling
// which vertices are whose, `inserted` points being in the triangulation already. Returns
// the points deferred, in increasing rank.
std::vector<VertexId> Builder::parallel_pass(const std::array<std::vector<VertexId>, 8>& lists,
                                             std::size_t inserted, bool locking) {
  ++(locking ? t_.stats_.lock_passes : t_.stats_.border_passes);
  auto& cells = t_.cells_;
  const unsigned k = workers_;
  while (helpers_.size() + 1 < k) {
    helpers_.push_back(std::make_unique<Builder>(*this, static_cast<std::uint8_t>(helpers_.size() + 1)));
  }
  const auto worker = [&](unsigned w) -> Builder& { return w == 0 ? *this : *helpers_[w - 1]; };
  // With locks, pairs of workers balance their stretches (see run_worker): with fixed
  // stretches the two workers of the last round of 10^6 torus points ended 0.8-1.5 s apart
  // (which one is slower changes from round to round and run to run: the cores' speeds in
  // this VM), one core idle meanwhile.
  std::array<Claim, 8> claims;
  for (unsigned w = 0; w < k; ++w) {
    Builder& b = worker(w);
    b.owner_ = owner_;
    b.star_cell_ = star_cell_;
    b.worker_ = static_cast<std::uint8_t>(w);
    b.locking_ = locking;
    const bool paired = locking && (w ^ 1u) < k;
    b.own_claim_ = &claims[w];
    b.partner_claim_ = paired ? &claims[w ^ 1u] : nullptr;
    b.partner_list_ = paired ? &lists[w ^ 1u] : nullptr;
  }
  // Each worker's first point whose cell (found by a sequential walk) it owns (without
  // locks) or can lock: there its own walks start. The points before it are deferred.
  std::array<CellId, 8> start{};
  std::array<std::size_t, 8> from{};
  CellId hint = t_.is_cell(last_) ? last_ : t_.any_cell();
  for (unsigned w = 0; w < k; ++w) {
    start[w] = kNoCell;
    from[w] = lists[w].size();
    if (locking) {
      worker(w).choose_locked_start(lists[w], from[w], hint);
      continue;
    }
    for (std::size_t i = 0; i < lists[w].size() && i < 64; ++i) {
      hint = t_.walk(points_[lists[w][i]], hint, rng_, stats_->walk_steps,
                     stats_->orient_calls, &*box_filter_);
      const Cell& c = cells[hint];
      bool own = !cell_is_shared(c);
      for (const VertexId v : c.v) own = own && (is_shared(v) || owner_[v] == w);
      if (own) {
        start[w] = hint;
        from[w] = i;
        break;
      }
    }
  }
  for (unsigned w = 0; w < k; ++w) {
    claims[w].size = lists[w].size();
    claims[w].taken.store(from[w], std::memory_order_relaxed);  // the points before the start
  }
  // Room for the new cells: per point, the larger of the live cells per vertex so far and
  // the growth over the previous stretch (points on a surface: the cells per point grow
  // with n), with a margin of a quarter, per worker. Where that margin would take the
  // regions past the capacity reserved and a tenth would not, the margin is what fits:
  // growing the capacity copies the cell array and holds both copies (10^6 points on a
  // torus: the last round's regions ended 0.01 % below or above the 24 cells per point
  // reserved, depending on the earlier rounds, and above, the peak rose from about 770 to
  // 960 bytes per point). A worker whose region runs out defers its remaining points.
  const double per_point =
      std::max(growth_rate_, static_cast<double>(cells.size() - t_.free_count_) /
                                 static_cast<double>(inserted));
  std::size_t to_insert = 0;
  for (unsigned w = 0; w < k; ++w) to_insert += lists[w].size() - from[w];
  const double need = per_point * static_cast<double>(to_insert);
  const double room = static_cast<double>(cells.capacity()) -
                      static_cast<double>(cells.size() + 256 * std::size_t{k});
  double margin = 1.25;
  if (margin * need > room && 1.1 * need <= room) margin = room / need;
  std::array<std::size_t, 9> region{};
  region[0] = cells.size();
  for (unsigned w = 0; w < k; ++w) {
    region[w + 1] = region[w] + 256 +
                    static_cast<std::size_t>(margin * per_point *
                                             static_cast<double>(lists[w].size() - from[w]));
  }
  std::vector<VertexId> deferred;
  if (region[k] >= kMaxCells) {
    for (unsigned w = 0; w < k; ++w) {
      worker(w).unlock_all();
      worker(w).locking_ = false;
      worker(w).forget_claims();
      deferred.insert(deferred.end(), lists[w].begin(), lists[w].end());
    }
    std::sort(deferred.begin(), deferred.end());
    return deferred;
  }
  if (region[k] > cells.capacity()) cells.reserve(region[k] + region[k] / 4);
  cells.resize(region[k]);  // default-initialised: written by the workers (or freed below)
  // With locks a worker may insert more points than its stretch holds (it takes its
  // partner's), and a stretch may need more cells per point than the average: the workers
  // take blocks of one pool as they need them. With fixed regions, 10^6 points on a torus,
  // two workers: in 4 of 7 runs one worker's region of the last round ran out (20-33 ids
  // left) while the other's had 2.2 million left, and its partner then inserted the rest
  // of its own stretch alone for 0.4-0.7 s. Without locks each worker keeps its region, so
  // that the cell ids do not depend on timing.
  CellPool pool;
  if (locking) {
    pool.next.store(region[0], std::memory_order_relaxed);
    pool.end = region[k];
    // 2^16 cells are 2 MiB, a huge page; a small pass's pool is split finer.
    pool.block = std::clamp<std::uint64_t>((region[k] - region[0]) / (8 * std::uint64_t{k}),
                                           std::uint64_t{256}, std::uint64_t{1} << 16);
  }
  for (unsigned w = 0; w < k; ++w) {
    Builder& b = worker(w);
    b.marks_.resize(region[k] / 32 + 1, 0);
    b.in_region_ = true;
    b.region_next_ = static_cast<CellId>(locking ? region[0] : region[w]);
    b.region_end_ = static_cast<CellId>(locking ? region[0] : region[w + 1]);
    b.pool_ = locking ? &pool : nullptr;
    b.exhausted_ = false;
    b.deferred_.clear();
  }
  {
    std::array<std::exception_ptr, 8> errors{};
    {
      std::vector<std::jthread> threads;
      for (unsigned w = 1; w < k; ++w) {
        threads.emplace_back([&, w] {
          try {
            worker(w).run_worker(lists[w], from[w], start[w]);
          } catch (...) {
            errors[w] = std::current_exception();
          }
        });
      }
      try {
        run_worker(lists[0], from[0], start[0]);
      } catch (...) {
        errors[0] = std::current_exception();
      }
    }
    for (unsigned w = 0; w < k; ++w) worker(w).pool_ = nullptr;  // (no blocks after the pass)
    for (const std::exception_ptr& e : errors) {
      if (e) std::rethrow_exception(e);
    }
  }
  // Without locks, unused ids of the regions join the free list; the last region's are cut
  // off. The helpers' free lists, hidden points and counts join the triangulation's.
  //
  // The unused ids are chained on all threads, each to the id below it (the lowest to the
  // list's head): the list a loop pushing them in increasing order made. Their pages are
  // mostly touched for the first time here: 10^6 points on a torus, two workers, the last
  // round's first region can leave a fifth unused, some 40 MB. That loop, on one thread,
  // took 0.0003-0.18 s after the last round (6 runs; 0.065 s typical), now 0.0008-0.053 s
  // (0.013 s typical).
  for (unsigned w = 0; w + 1 < k && !locking; ++w) {
    const CellId lo = worker(w).region_next_;
    Cell* const data = cells.data();
    parallel_chunks(worker(w).region_end_ - lo, k, std::size_t{1} << 16,
                    [&](std::size_t begin, std::size_t end, unsigned) {
                      for (std::size_t i = begin; i < end; ++i) {
                        const auto c = static_cast<CellId>(lo + i);
                        data[c].v[0] = RegularTriangulation3::kFreeMark;
                        data[c].n[0] = c - 1;  // the lowest one's is set below
                      }
                    });
  }
  if (locking) {
    // The rest of each worker's last block joins its free list (fewer than a block: pages
    // the worker has mostly touched already); the pool's untaken ids are cut off.
    for (unsigned w = 0; w < k; ++w) worker(w).free_region_rest();
    cells.resize(std::min(pool.next.load(std::memory_order_relaxed), pool.end));
  }
  for (unsigned w = 0; w < k; ++w) {
    Builder& b = worker(w);
    b.in_region_ = false;
    b.locking_ = false;
    if (!locking) {  // (with locks, done above)
      if (w + 1 < k) {
        if (b.region_next_ < b.region_end_) {
          cells[b.region_next_].n[0] = t_.free_head_;
          t_.free_head_ = b.region_end_ - 1;
          t_.free_count_ += b.region_end_ - b.region_next_;
        }
      } else {
        cells.resize(b.region_next_);
      }
    }
    deferred.insert(deferred.end(), lists[w].begin(),
                    lists[w].begin() + static_cast<std::ptrdiff_t>(from[w]));
    // Points nobody claimed (the regions ran out).
    const std::uint64_t taken = claims[w].taken.load(std::memory_order_relaxed);
    deferred.insert(deferred.end(),
                    lists[w].begin() + static_cast<std::ptrdiff_t>(taken & 0xffffffffu),
                    lists[w].end() - static_cast<std::ptrdiff_t>(taken >> 32));
    if (b.exhausted_) ++t_.stats_.exhausted_workers;
    b.forget_claims();
    for (const auto& [p, cell] : b.deferred_) deferred.push_back(p);
    deferred_cells_.insert(deferred_cells_.end(), b.deferred_.begin(), b.deferred_.end());
    if (w == 0) continue;
    if (b.own_free_head_ != kNoCell) {
      CellId tail = b.own_free_head_;
      while (cells[tail].n[0] != kNoCell) tail = cells[tail].n[0];
      cells[tail].n[0] = t_.free_head_;
      t_.free_head_ = b.own_free_head_;
      t_.free_count_ += b.own_free_count_;
      b.own_free_head_ = kNoCell;
      b.own_free_count_ = 0;
    }
    raw_hidden_.insert(raw_hidden_.end(), b.raw_hidden_.begin(), b.raw_hidden_.end());
    b.raw_hidden_.clear();
    TriangulationStats& s = t_.stats_;
    s.walk_steps += b.own_stats_.walk_steps;
    s.conflict_cells += b.own_stats_.conflict_cells;
    s.orient_calls += b.own_stats_.orient_calls;
    s.power_test_calls += b.own_stats_.power_test_calls;
    s.filter_misses += b.own_stats_.filter_misses;
    s.large_cavities += b.own_stats_.large_cavities;
    s.taken_points += b.own_stats_.taken_points;
    b.own_stats_ = {};
  }
  std::sort(deferred.begin(), deferred.end());
  return deferred;
}

void Builder::run_worker(const std::vector<VertexId>& list, std::size_t from, CellId start) {
  if (!locking_) {
    last_ = start;
    star_is_latest_ = false;
  }
  // With locks, a point that another worker's locks kept out (mostly: its walk was
  // blocked) is tried again at once, up to kAtOnce times after a short pause: the other
  // worker holds those locks only until its insertion ends (about 10 µs on a torus), and
  // the new walk starts where the blocked one stopped. 10^6 points on a torus, two workers,
  // 6 interleaved pairs: deferred 4.6-12.9 % -> 0.9-1.4 %, insertion 8.70 -> 8.03 s
  // (medians; every pair faster).
  // Then it is tried once more kRetryDelay points later, when that worker has usually
  // moved on, and only then deferred to the sequential pass: 10^6 points on a torus, two
  // workers, deferred 6.3 -> 4.4 % and 11.0 -> 10.5 s (medians of 6 interleaved pairs on
  // a slow VM; 4 earlier pairs: 9.06 -> 8.58 s).
  // With locks any worker may insert any point, so a worker that is done with its stretch
  // takes its partner's remaining points from the far end, towards the partner (on 10^6
  // torus points the last round's two stretches ended 0.8-1.5 s apart). Tried before: the
  // far half of the other's remaining stretch, again and again, which brought the two
  // into one region early and deferred more: 10 interleaved pairs, insertion medians 8.24
  // -> 8.46 s.
  constexpr std::size_t kRetryDelay = 16;
  constexpr int kAtOnce = 4;
  constexpr int kPauses = 20;
  retry_.clear();
  std::size_t retry_head = 0;
  std::size_t attempts = 0;
  const auto attempt = [&](VertexId p, bool may_retry) {
    bool inserted = !exhausted_ && insert_owned(p);
    for (int t = 0; !inserted && locking_ && !exhausted_ && t < kAtOnce; ++t) {
      unlock_attempt();
      for (int pause = 0; pause < kPauses; ++pause) cpu_relax();
      inserted = insert_owned(p);
    }
    if (!inserted) {
      if (locking_) unlock_attempt();
      if (may_retry && locking_ && !exhausted_) {
        retry_.push_back({attempts, p});
      } else {
        deferred_.emplace_back(p, last_);
      }
    }
  };
  // p, then the retries that are due; `next` is the point after p (kInfiniteVertex if
  // unknown), near which insert_owned keeps its locks.
  const auto take = [&](VertexId p, VertexId next) {
    next_point_ = next;
    attempt(p, true);
    ++attempts;
    while (retry_head < retry_.size() && retry_[retry_head].first + kRetryDelay <= attempts) {
      attempt(retry_[retry_head++].second, false);
    }
  };
  // The own stretch from the front, a block at a time (a worker whose region runs out
  // stops claiming: its partner, or the sequential pass, takes the rest).
  std::size_t end = from;
  for (std::size_t i = from;; ++i) {
    if (i >= end && (exhausted_ || !claim_more(*own_claim_, false, 0, end))) break;
    // (The next point is nearly always this worker's too: the partner takes points from
    // the far end only.)
    take(list[i], i + 1 < list.size() ? list[i + 1] : kInfiniteVertex);
  }
  // Then the partner's from the back, towards the partner (the partner's walks come from
  // the other side: the two meet only at the end).
  // (A worker that found no start holds no cell to walk from: it takes nothing.)
  if (partner_claim_ != nullptr && from < list.size()) {
    const std::vector<VertexId>& other = *partner_list_;
    std::size_t back = 0;
    for (std::size_t j = 0;; ++j) {
      if (j >= back &&
          (exhausted_ || !claim_more(*partner_claim_, true, options_.parallel_steal_gap, back))) {
        break;
      }
      const std::size_t at = other.size() - 1 - j;
      take(other[at], at > 0 ? other[at - 1] : kInfiniteVertex);
      ++stats_->taken_points;
    }
  }
  next_point_ = kInfiniteVertex;
  while (retry_head < retry_.size()) attempt(retry_[retry_head++].second, false);
  if (locking_) unlock_all();
}

bool Builder::claim_more(Claim& claim, bool back, std::size_t gap, std::size_t& end) {
  std::uint64_t taken = claim.taken.load(std::memory_order_relaxed);
  for (;;) {
    const std::size_t front_count = taken & 0xffffffffu;
    const std::size_t back_count = taken >> 32;
    const std::size_t mine = back ? back_count : front_count;
    const std::size_t other = back ? front_count : back_count;
    RSTRUCT_DEBUG_ASSERT(mine == end);
    // The gap (TriangulationOptions::parallel_steal_gap) trades two costs. Two workers
    // that near each other keep each other out: 1.2·10^5 torus points, two workers
    // (test_parallel_workload, 3 runs of 3 triangulations each), deferred 0.38-0.57 % when
    // a worker takes points until the two meet. And the partner inserts the gap alone:
    // 4,096 points are 20-25 ms of one idle core on the double torus (85,237 points, last
    // round about 2·21,000), a fifth of a stretch there. Measured, same binary:
    // - deferrals in test_parallel_workload (sums over its 3 triangulations, 10 runs each,
    //   debugoptimized): gap 4,096 median 905 (533-2,582), 1,024 median 988 (711-1,735),
    //   256 median 1,390 (998-1,901);
    // - the double torus's pole analysis Delaunay (bench_seed): 4,096 -> 256, 5 pairs,
    //   0.441 / 0.322 / 0.298 / 0.389 / 0.320 -> 0.315 / 0.298 / 0.293 / 0.316 / 0.301 s;
    //   256 -> 1,024, 6 pairs, medians 0.356 -> 0.366 s (the noise);
    // - 10^6 torus points (bench_triangulation, 4,096 -> 256, 3 pairs): 8.17 / 7.70 / 8.36
    //   -> 7.89 / 7.88 / 8.39 s (the noise).
    if (mine + other + (back ? gap : 0) >= claim.size) return false;
    const std::uint64_t next = std::min(mine + kClaimBlock, claim.size - other);
    const std::uint64_t updated = back ? (taken & 0xffffffffu) | next << 32
                                       : (taken & ~std::uint64_t{0xffffffffu}) | next;
    // Relaxed: the claims only split the points; the vertex locks order the insertions.
    if (claim.taken.compare_exchange_weak(taken, updated, std::memory_order_relaxed)) {
      end = next;
      return true;
    }
  }
}

void Builder::unlock_attempt() {
  for (std::size_t i = kept_locks_; i < locked_.size(); ++i) {
    std::atomic_ref<std::uint8_t>(owner_[locked_[i]]).store(0, std::memory_order_release);
  }
  locked_.resize(kept_locks_);
}

void Builder::unlock_all() {
  kept_locks_ = 0;
  unlock_attempt();
  star_is_latest_ = false;  // the other workers may change the star from now on
}

void Builder::choose_locked_start(const std::vector<VertexId>& list, std::size_t& from,
                                  CellId& hint) {
  from = list.size();
  star_is_latest_ = false;
  for (std::size_t i = 0; i < list.size() && i < 64; ++i) {
    hint = t_.walk(points_[list[i]], hint, rng_, stats_->walk_steps, stats_->orient_calls,
                   &*box_filter_);
    bool all = !cell_is_shared(t_.cells_[hint]);
    for (const VertexId v : t_.cells_[hint].v) all = all && owned(v);
    if (all) {
      keep_cell_locks(hint);
      from = i;
      return;
    }
    unlock_attempt();
  }
}

bool Builder::insert_owned(VertexId p) {
  if (!owned(p)) return false;
  duplicate_of_ = kInfiniteVertex;
  bool conflict = false;
  bool blocked = false;
  const CellId c = locate_conflict(p, conflict, &blocked);
  if (blocked) return false;
  if (!conflict) {
    record_hidden(p, c);
    if (locking_) unlock_attempt();
    return true;
  }
  const bool complete = weights_ == nullptr ? find_conflict_region_impl<false, true>(c, p)
                                            : find_conflict_region_impl<true, true>(c, p);
  if (!complete) {
    clear_conflict_marks();
    return false;
  }
  while (boundary_.size() > *free_count_ + (region_end_ - region_next_)) {
    if (!take_pool_block()) {
      clear_conflict_marks();
      exhausted_ = true;
      return false;
    }
  }
  build_star(p);
  collect_hidden_vertices(duplicate_of_);
  if (locking_) {
    // Only the locks of the new cell nearest to the next point are kept (its walk starts
    // there): a whole star's are many more, and in the pole analysis a star often holds a
    // bounding-box corner, which every cell outside the sample shares (double torus: 3 %
    // to 33 % deferred while stars were kept, about 1 % with one cell).
    keep_cell_locks(next_point_ != kInfiniteVertex
                        ? nearest_star_cell(points_[next_point_], star_.front())
                        : star_.front());
  }
  for (const VertexId v : local_vertices_) vertex_local_[v] = 0;
  release_conflict_region();
  return true;
}

bool Builder::take_pool_block() {
  if (pool_ == nullptr) return false;
  // Relaxed: the count only hands out disjoint ranges; each range's cells are then written
  // by its worker alone, and the pass's end joins the threads.
  const std::uint64_t at = pool_->next.fetch_add(pool_->block, std::memory_order_relaxed);
  if (at >= pool_->end) return false;
  free_region_rest();
  region_next_ = static_cast<CellId>(at);
  region_end_ = static_cast<CellId>(std::min(at + pool_->block, pool_->end));
  return true;
}

void Builder::free_region_rest() {
  auto& cells = t_.cells_;
  for (CellId c = region_end_; c > region_next_;) {
    --c;
    cells[c].v[0] = RegularTriangulation3::kFreeMark;
    cells[c].n[0] = *free_head_;
    *free_head_ = c;
    ++*free_count_;
  }
  region_next_ = region_end_;
}

void Builder::clear_conflict_marks() {
  for (const CellId x : conflict_) set_mark(x, kNone);
  for (const CellId y : outside_) set_mark(y, kNone);
}

// RegularTriangulation3::walk restricted to the worker's cells: it starts in one and stops
// (blocked) before stepping into a cell with a vertex of another worker (or the infinite
// vertex), so it never reads a cell another worker may be changing. Same moves otherwise:
// the segment from the start cell's centroid first, then the facets in random order, each
// move decided by an exact orientation.
// With locks, a worker keeps between two points only the locks of one cell, where its
// next walk starts: after an insertion the new cell nearest to the next point, after a
// walk the cell it ended in, even if the insertion is then deferred. (When the start
// stayed at the latest insertion, a run of deferred points near the other worker made
// the walks grow: 10^6 points on a torus, 1,000 to 65,000 steps, up to 0.5 apart where
// points are 0.004 apart, locking every vertex on the way, and the other worker then
// deferred a fifth of its points.)
void Builder::keep_cell_locks(CellId c) {
  const Cell& k = t_.cells_[c];
  std::size_t kept = 0;
  for (const VertexId v : locked_) {
    if (v == k.v[0] || v == k.v[1] || v == k.v[2] || v == k.v[3]) {
      locked_[kept++] = v;
    } else {
      std::atomic_ref<std::uint8_t>(owner_[v]).store(0, std::memory_order_release);
    }
  }
  locked_.resize(kept);
  kept_locks_ = kept;
  star_.assign(1, c);
  star_numbered_ = false;
  last_ = c;
  star_is_latest_ = true;
}

CellId Builder::walk_owned(const Point3& q, CellId start, bool& blocked) {
  const auto& cells = t_.cells_;
  CellId c = start;
  CellId previous = kNoCell;
  bool follow_segment = t_.infinite_index(c) < 0;
  Point3 o{0, 0, 0};
  if (follow_segment) {
    for (const VertexId v : cells[c].v) {
      o.x += 0.25 * points_[v].x;
      o.y += 0.25 * points_[v].y;
      o.z += 0.25 * points_[v].z;
    }
  }
  const double wx = q.x - o.x, wy = q.y - o.y, wz = q.z - o.z;
  constexpr std::size_t kLimit = 1 << 16;  // a pathological walk is left to the sequential pass
  for (std::size_t step = 0; step < kLimit; ++step) {
    ++stats_->walk_steps;
    std::uint32_t link = 0;
    const int inf = t_.infinite_index(c);
    if (inf >= 0) {
      link = cells[c].n[inf];
      if (previous == (link >> 2)) return c;
      ++stats_->orient_calls;
      if (t_.orient_replaced(c, inf, q, &*box_filter_) > 0) return c;
      follow_segment = false;
      if (facet_is_shared(cells[c], inf)) {
        blocked = true;
        return c;
      }
    } else {
      for (int i = 0; i < 4; ++i) __builtin_prefetch(&cells[cells[c].n[i] >> 2]);
      // Any facet q is strictly beyond is a valid move (the walk still terminates), so a
      // facet into a cell of another worker is skipped while another one remains.
      int next = -1;
      bool beyond_foreign = false;
      const auto try_facet = [&](int i) {
        ++stats_->orient_calls;
        if (t_.orient_replaced(c, i, q, &*box_filter_) >= 0) return;
        const std::uint32_t l = cells[c].n[i];
        if (!facet_is_shared(cells[c], i) && owned(cells[l >> 2].v[l & 3u])) {
          next = i;
        } else {
          beyond_foreign = true;
        }
      };
      int exit = -1;
      if (follow_segment) {
        exit = t_.segment_exit_facet(c, o, wx, wy, wz, previous);
        if (exit >= 0) try_facet(exit);
      }
      if (next < 0) {
        rng_ ^= rng_ << 13;
        rng_ ^= rng_ >> 7;
        rng_ ^= rng_ << 17;
        const int r = static_cast<int>(rng_ & 3u);
        for (int t = 0; t < 4 && next < 0; ++t) {
          const int i = (r + t) & 3;
          if (i != exit && (cells[c].n[i] >> 2) != previous) try_facet(i);
        }
      }
      if (next < 0) {
        blocked = beyond_foreign;
        return c;
      }
      link = cells[c].n[next];
    }
    if (!owned(cells[link >> 2].v[link & 3u])) {
      blocked = true;
      return c;
    }
    previous = c;
    c = link >> 2;
  }
  blocked = true;
  return c;
}

// Points on a surface have Theta(n log n) Delaunay cells (cylinder-like pieces: Devillers,
// Erickson & Goaoc), 20 per point for 10^6 points on a torus. Growing the cell array by
// doubling late in the construction copies hundreds of MiB and holds both copies: peak
// memory near twice the final size. So after k of the n points (k = n/64, n/8, n/2: the
// sample is random, the BRIO rounds spread over the whole input), the cells per inserted
// point are extrapolated to n with a margin and reserved at once, while the copy is small.
void Builder::reserve_for_projection(std::size_t k, std::size_t n, double margin) {
  auto& cells = t_.cells_;
  const double per_point = static_cast<double>(cells.size()) / static_cast<double>(k);
  const double projected = margin * per_point * static_cast<double>(n) + 64;
  if (projected > static_cast<double>(cells.capacity()) &&
      projected < static_cast<double>(kMaxCells)) {
    cells.reserve(static_cast<std::size_t>(projected));
    marks_.reserve(cells.capacity() / 32 + 1);
  }
}

void Builder::permute_to_insertion_order() {
  const std::vector<VertexId>& order = t_.order_;
  std::vector<Point3> points(order.size());
  for (std::size_t r = 0; r < order.size(); ++r) points[r] = t_.points_[order[r]];
  t_.points_.swap(points);
  points_ = t_.points_.data();
  if (weights_ != nullptr) {
    std::vector<double> weights(order.size());
    for (std::size_t r = 0; r < order.size(); ++r) weights[r] = t_.weights_[order[r]];
    t_.weights_.swap(weights);
    weights_ = t_.weights_.data();
  }
}

// Back to input ids: cell vertices and hidden records are renamed through order_, and the
// points (and weights) are permuted in place (permute_points_to_input_order), so no second
// copy is needed.
void Builder::restore_input_order() {
  const std::vector<VertexId>& order = t_.order_;
  Cell* const cells = t_.cells_.data();
  parallel_chunks(t_.cells_.size(), workers_, std::size_t{1} << 16,
                  [&](std::size_t begin, std::size_t end, unsigned) {
                    for (std::size_t c = begin; c < end; ++c) {
                      Cell& k = cells[c];
                      if (k.v[0] == RegularTriangulation3::kFreeMark) continue;
                      for (VertexId& v : k.v) {
                        if (v != kInfiniteVertex) v = order[v];
                      }
                    }
                  });
  for (HiddenPoint& h : raw_hidden_) h.point = order[h.point];
  permute_points_to_input_order();
  points_ = t_.points_.data();
  weights_ = weights_ != nullptr ? t_.weights_.data() : nullptr;
  reorder_ = false;
}

// The point at rank r moves to position order[r], along the permutation's cycles. Following
// one cycle is a chain of dependent loads of order[] (a random permutation for points given
// in random order: 10^6 points, about 60 ns per step, memory latency). So the cycles are cut
// into segments at evenly spaced ranks (their points put aside first), and kLanes segments
// are followed at once, one step of each in turn: each lane's loads wait, but the lanes'
// waits overlap. A lane ends its segment at the next start it meets (whose point was put
// aside, so that position takes the lane's point) and then takes the next segment. Cycles
// without a start (short ones) are followed one by one afterwards. 10^6 points, perf
// samples (4 kHz) of restore_input_order, which did this one cycle at a time (the point
// two steps ahead prefetched): uniform 490 / 397 -> 172 / 168 with 8 lanes, weighted
// 554 / 668 -> 211 / 226; 16 lanes took 7-30 % fewer samples than 8 in this function.
void Builder::permute_points_to_input_order() {
  const std::vector<VertexId>& order = t_.order_;
  const std::size_t n = order.size();
  Point3* const points = t_.points_.data();
  double* const weights = weights_ != nullptr ? t_.weights_.data() : nullptr;
  std::vector<bool> placed(n, false);
  constexpr std::size_t kLanes = 16;
  // Ranks between two segment starts: 1,024 (10^6 points: 977 starts), fewer below 65,536
  // points (64 starts), so that every input takes this path.
  const std::size_t spacing = std::clamp<std::size_t>(n / 64, 1, 1024);
  const std::size_t starts = (n + spacing - 1) / spacing;
  std::vector<bool> is_start(n, false);
  struct Carried {
    Point3 point;
    double weight;
    std::size_t at;  // its position: the current step's source
  };
  std::vector<Carried> start_points(starts);
  for (std::size_t j = 0; j < starts; ++j) {
    const std::size_t s = j * spacing;
    is_start[s] = true;
    start_points[j] = {points[s], weights != nullptr ? weights[s] : 0.0, s};
  }
  Carried lane[kLanes];
  bool active[kLanes];
  std::size_t taken = 0;
  std::size_t running = 0;
  for (std::size_t l = 0; l < kLanes; ++l) {
    active[l] = taken < starts;
    if (active[l]) {
      lane[l] = start_points[taken++];
      ++running;
    }
  }
  while (running > 0) {
    for (std::size_t l = 0; l < kLanes; ++l) {
      if (!active[l]) continue;
      Carried& c = lane[l];
      const std::size_t next = order[c.at];
      placed[next] = true;
      if (is_start[next]) [[unlikely]] {
        points[next] = c.point;
        if (weights != nullptr) weights[next] = c.weight;
        active[l] = taken < starts;
        if (active[l]) {
          lane[l] = start_points[taken++];
        } else {
          --running;
        }
        continue;
      }
      std::swap(c.point, points[next]);
      if (weights != nullptr) std::swap(c.weight, weights[next]);
      c.at = next;
    }
  }
  for (std::size_t r = 0; r < n; ++r) {
    if (placed[r]) continue;
    // A cycle without a start; the point two steps ahead is fetched meanwhile.
    Point3 point = points[r];
    double weight = weights != nullptr ? weights[r] : 0.0;
    std::size_t current = r;
    do {
      const std::size_t next = order[current];
      const std::size_t after = order[next];
      __builtin_prefetch(&points[after]);
      if (weights != nullptr) __builtin_prefetch(&weights[after]);
      std::swap(point, points[next]);
      if (weights != nullptr) std::swap(weight, weights[next]);
      placed[next] = true;
      current = next;
    } while (current != r);
  }
}

// The canonical order: cells by their smallest vertex id, then by their other vertex ids
// in increasing order; within a cell the two smallest vertex ids first, increasing, and
// the other two in the order that keeps the orientation (an even permutation of the
// stored order). It depends only on the set of cells, which the perturbation makes
// unique: not on the insertion order, the walks or the threads. A counting sort by
// smallest vertex, each vertex's few dozen cells then sorted; every pass runs on the
// insertion threads, each on a fixed stretch of cells (so the scatter is deterministic too).
void Builder::canonicalize_cells() {
  auto& cells = t_.cells_;
  const std::size_t m = cells.size();
  const std::size_t n = t_.points_.size();
  const unsigned threads = thread_count(workers_, m, std::size_t{1} << 16);
  const std::size_t stretch = (m + threads - 1) / threads;
  const auto on_stretches = [&](auto&& fn) {
    parallel_chunks(m, threads, stretch, [&](std::size_t begin, std::size_t end, unsigned) {
      fn(begin / stretch, begin, end);
    });
  };
  // Pass 1: each cell's new slot for every old slot (2 bits each): its rank by vertex id
  // (the ids of a cell are distinct; the infinite vertex's is the largest), the two
  // largest exchanged when the ranking is an odd permutation; and per stretch, the number
  // of cells by smallest vertex.
  std::vector<std::uint8_t> new_slot(m, 0);
  std::vector<std::uint32_t> count(static_cast<std::size_t>(threads) * n, 0);
  std::vector<std::size_t> live_in(threads, 0);
  on_stretches([&](std::size_t t, std::size_t begin, std::size_t end) {
    std::uint32_t* mine = count.data() + t * n;
    for (std::size_t c = begin; c < end; ++c) {
      const Cell& k = cells[c];
      if (k.v[0] == RegularTriangulation3::kFreeMark) continue;
      ++live_in[t];
      unsigned rank[4] = {0, 0, 0, 0};
      unsigned inversions = 0;
      for (unsigned i = 0; i < 4; ++i) {
        for (unsigned j = i + 1; j < 4; ++j) {
          const unsigned greater = k.v[i] > k.v[j] ? 1u : 0u;
          inversions += greater;
          rank[i] += greater;
          rank[j] += 1u - greater;
        }
      }
      std::uint8_t packed = 0;
      for (unsigned j = 0; j < 4; ++j) {
        const unsigned to = rank[j] >= 2 ? rank[j] ^ (inversions & 1u) : rank[j];
        packed |= static_cast<std::uint8_t>(to << (2 * j));
        if (rank[j] == 0) ++mine[k.v[j]];
      }
      new_slot[c] = packed;
    }
  });
  std::size_t live = 0;
  for (const std::size_t l : live_in) live += l;
  // Where each stretch's cells of each bucket go; afterwards end_of[v], the end of v's.
  std::vector<std::uint32_t> end_of(n);
  {
    std::uint32_t at = 0;
    for (std::size_t v = 0; v < n; ++v) {
      for (std::size_t t = 0; t < threads; ++t) {
        const std::uint32_t c = count[t * n + v];
        count[t * n + v] = at;
        at += c;
      }
      end_of[v] = at;
    }
  }
  // Pass 2: (other three ids sorted, cell) records scattered into the buckets, then each
  // bucket sorted (contiguous records: no random reads).
  struct Record {
    std::array<VertexId, 3> rest;
    CellId cell;
  };
  const std::unique_ptr<Record[]> records(new Record[live]);
  on_stretches([&](std::size_t t, std::size_t begin, std::size_t end) {
    std::uint32_t* at = count.data() + t * n;
    for (std::size_t c = begin; c < end; ++c) {
      const Cell& k = cells[c];
      if (k.v[0] == RegularTriangulation3::kFreeMark) continue;
      VertexId v[4];  // in their new slots: the two smallest first, increasing
      for (unsigned j = 0; j < 4; ++j) v[(new_slot[c] >> (2 * j)) & 3u] = k.v[j];
      records[at[v[0]]++] = {{v[1], std::min(v[2], v[3]), std::max(v[2], v[3])},
                             static_cast<CellId>(c)};
    }
  });
  count = {};
  parallel_chunks(n, threads, (n + threads - 1) / threads,
                  [&](std::size_t first, std::size_t last, unsigned) {
                    for (std::size_t v = first; v < last; ++v) {
                      // Insertion sort: a bucket holds a few dozen cells.
                      Record* lo = records.get() + (v == 0 ? 0 : end_of[v - 1]);
                      Record* hi = records.get() + end_of[v];
                      for (Record* r = lo + 1; r < hi; ++r) {
                        const Record x = *r;
                        Record* q = r;
                        for (; q > lo && x.rest < (q - 1)->rest; --q) *q = *(q - 1);
                        *q = x;
                      }
                    }
                  });
  end_of = {};
  std::vector<CellId> new_id(m, kNoCell);
  parallel_chunks(live, threads, (live + threads - 1) / threads,
                  [&](std::size_t first, std::size_t last, unsigned) {
                    for (std::size_t i = first; i < last; ++i) {
                      new_id[records[i].cell] = static_cast<CellId>(i);
                    }
                  });
  // Pass 3: each cell written to its new place, its vertices and links moved to their new
  // slots, the links renamed.
  std::vector<Cell, HugePageAllocator<Cell>> out(live);
  on_stretches([&](std::size_t, std::size_t begin, std::size_t end) {
    for (std::size_t c = begin; c < end; ++c) {
      const Cell& k = cells[c];
      if (k.v[0] == RegularTriangulation3::kFreeMark) continue;
      Cell& o = out[new_id[c]];
      const unsigned mine = new_slot[c];
      for (unsigned j = 0; j < 4; ++j) {
        const unsigned to = (mine >> (2 * j)) & 3u;
        const std::uint32_t link = k.n[j];
        const CellId nb = link >> 2;
        o.v[to] = k.v[j];
        o.n[to] = new_id[nb] << 2 |
                  ((static_cast<unsigned>(new_slot[nb]) >> (2 * (link & 3u))) & 3u);
      }
    }
  });
  cells.swap(out);
  for (HiddenPoint& h : raw_hidden_) h.cell = h.cell < m ? new_id[h.cell] : kNoCell;
  t_.free_head_ = kNoCell;
  t_.free_count_ = 0;
}

void Builder::after_insertion(VertexId p) {
  if (!options_.after_insertion) return;
  t_.finalize(raw_hidden_);
  options_.after_insertion(t_, p);
}

// Picks a, b != a, c not collinear with a b, d not coplanar with a b c, scanning the
// insertion order, and moves them to its front. Returns whether (a, b, c, d) is negatively
// oriented.
bool Builder::choose_first_tetrahedron() {
  std::vector<VertexId>& order = t_.order_;
  const std::size_t n = order.size();
  std::size_t ib = 1;
  while (ib < n && points_[order[ib]] == points_[order[0]]) ++ib;
  if (n < 4 || ib == n) {
    throw InvalidInput("triangulation: fewer than 4 affinely independent points (" +
                       std::to_string(n) + " points, all equal" +
                       (n < 4 ? " or too few)" : ")"));
  }
  const Point3& a = points_[order[0]];
  const Point3& b = points_[order[ib]];
  std::size_t ic = ib + 1;
  while (ic < n && collinear(a, b, points_[order[ic]])) ++ic;
  if (ic == n) {
    throw InvalidInput("triangulation: fewer than 4 affinely independent points (all " +
                       std::to_string(n) + " points are collinear)");
  }
  const Point3& c = points_[order[ic]];
  std::size_t id = ic + 1;
  Sign o = Sign::zero;
  while (id < n && (o = pr::orient3d(a, b, c, points_[order[id]])) == Sign::zero) ++id;
  if (id == n) {
    throw InvalidInput("triangulation: all " + std::to_string(n) +
                       " points are coplanar; a 3D triangulation needs points spanning R^3");
  }
  // Move the four to the front, keeping the relative order of the others.
  const VertexId chosen[4] = {order[0], order[ib], order[ic], order[id]};
  std::size_t w = n;
  for (std::size_t r = n; r-- > 0;) {
    const VertexId v = order[r];
    if (v != chosen[0] && v != chosen[1] && v != chosen[2] && v != chosen[3]) order[--w] = v;
  }
  RSTRUCT_ASSERT(w == 4);
  for (int i = 0; i < 4; ++i) order[static_cast<std::size_t>(i)] = chosen[i];
  return o == Sign::negative;
}

void Builder::make_first_cells(const VertexId (&v)[4]) {
  auto& cells = t_.cells_;
  cells.push_back({{v[0], v[1], v[2], v[3]}, {0, 0, 0, 0}});
  for (int i = 0; i < 4; ++i) {
    Cell k = cells[0];
    k.v[i] = kInfiniteVertex;
    // Beyond facet i lies the side opposite v[i]: swap two other vertices to stay positive.
    const int s = (i + 1) & 3;
    const int u = (i + 2) & 3;
    std::swap(k.v[s], k.v[u]);
    cells.push_back(k);
  }
  marks_.assign(1, 0);
  // Link the five cells by matching facets (sorted vertex triples).
  const auto facet_key = [&](CellId c, int i) {
    std::array<VertexId, 3> f{};
    int m = 0;
    for (int j = 0; j < 4; ++j) {
      if (j != i) f[static_cast<std::size_t>(m++)] = cells[c].v[j];
    }
    std::sort(f.begin(), f.end());
    return f;
  };
  for (CellId c = 0; c < 5; ++c) {
    for (int i = 0; i < 4; ++i) {
      bool found = false;
      for (CellId d = 0; d < 5 && !found; ++d) {
        for (int j = 0; j < 4 && !found; ++j) {
          if (d != c && facet_key(c, i) == facet_key(d, j)) {
            cells[c].n[i] = d << 2 | static_cast<std::uint32_t>(j);
            found = true;
          }
        }
      }
      RSTRUCT_ASSERT(found);
    }
  }
  last_ = 0;
}

CellId Builder::append_cell() {
  auto& cells = t_.cells_;
  if (cells.size() >= kMaxCells) {
    throw InvalidInput("triangulation: more than 2^30 cells needed; the input is too large");
  }
  cells.push_back(Cell{});
  if (cells.size() > marks_.size() * 32) marks_.push_back(0);
  return static_cast<CellId>(cells.size() - 1);
}

bool Builder::in_conflict_general(CellId c, VertexId p) {
  const Cell& k = t_.cells_[c];
  const int inf = t_.infinite_index(c);
  if (inf < 0) {
    // in_conflict() tried both filter stages on this finite cell.
    ++stats_->filter_misses;
    if (weights_ == nullptr) {
      // A Delaunay vertex is removed only by a point with its exact coordinates; the
      // filter never decides such a test (the point's row of differences is zero, so the
      // computed value is exactly zero), so this is where duplicates show up.
      for (const VertexId v : k.v) {
        if (points_[v] == points_[p]) duplicate_of_ = v;
      }
      return pr::detail::insphere_sos_after_filter(
                 points_[k.v[0]], points_[k.v[1]], points_[k.v[2]], points_[k.v[3]],
                 points_[p], input_id(k.v[0]), input_id(k.v[1]), input_id(k.v[2]),
                 input_id(k.v[3]), input_id(p)) == Sign::positive;
    }
    const auto wp = [&](VertexId v) { return WeightedPoint{points_[v], weights_[v]}; };
    return pr::detail::power_test_sos_after_filter(
               wp(k.v[0]), wp(k.v[1]), wp(k.v[2]), wp(k.v[3]), wp(p), input_id(k.v[0]),
               input_id(k.v[1]), input_id(k.v[2]), input_id(k.v[3]),
               input_id(p)) == Sign::positive;
  }
  const int o = t_.orient_replaced(c, inf, points_[p], &*box_filter_);
  if (o != 0) return o > 0;
  // p lies in the plane of the hull facet: decide in that plane (2D power test).
  VertexId f[3];
  int m = 0;
  for (int j = 0; j < 4; ++j) {
    if (j != inf) f[m++] = k.v[j];
  }
  const auto wp = [&](VertexId v) {
    return WeightedPoint{points_[v], weights_ == nullptr ? 0.0 : weights_[v]};
  };
  return pr::coplanar_power_test_sos(wp(f[0]), wp(f[1]), wp(f[2]), wp(p), input_id(f[0]),
                                     input_id(f[1]), input_id(f[2]),
                                     input_id(p)) == Sign::positive;
}

void Builder::insert(VertexId p) {
  duplicate_of_ = kInfiniteVertex;
  bool conflict = false;
  const CellId c = locate_conflict(p, conflict, nullptr);
  if (!conflict) {
    record_hidden(p, c);
    return;
  }
  find_conflict_region(c, p);
  build_star(p);
  collect_hidden_vertices(duplicate_of_);
  for (const VertexId v : local_vertices_) vertex_local_[v] = 0;  // the boundary numbering
  release_conflict_region();
}

// Bowyer-Watson needs some cell in conflict with p, not necessarily the one containing
// it. The walk starts in the cell of the previous point's star (the cells just created
// around it, close in the BRIO order) whose centroid is nearest to p (nearest_star_cell);
// the conflict region of p covers a neighbourhood of p, so that cell is often in conflict
// already, and then the walk is skipped. Otherwise the walk ends at the cell containing p,
// which conflicts with p unless p is hidden: then `conflict` is false. (Testing for
// conflicts at every step of the walk as well was slower on points of a surface: a
// conflict cell met early can be a long thin cell far from p, and the next walk, started
// from the new cells next to it, gets long.)
CellId Builder::locate_conflict(VertexId p, bool& conflict, bool* blocked) {
  auto& stats = *stats_;
  CellId start = t_.is_cell(last_) ? last_ : t_.any_cell();
  if (star_is_latest_) start = nearest_star_cell(points_[p], start);
  ++stats.power_test_calls;
  if (in_conflict(start, p)) {
    conflict = true;
    return start;
  }
  const CellId c = blocked != nullptr
                       ? walk_owned(points_[p], start, *blocked)
                       : t_.walk(points_[p], start, rng_, stats.walk_steps, stats.orient_calls,
                                 &*box_filter_);
  if (locking_ && c != start) {
    keep_cell_locks(c);
    lock(p);  // released with the others if the insertion is deferred
  }
  if (blocked != nullptr && *blocked) return c;
  ++stats.power_test_calls;
  conflict = c == start ? false : in_conflict(c, p);
  return c;
}

void Builder::record_hidden(VertexId p, CellId c) {
  raw_hidden_.push_back({p, c});
  if (locking_) return;  // the walk starts from the kept star, whose locks are held
  last_ = c;
  star_is_latest_ = false;
}

// A floating-point construction (centroids and squared distances) that only chooses where
// the walk starts: the triangulation does not depend on it. Starting from an arbitrary
// cell of the previous star, the walk first had to turn around the previous point: 10^6
// uniform points took 5.6 walk steps per point, 3·10^5 points on a torus 37.7; from the
// nearest centroid 1.2 and 22.3 (torus insertion 2.95 -> 2.64 s, medians of 5 interleaved
// runs; uniform unchanged within the noise). The star's cells and
// points were just written or tested, so the scan runs in cache.
// When the star is the latest insertion's with its boundary numbered (build_star), the
// differences v - q are computed once per boundary vertex (the infinite vertex's are
// +inf, so its cells never win) and each cell adds its three and p's instead of reading
// four points (10^5 uniform points: 1,736 -> 1,149 instructions per point, callgrind).
// The minimum is kept in two lanes (10^6 uniform points: perf samples of this function
// 619 / 692 -> 487 / 443 at 4 kHz; four lanes took twice as many as one).
CellId Builder::nearest_star_cell(const Point3& q, CellId fallback) {
  const auto& cells = t_.cells_;
  CellId best = fallback;
  double best_distance = std::numeric_limits<double>::infinity();
  if (star_numbered_) {
    if constexpr (check_level() >= 2) {
      // star_local_ must still describe star_ (keep_cell_locks replaces star_ and clears
      // the flag): every cell (p, a, b, c) with a, b, c numbered as listed.
      RSTRUCT_ASSERT(star_local_.size() == star_.size());
      for (std::size_t s = 0; s < star_.size(); ++s) {
        const Cell& k = cells[star_[s]];
        RSTRUCT_ASSERT(k.v[0] == cells[star_.front()].v[0]);
        for (std::size_t j = 0; j < 3; ++j) {
          const std::size_t number = star_local_[s][j];
          RSTRUCT_ASSERT(k.v[j + 1] ==
                         (number == 0 ? kInfiniteVertex : local_vertices_[number - 1]));
        }
      }
    }
    constexpr double kInf = std::numeric_limits<double>::infinity();
    Point3* offset = star_offsets_.data();
    offset[0] = Point3{kInf, kInf, kInf};
    for (std::size_t k = 0; k < local_vertices_.size(); ++k) {
      offset[k + 1] = points_[local_vertices_[k]] - q;
    }
    const Point3 center = points_[cells[star_.front()].v[0]] - q;  // p, in every cell
    const auto distance = [&](std::size_t s) {
      const Point3 d = center + offset[star_local_[s][0]] + offset[star_local_[s][1]] +
                       offset[star_local_[s][2]];
      return d.x * d.x + d.y * d.y + d.z * d.z;
    };
    // Two running minima, of the even and of the odd cells, merged at the end (the first
    // of equal distances wins, as in one pass): each one's chain of comparisons is half
    // as long, and the start cell is waited for.
    const std::size_t m = star_.size();
    double even = best_distance, odd = best_distance;
    std::size_t even_at = 0, odd_at = 1;
    std::size_t s = 0;
    for (; s + 1 < m; s += 2) {
      const double de = distance(s);
      const double dd = distance(s + 1);
      even_at = de < even ? s : even_at;
      even = de < even ? de : even;
      odd_at = dd < odd ? s + 1 : odd_at;
      odd = dd < odd ? dd : odd;
    }
    if (s < m) {
      const double de = distance(s);
      even_at = de < even ? s : even_at;
      even = de < even ? de : even;
    }
    const bool take_odd = odd < even || (odd == even && odd_at < even_at);
    const double d2 = take_odd ? odd : even;
    if (d2 < best_distance) best = star_[take_odd ? odd_at : even_at];
    if constexpr (check_level() >= 2) {
      // The same cell as one pass over the star.
      CellId first = fallback;
      double nearest = best_distance;
      for (std::size_t t = 0; t < m; ++t) {
        const double d = distance(t);
        if (d < nearest) {
          nearest = d;
          first = star_[t];
        }
      }
      RSTRUCT_ASSERT(first == best);
    }
    return best;
  }
  for (const CellId n : star_) {
    const Cell& k = cells[n];
    if ((k.v[0] == kInfiniteVertex) | (k.v[1] == kInfiniteVertex) |
        (k.v[2] == kInfiniteVertex) | (k.v[3] == kInfiniteVertex)) {
      continue;
    }
    const double d2 = centroid_distance(n, q);
    if (d2 < best_distance) {
      best_distance = d2;
      best = n;
    }
  }
  return best;
}

void Builder::find_conflict_region(CellId start, VertexId p) {
  if (weights_ == nullptr) {
    find_conflict_region_impl<false, false>(start, p);
  } else {
    find_conflict_region_impl<true, false>(start, p);
  }
}

template <bool kWeighted, bool kOwned>
bool Builder::find_conflict_region_impl(CellId start, VertexId p) {
  auto& cells = t_.cells_;
  const auto prefetch_neighbors = [&](CellId c) {
    for (int i = 0; i < 4; ++i) __builtin_prefetch(&cells[cells[c].n[i] >> 2]);
  };
  conflict_.clear();
  outside_.clear();
  boundary_.clear();
  set_mark(start, kConflict);
  conflict_.push_back(start);
  prefetch_neighbors(start);
  // Breadth first, conflict_ being the queue: a cell joins the queue well before its
  // neighbours are tested, and its neighbours' cells are prefetched when it joins. When it
  // is taken from the queue, the new points of its neighbours are prefetched, all before
  // the first test: the tests then rarely wait for memory (cells and points of a cavity are
  // scattered over the arrays).
  for (std::size_t head = 0; head < conflict_.size(); ++head) {
    const CellId x = conflict_[head];
    const Cell& k = cells[x];
    conflict_.make_room(4);
    outside_.make_room(4);
    boundary_.make_room(8);
    // The filter values of the untested neighbours first, then the lists updated from
    // them: the (independent) evaluations overlap instead of waiting, one by one, and the
    // signs, hard to predict, choose where values are written rather than which code runs
    // (push_if, the mark and the prefetch's address).
    int untested[4];
    int count = 0;
    for (int i = 0; i < 4; ++i) {
      const CellId y = k.n[i] >> 2;
      const unsigned m = mark(y);
      // A worker never looks across a facet of shared vertices (see facet_is_shared).
      if constexpr (kOwned) {
        if (m == kNone && facet_is_shared(k, i)) return false;
      }
      untested[count] = i;
      count += static_cast<int>(m == kNone);
      boundary_.push_if({x, i}, m == kOutside);
      // y shares three vertices with x (whose test loaded them): only the one opposite
      // the shared facet is new.
      const VertexId v = cells[y].v[k.n[i] & 3u];
      if (v != kInfiniteVertex) {
        __builtin_prefetch(&points_[v]);
        if constexpr (kWeighted) __builtin_prefetch(&weights_[v]);
      }
    }
    int f[4];
    for (int j = 0; j < count; ++j) f[j] = filtered_conflict<kWeighted>(k.n[untested[j]] >> 2, p);
    for (int j = 0; j < count; ++j) {
      const int i = untested[j];
      const CellId y = k.n[i] >> 2;
      const bool conflict = f[j] != pr::detail::kUndecided ? f[j] > 0 : in_conflict_general(y, p);
      if constexpr (kOwned) {
        // y shares three of the worker's vertices with x: is the fourth its own too?
        if (conflict && !owned(cells[y].v[k.n[i] & 3u])) {
          set_mark(y, kOutside);  // marked, so that clear_conflict_marks() clears it
          outside_.push_back(y);
          return false;
        }
      }
      set_mark(y, conflict ? kConflict : kOutside);
      conflict_.push_if(y, conflict);
      outside_.push_if(y, !conflict);
      boundary_.push_if({x, i}, !conflict);
      // A cell joining the queue has its neighbours prefetched; otherwise the address is
      // x's, whose neighbours are in cache already.
      prefetch_neighbors(conflict ? y : x);
    }
  }
  stats_->conflict_cells += conflict_.size();
  // Every cell tested but the start (tested by insert()) is in conflict_ or outside_.
  stats_->power_test_calls += conflict_.size() - 1 + outside_.size();
  return true;
}

// One new cell per boundary facet (the facet joined to p), linked to the cell outside the
// cavity; the new cells are linked among themselves through the edge table (link_star).
// Every new cell is (p, a, b, c): p in slot 0, so that its facet 0 is the boundary facet and
// facets 1, 2, 3 are the ones through p, whatever the facet's index in the conflict cell
// (a, b, c in the order of kFacetOrder keep the orientation).
//
// The new cells' facets through p pair up along the edges of the cavity boundary, a
// triangulated sphere in which every edge lies in exactly two facets with opposite
// directions. Seen from outside a positively oriented cell (p, a, b, c), its facets 1, 2
// and 3 run counter-clockwise as (p, c, b), (p, a, c) and (p, b, a); the cell across each
// sees the same facet clockwise. With the boundary's vertices numbered 1..kLocal-1 (the
// infinite vertex 0), facet j of new cell n is written at slot [c][b], [a][c] or [b][a] of
// the edge table while the cell is built, and finds its partner at the reversed slot
// afterwards: no search, no branch. Larger cavities (degenerate input) use a hash table.
void Builder::build_star(VertexId p) {
  auto& cells = t_.cells_;
  const std::size_t m = boundary_.size();
  star_.resize(m);
  star_local_.resize(m);
  local_vertices_.clear();
  local_vertices_.make_room(kLocal);  // local_number's pushes
  for (std::size_t s = 0; s < m; ++s) {
    const BoundaryFacet& f = boundary_[s];
    const CellId n = new_cell();
    const Cell& x = cells[f.cell];
    const int i = f.index;
    const std::uint32_t out = x.n[i];
    const VertexId a = x.v[kFacetOrder[i][0]];
    const VertexId b = x.v[kFacetOrder[i][1]];
    const VertexId c = x.v[kFacetOrder[i][2]];
    Cell& k = cells[n];
    k.v[0] = p;
    k.v[1] = a;
    k.v[2] = b;
    k.v[3] = c;
    k.n[0] = out;
    cells[out >> 2].n[out & 3u] = n << 2;
    const std::size_t la = local_number(a);
    const std::size_t lb = local_number(b);
    const std::size_t lc = local_number(c);
    edge_faces_[lc * kLocal + lb] = n << 2 | 1u;
    edge_faces_[la * kLocal + lc] = n << 2 | 2u;
    edge_faces_[lb * kLocal + la] = n << 2 | 3u;
    star_local_[s] = {static_cast<std::uint8_t>(la), static_cast<std::uint8_t>(lb),
                      static_cast<std::uint8_t>(lc)};
    star_[s] = n;
  }
  link_star();
  last_ = star_.front();
  if (star_cell_ != nullptr) star_cell_[p] = last_;
  star_is_latest_ = true;
  star_numbered_ = local_vertices_.size() < kLocal - 1;
}

void Builder::link_star() {
  // With every number in use, a vertex may have gone unnumbered (0, like the infinite one).
  if (local_vertices_.size() == kLocal - 1) {
    ++stats_->large_cavities;
    link_star_hashed();
    return;
  }
  auto& cells = t_.cells_;
  const std::size_t m = star_.size();
  for (std::size_t s = 0; s < m; ++s) {
    Cell& k = cells[star_[s]];
    const std::size_t la = star_local_[s][0];
    const std::size_t lb = star_local_[s][1];
    const std::size_t lc = star_local_[s][2];
    k.n[1] = edge_faces_[lb * kLocal + lc];
    k.n[2] = edge_faces_[lc * kLocal + la];
    k.n[3] = edge_faces_[la * kLocal + lb];
  }
}

// Fallback for cavities with many boundary vertices: an open-addressing table keyed by the
// edge's vertex ids pairs the facets; stamps avoid clearing it.
void Builder::link_star_hashed() {
  auto& cells = t_.cells_;
  std::size_t size = 64;
  while (size < 4 * boundary_.size()) size *= 2;
  if (edge_table_.size() < size || ++stamp_ == 0) {
    edge_table_.assign(std::max(size, edge_table_.size()), EdgeSlot{0, 0, 0});
    stamp_ = 1;
  }
  const std::size_t mask = edge_table_.size() - 1;
  const int shift = 64 - std::countr_zero(edge_table_.size());
  for (std::size_t s = 0; s < star_.size(); ++s) {
    const CellId n = star_[s];
    for (int j = 1; j < 4; ++j) {  // the facets through p, in slot 0
      const int k = kOther[0][j][0];
      const int l = kOther[0][j][1];
      const VertexId a = cells[n].v[k];
      const VertexId b = cells[n].v[l];
      const std::uint64_t key = a < b ? (std::uint64_t{a} << 32 | b) : (std::uint64_t{b} << 32 | a);
      std::size_t h = static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> shift);
      const std::uint32_t self = n << 2 | static_cast<std::uint32_t>(j);
      for (;; h = (h + 1) & mask) {
        EdgeSlot& e = edge_table_[h];
        if (e.stamp != stamp_) {
          e = {key, self, stamp_};
          break;
        }
        if (e.key == key) {
          cells[n].n[j] = e.face;
          cells[e.face >> 2].n[e.face & 3u] = self;
          break;
        }
      }
    }
  }
}

// Weighted: a vertex of the cavity on no boundary facet is in no new cell, so p hides it.
// While the boundary's numbering (local_number, still set) is not full, the boundary
// vertices are exactly the numbered ones: the cavity's vertices are checked against the
// numbers. Otherwise every vertex of the cavity and of the star is marked in a per-point
// array (that general method took 9 % of the regular triangulation of a double torus's
// 85,237 surface balls).
void Builder::collect_hidden_vertices(VertexId duplicate_of) {
  const auto& cells = t_.cells_;
  if (weights_ == nullptr) {
    if (duplicate_of != kInfiniteVertex) raw_hidden_.push_back({duplicate_of, last_});
    return;
  }
  if (local_vertices_.size() < kLocal - 1) {
    constexpr std::uint8_t kSeen = 0xFF;  // above every number
    const std::size_t first = raw_hidden_.size();
    for (const CellId x : conflict_) {
      for (const VertexId v : cells[x].v) {
        if (v != kInfiniteVertex && vertex_local_[v] == 0) {
          vertex_local_[v] = kSeen;
          raw_hidden_.push_back({v, last_});
        }
      }
    }
    for (std::size_t i = first; i < raw_hidden_.size(); ++i) {
      vertex_local_[raw_hidden_[i].point] = 0;
    }
    return;
  }
  cavity_vertices_.clear();
  for (const CellId x : conflict_) {
    for (const VertexId v : cells[x].v) {
      if (v != kInfiniteVertex && vertex_mark_[v] == 0) {
        vertex_mark_[v] = 1;
        cavity_vertices_.push_back(v);
      }
    }
  }
  for (const CellId n : star_) {
    for (const VertexId v : cells[n].v) {
      if (v != kInfiniteVertex) vertex_mark_[v] = 2;
    }
  }
  for (const VertexId v : cavity_vertices_) {
    if (vertex_mark_[v] == 1) raw_hidden_.push_back({v, last_});
    vertex_mark_[v] = 0;
  }
  for (const CellId n : star_) {
    for (const VertexId v : cells[n].v) {
      if (v != kInfiniteVertex) vertex_mark_[v] = 0;
    }
  }
}

void Builder::release_conflict_region() {
  auto& cells = t_.cells_;
  for (const CellId x : conflict_) {
    cells[x].v[0] = RegularTriangulation3::kFreeMark;
    cells[x].n[0] = *free_head_;
    *free_head_ = x;
    set_mark(x, kNone);
  }
  *free_count_ += conflict_.size();
  for (const CellId y : outside_) set_mark(y, kNone);
}

}  // namespace rstruct::triangulation
