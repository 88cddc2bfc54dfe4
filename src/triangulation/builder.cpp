#include "builder.hpp"

#include <algorithm>
#include <numeric>
#include <string>

#include "rstruct/core/assert.hpp"
#include "rstruct/core/error.hpp"
#include "rstruct/core/stopwatch.hpp"
#include "rstruct/predicates/predicates.hpp"
#include "rstruct/triangulation/spatial_sort.hpp"

namespace rstruct::triangulation {

namespace pr = rstruct::predicates;

namespace {

constexpr std::uint32_t kUnlinked = 0xFFFFFFFFu;

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

Builder::Builder(RegularTriangulation3& t, const TriangulationOptions& options)
    : t_(t),
      options_(options),
      points_(t.points_.data()),
      weights_(t.weights_.empty() ? nullptr : t.weights_.data()),
      rng_(options.seed | 1u) {}

void Builder::run() {
  const std::size_t n = t_.points_.size();
  Stopwatch clock;
  if (options_.spatial_sort) {
    t_.order_ = brio_order(t_.points_, options_.seed);
  } else {
    t_.order_.resize(n);
    std::iota(t_.order_.begin(), t_.order_.end(), 0u);
  }
  t_.stats_.sort_seconds = clock.seconds();
  clock.reset();
  // Delaunay of uniform points has about 6.7 cells per point; pages never touched cost
  // nothing, so reserving generously avoids a reallocation (and its 2x peak) in practice.
  t_.cells_.reserve(n * 7 + n / 2 + 64);
  mark_.reserve(t_.cells_.capacity());
  if (weights_ != nullptr) vertex_mark_.assign(n, 0);
  choose_first_tetrahedron();
  t_.processed_ = 4;
  for (VertexId i = 0; i < 4; ++i) after_insertion(t_.order_[i]);
  for (std::size_t k = 4; k < n; ++k) {
    insert(t_.order_[k]);
    t_.processed_ = k + 1;
    after_insertion(t_.order_[k]);
  }
  t_.order_.clear();
  t_.order_.shrink_to_fit();
  mark_.clear();
  mark_.shrink_to_fit();
  vertex_mark_.clear();
  vertex_mark_.shrink_to_fit();
  t_.finalize(raw_hidden_);
  t_.stats_.insertion_seconds = clock.seconds();
}

void Builder::after_insertion(VertexId p) {
  if (!options_.after_insertion) return;
  t_.finalize(raw_hidden_);
  options_.after_insertion(t_, p);
}

// Picks a, b != a, c not collinear with a b, d not coplanar with a b c, scanning the
// insertion order, and moves them to its front.
void Builder::choose_first_tetrahedron() {
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
  VertexId first[4] = {order[0], order[ib], order[ic], order[id]};
  if (o == Sign::negative) std::swap(first[0], first[1]);
  // Move the four to the front, keeping the relative order of the others.
  const VertexId chosen[4] = {order[0], order[ib], order[ic], order[id]};
  std::size_t w = n;
  for (std::size_t r = n; r-- > 0;) {
    const VertexId v = order[r];
    if (v != chosen[0] && v != chosen[1] && v != chosen[2] && v != chosen[3]) order[--w] = v;
  }
  RSTRUCT_ASSERT(w == 4);
  for (int i = 0; i < 4; ++i) order[static_cast<std::size_t>(i)] = chosen[i];
  make_first_cells(first);
}

void Builder::make_first_cells(const VertexId (&v)[4]) {
  std::vector<Cell>& cells = t_.cells_;
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
  mark_.assign(cells.size(), kNone);
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

CellId Builder::new_cell() {
  std::vector<Cell>& cells = t_.cells_;
  if (t_.free_head_ != kNoCell) {
    const CellId c = t_.free_head_;
    t_.free_head_ = cells[c].n[0];
    --t_.free_count_;
    return c;
  }
  cells.push_back(Cell{});
  mark_.push_back(kNone);
  return static_cast<CellId>(cells.size() - 1);
}

bool Builder::in_conflict(CellId c, VertexId p) {
  const Cell& k = t_.cells_[c];
  const int inf = t_.infinite_index(c);
  ++t_.stats_.power_test_calls;
  if (inf < 0) {
    if (weights_ == nullptr) {
      return pr::insphere_sos(points_[k.v[0]], points_[k.v[1]], points_[k.v[2]],
                              points_[k.v[3]], points_[p], k.v[0], k.v[1], k.v[2], k.v[3],
                              p) == Sign::positive;
    }
    const auto wp = [&](VertexId v) { return WeightedPoint{points_[v], weights_[v]}; };
    return pr::power_test_sos(wp(k.v[0]), wp(k.v[1]), wp(k.v[2]), wp(k.v[3]), wp(p), k.v[0],
                              k.v[1], k.v[2], k.v[3], p) == Sign::positive;
  }
  const int o = t_.orient_replaced(c, inf, points_[p]);
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
  return pr::coplanar_power_test_sos(wp(f[0]), wp(f[1]), wp(f[2]), wp(p), f[0], f[1], f[2],
                                     p) == Sign::positive;
}

void Builder::insert(VertexId p) {
  const Point3& q = points_[p];
  const CellId c = t_.walk(q, t_.is_cell(last_) ? last_ : t_.any_cell(), rng_,
                           t_.stats_.walk_steps);
  if (!in_conflict(c, p)) {
    raw_hidden_.push_back({p, c});
    last_ = c;
    return;
  }
  // Delaunay: a vertex is hidden only by a point with its exact coordinates.
  VertexId duplicate_of = kInfiniteVertex;
  if (weights_ == nullptr) {
    for (const VertexId v : t_.cells_[c].v) {
      if (v != kInfiniteVertex && points_[v] == q) duplicate_of = v;
    }
  }
  find_conflict_region(c, p);
  build_star(p);
  collect_hidden_vertices(p, duplicate_of);
  release_conflict_region();
}

void Builder::find_conflict_region(CellId start, VertexId p) {
  conflict_.clear();
  outside_.clear();
  boundary_.clear();
  stack_.clear();
  mark_[start] = kConflict;
  stack_.push_back(start);
  while (!stack_.empty()) {
    const CellId x = stack_.back();
    stack_.pop_back();
    conflict_.push_back(x);
    for (int i = 0; i < 4; ++i) {
      const CellId y = t_.cells_[x].n[i] >> 2;
      const std::uint8_t m = mark_[y];
      if (m == kConflict) continue;
      if (m == kNone) {
        if (in_conflict(y, p)) {
          mark_[y] = kConflict;
          stack_.push_back(y);
          continue;
        }
        mark_[y] = kOutside;
        outside_.push_back(y);
      }
      boundary_.push_back({x, i});
    }
  }
  t_.stats_.conflict_cells += conflict_.size();
}

// One new cell per boundary facet (the facet joined to p); the conflict cell's link across
// that facet is redirected to the new cell so that link_star_face() can find it.
void Builder::build_star(VertexId p) {
  std::vector<Cell>& cells = t_.cells_;
  star_.clear();
  for (const BoundaryFacet& b : boundary_) {
    const CellId n = new_cell();
    Cell& k = cells[n];
    const Cell& x = cells[b.cell];
    const std::uint32_t out = x.n[b.index];
    for (int j = 0; j < 4; ++j) {
      k.v[j] = x.v[j];
      k.n[j] = kUnlinked;
    }
    k.v[b.index] = p;
    k.n[b.index] = out;
    const std::uint32_t self = n << 2 | static_cast<std::uint32_t>(b.index);
    cells[out >> 2].n[out & 3u] = self;
    cells[b.cell].n[b.index] = self;
    mark_[n] = kNew;
    star_.push_back(n);
  }
  for (std::size_t s = 0; s < star_.size(); ++s) {
    const CellId n = star_[s];
    for (int j = 0; j < 4; ++j) {
      if (cells[n].n[j] == kUnlinked) link_star_face(s, j);
    }
  }
  last_ = star_.front();
}

// New cell n = (conflict cell x with vertex i replaced by p). Its facet j contains p and the
// edge (a, b) of x's boundary facet; the new cell across it is found by turning around the
// edge (a, b) inside the cavity, starting from x across its facet j.
void Builder::link_star_face(std::size_t s, int j) {
  std::vector<Cell>& cells = t_.cells_;
  // n was built on boundary facet (x, i); p sits at index i of n.
  const CellId n = star_[s];
  const BoundaryFacet& origin = boundary_[s];
  const CellId x = origin.cell;
  const int i = origin.index;
  int other[2];
  int m = 0;
  for (int k = 0; k < 4; ++k) {
    if (k != i && k != j) other[m++] = k;
  }
  const VertexId a = cells[x].v[other[0]];
  const VertexId b = cells[x].v[other[1]];
  CellId z = x;
  int face = j;
  int entry = i;
  for (;;) {
    const std::uint32_t link = cells[z].n[face];
    const CellId y = link >> 2;
    const int e = static_cast<int>(link & 3u);
    if (mark_[y] == kNew) {
      // (z, face) is a boundary facet and y its new cell; p, a, b lie opposite z's
      // vertex at `entry`, which y keeps at the same index.
      cells[n].n[j] = y << 2 | static_cast<std::uint32_t>(entry);
      cells[y].n[entry] = n << 2 | static_cast<std::uint32_t>(j);
      return;
    }
    RSTRUCT_ASSERT(mark_[y] == kConflict);
    const int ia = t_.index(y, a);
    const int ib = t_.index(y, b);
    RSTRUCT_ASSERT(ia >= 0 && ib >= 0);
    entry = e;
    face = 6 - ia - ib - e;
    z = y;
  }
}

void Builder::collect_hidden_vertices(VertexId p, VertexId duplicate_of) {
  const std::vector<Cell>& cells = t_.cells_;
  if (weights_ == nullptr) {
    if (duplicate_of != kInfiniteVertex) raw_hidden_.push_back({duplicate_of, last_});
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
  (void)p;
}

void Builder::release_conflict_region() {
  std::vector<Cell>& cells = t_.cells_;
  for (const CellId x : conflict_) {
    cells[x].v[0] = RegularTriangulation3::kFreeMark;
    cells[x].n[0] = t_.free_head_;
    t_.free_head_ = x;
    mark_[x] = kNone;
  }
  t_.free_count_ += conflict_.size();
  for (const CellId y : outside_) mark_[y] = kNone;
  for (const CellId n : star_) mark_[n] = kNone;
}

}  // namespace rstruct::triangulation
