#include "rstruct/triangulation/regular_triangulation_3.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_set>

#include "builder.hpp"
#include "rstruct/core/assert.hpp"
#include "rstruct/core/error.hpp"
#include "rstruct/predicates/almost_static_filter.hpp"
#include "rstruct/predicates/predicates.hpp"

namespace rstruct::triangulation {

namespace pr = rstruct::predicates;

namespace {

void validate_points(const std::vector<Point3>& points) {
  if (points.size() > kMaxPoints) {
    throw InvalidInput("triangulation: " + std::to_string(points.size()) +
                       " points exceed the supported maximum of " + std::to_string(kMaxPoints));
  }
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!is_finite(points[i])) {
      throw InvalidInput("triangulation: point " + std::to_string(i) +
                         " has a non-finite coordinate");
    }
  }
}

std::uint64_t next_bits(std::uint64_t& s) {
  s ^= s << 13;
  s ^= s >> 7;
  s ^= s << 17;
  return s;
}

}  // namespace

RegularTriangulation3::RegularTriangulation3(std::vector<Point3> points,
                                             const TriangulationOptions& options)
    : points_(std::move(points)) {
  validate_points(points_);
  Builder(*this, options).run();
  if (check_level() >= 2 && points_.size() <= 100000) {
    const ValidityReport r = is_valid();
    RSTRUCT_ASSERT_MSG(r.ok, r.message);
  }
}

RegularTriangulation3::RegularTriangulation3(std::vector<Point3> points,
                                             std::vector<double> weights,
                                             const TriangulationOptions& options)
    : points_(std::move(points)), weights_(std::move(weights)) {
  if (weights_.size() != points_.size()) {
    throw InvalidInput("triangulation: " + std::to_string(points_.size()) + " points but " +
                       std::to_string(weights_.size()) + " weights");
  }
  validate_points(points_);
  for (std::size_t i = 0; i < weights_.size(); ++i) {
    if (!std::isfinite(weights_[i])) {
      throw InvalidInput("triangulation: weight of point " + std::to_string(i) +
                         " is not finite");
    }
  }
  Builder(*this, options).run();
  if (check_level() >= 2 && points_.size() <= 100000) {
    const ValidityReport r = is_valid();
    RSTRUCT_ASSERT_MSG(r.ok, r.message);
  }
}

RegularTriangulation3::RegularTriangulation3(std::vector<Point3> points,
                                             const TriangulationOptions& options, CellsOnly)
    : points_(std::move(points)) {
  validate_points(points_);
  Builder(*this, options, Builder::Finish::cells_only).run();
}

DelaunayCells RegularTriangulation3::delaunay_cells(std::vector<Point3> points,
                                                    const TriangulationOptions& options) {
  // A caller watching the insertions, or a canonical order, gets the full construction
  // (its cells and reports in input ids, order_ cleared). Otherwise Builder::run leaves
  // them in ranks (order_ kept) or in input ids (order_ empty).
  const bool full =
      options.after_insertion || options.canonical_order || options.canonical_order_after_locks;
  RegularTriangulation3 t = full ? RegularTriangulation3(std::move(points), options)
                                 : RegularTriangulation3(std::move(points), options, CellsOnly{});
  const VertexId* rename = t.order_.empty() ? nullptr : t.order_.data();
  if (!t.hidden_.empty()) {
    throw InternalError("delaunay_cells: the Delaunay triangulation hid point " +
                        std::to_string(rename != nullptr ? rename[t.hidden_.front().point]
                                                         : t.hidden_.front().point));
  }
  DelaunayCells result;
  result.duplicates = std::move(t.duplicates_);
  if (rename != nullptr) {
    for (DuplicatePoint& d : result.duplicates) d = {rename[d.point], rename[d.vertex]};
    std::sort(result.duplicates.begin(), result.duplicates.end(),
              [](const DuplicatePoint& a, const DuplicatePoint& b) { return a.point < b.point; });
  }
  result.stats = t.stats_;
  result.cells = t.take_finite_cells(options.threads, rename, true);
  return result;
}

RegularTriangulation3::RegularTriangulation3(RegularTriangulation3&&) noexcept = default;
RegularTriangulation3& RegularTriangulation3::operator=(RegularTriangulation3&&) noexcept =
    default;
RegularTriangulation3::~RegularTriangulation3() = default;

bool RegularTriangulation3::is_infinite(CellId c) const { return infinite_index(c) >= 0; }

bool RegularTriangulation3::is_infinite(const Facet& f) const {
  const int k = infinite_index(f.cell);
  return k >= 0 && k != f.index;
}

bool RegularTriangulation3::is_infinite(const Edge& e) const {
  return vertex(e.cell, e.i) == kInfiniteVertex || vertex(e.cell, e.j) == kInfiniteVertex;
}

int RegularTriangulation3::index(CellId c, VertexId v) const {
  const Cell& k = cells_[c];
  for (int i = 0; i < 4; ++i) {
    if (k.v[i] == v) return i;
  }
  return -1;
}

std::array<VertexId, 3> RegularTriangulation3::facet_vertices(const Facet& f) const {
  // (i, a, b, c) an even permutation of (0, 1, 2, 3).
  static constexpr int kOrder[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  const Cell& k = cells_[f.cell];
  const int* o = kOrder[f.index];
  return {k.v[o[0]], k.v[o[1]], k.v[o[2]]};
}

int RegularTriangulation3::orient_replaced(CellId c, int i, const Point3& q,
                                           const pr::AlmostStaticFilter* filter) const {
  const Cell& k = cells_[c];
  const Point3* p[4];
  for (int j = 0; j < 4; ++j) p[j] = j == i ? &q : &points_[k.v[j]];
  if (filter != nullptr) return to_int(filter->orient3d_two_stage(*p[0], *p[1], *p[2], *p[3]));
  return to_int(pr::orient3d(*p[0], *p[1], *p[2], *p[3]));
}

CellId RegularTriangulation3::any_cell() const {
  for (CellId c = 0; c < cells_.size(); ++c) {
    if (cells_[c].v[0] != kFreeMark) return c;
  }
  return kNoCell;
}

// The facet of finite cell c (not the one towards `previous`) that the line through o
// with direction w = q − o crosses, or −1: a facet is crossed iff the three values
// det(w, a − o, b − o) of its edges (a, b), taken around it, have one sign. Floating
// point, and only a preference of the walk.
int RegularTriangulation3::segment_exit_facet(CellId c, const Point3& o, double wx, double wy,
                                              double wz, CellId previous) const {
  double d[4][3];
  for (int j = 0; j < 4; ++j) {
    const Point3& v = points_[cells_[c].v[j]];
    d[j][0] = v.x - o.x;
    d[j][1] = v.y - o.y;
    d[j][2] = v.z - o.z;
  }
  const auto edge = [&](int a, int b) {
    const double cx = d[a][1] * d[b][2] - d[a][2] * d[b][1];
    const double cy = d[a][2] * d[b][0] - d[a][0] * d[b][2];
    const double cz = d[a][0] * d[b][1] - d[a][1] * d[b][0];
    return wx * cx + wy * cy + wz * cz;
  };
  const double e01 = edge(0, 1), e02 = edge(0, 2), e03 = edge(0, 3), e12 = edge(1, 2),
               e13 = edge(1, 3), e23 = edge(2, 3);
  // Facet i is the triangle of the other three vertices (a, b, c): edges ab, bc, ca.
  const double around[4][3] = {
      {e12, e23, -e13}, {e02, e23, -e03}, {e01, e13, -e03}, {e01, e12, -e02}};
  for (int i = 0; i < 4; ++i) {
    if (neighbor(c, i) == previous) continue;
    const double* f = around[i];
    if ((f[0] > 0 && f[1] > 0 && f[2] > 0) || (f[0] < 0 && f[1] < 0 && f[2] < 0)) return i;
  }
  return -1;
}

CellId RegularTriangulation3::walk(const Point3& q, CellId start, std::uint64_t& rng,
                                   std::uint64_t& steps, std::uint64_t& orients,
                                   const pr::AlmostStaticFilter* filter) const {
  CellId c = start;
  CellId previous = kNoCell;
  // The walk prefers, among the facets q is beyond, the one the segment from the start
  // cell's centroid o to q leaves through: it then follows the segment instead of
  // wandering. Points on a surface make long thin cells, through which a walk choosing at
  // random zig-zags: 10^6 points on a torus took 33 steps per point (one walk of 11,380
  // steps covered 9 sample spacings), 14 with the segment (3·10^5 points: 22.3 -> 11.5
  // steps, insertion 2.73 -> 2.54 s). The segment test is a floating-point heuristic
  // (a wrong answer only costs steps): every move still crosses a facet that the exact
  // orientation puts q strictly beyond, and any such walk terminates in a regular
  // triangulation (Edelsbrunner's acyclicity theorem); the random order remains for the
  // rest.
  bool follow_segment = infinite_index(c) < 0;
  Point3 o{0, 0, 0};
  if (follow_segment) {
    for (int j = 0; j < 4; ++j) {
      const Point3& v = points_[cells_[c].v[j]];
      o.x += 0.25 * v.x;
      o.y += 0.25 * v.y;
      o.z += 0.25 * v.z;
    }
  }
  const double wx = q.x - o.x, wy = q.y - o.y, wz = q.z - o.z;
  // The stochastic walk terminates with probability 1 (Devillers, Pion & Teillaud); the
  // bound only turns a pathological run into a linear scan.
  const std::size_t limit = 4 * cells_.size() + 1000;
  for (std::size_t step = 0; step < limit; ++step) {
    ++steps;
    const int inf = infinite_index(c);
    if (inf >= 0) {
      const CellId inner = neighbor(c, inf);
      if (previous == inner) return c;
      ++orients;
      if (orient_replaced(c, inf, q, filter) > 0) return c;
      previous = c;
      c = inner;
      follow_segment = false;  // beyond the hull: the segment is left behind
      continue;
    }
    // The next cell is one of the neighbours: start their loads before the tests.
    for (int i = 0; i < 4; ++i) __builtin_prefetch(&cells_[cells_[c].n[i] >> 2]);
    if (follow_segment) {
      const int exit = segment_exit_facet(c, o, wx, wy, wz, previous);
      if (exit >= 0) {
        ++orients;
        if (orient_replaced(c, exit, q, filter) < 0) {
          previous = c;
          c = neighbor(c, exit);
          continue;
        }
      }
    }
    const int r = static_cast<int>(next_bits(rng) & 3u);
    bool moved = false;
    for (int t = 0; t < 4; ++t) {
      const int i = (r + t) & 3;
      const CellId next = neighbor(c, i);
      if (next == previous) continue;
      ++orients;
      if (orient_replaced(c, i, q, filter) < 0) {
        previous = c;
        c = next;
        moved = true;
        break;
      }
    }
    if (!moved) return c;
  }
  // Linear scan: a finite cell containing q, else an infinite cell q is strictly beyond.
  CellId beyond = kNoCell;
  for (CellId d = 0; d < cells_.size(); ++d) {
    if (cells_[d].v[0] == kFreeMark) continue;
    const int inf = infinite_index(d);
    if (inf >= 0) {
      if (beyond == kNoCell && orient_replaced(d, inf, q) > 0) beyond = d;
      continue;
    }
    bool inside = true;
    for (int i = 0; i < 4 && inside; ++i) inside = orient_replaced(d, i, q) >= 0;
    if (inside) return d;
  }
  RSTRUCT_ASSERT_MSG(beyond != kNoCell, "point location failed");
  return beyond;
}

CellId RegularTriangulation3::locate(const Point3& q, CellId hint) const {
  RSTRUCT_ASSERT_MSG(!cells_.empty(), "locate in an empty triangulation");
  std::uint64_t rng = 0x2545F4914F6CDD1Dull;
  std::uint64_t steps = 0;
  std::uint64_t orients = 0;
  return walk(q, is_cell(hint) ? hint : any_cell(), rng, steps, orients);
}

void RegularTriangulation3::finalize(std::span<const HiddenPoint> raw_hidden) {
  vertex_cell_.assign(points_.size(), kNoCell);
  infinite_count_ = 0;
  for (CellId c = 0; c < cells_.size(); ++c) {
    const Cell& k = cells_[c];
    if (k.v[0] == kFreeMark) continue;
    for (const VertexId v : k.v) {
      if (v == kInfiniteVertex) {
        ++infinite_count_;
      } else {
        vertex_cell_[v] = c;
      }
    }
  }
  number_of_vertices_ = static_cast<std::size_t>(
      std::count_if(vertex_cell_.begin(), vertex_cell_.end(),
                    [](CellId c) { return c != kNoCell; }));
  resolve_hidden(raw_hidden);
}

void RegularTriangulation3::resolve_hidden(std::span<const HiddenPoint> raw_hidden) {
  hidden_.clear();
  duplicates_.clear();
  std::uint64_t rng = 0x853C49E6748FEA9Bull;
  std::uint64_t steps = 0;
  CellId start = any_cell();
  for (const HiddenPoint& h : raw_hidden) {
    const Point3& q = points_[h.point];
    const CellId c = walk(q, is_cell(h.cell) ? h.cell : start, rng, steps, steps);
    start = c;
    VertexId same = kInfiniteVertex;
    for (const VertexId v : cells_[c].v) {
      if (v != kInfiniteVertex && points_[v] == q) same = v;
    }
    if (same != kInfiniteVertex) {
      duplicates_.push_back({h.point, same});
    } else {
      hidden_.push_back({h.point, c});
    }
  }
  std::sort(hidden_.begin(), hidden_.end(),
            [](const HiddenPoint& a, const HiddenPoint& b) { return a.point < b.point; });
  std::sort(duplicates_.begin(), duplicates_.end(),
            [](const DuplicatePoint& a, const DuplicatePoint& b) { return a.point < b.point; });
}

void RegularTriangulation3::incident_cells(VertexId v, std::vector<CellId>& out) const {
  out.clear();
  const CellId start = incident_cell(v);
  if (start == kNoCell) return;
  out.push_back(start);
  std::unordered_set<CellId> seen;  // used only for high-degree vertices
  constexpr std::size_t kLinear = 48;
  for (std::size_t k = 0; k < out.size(); ++k) {
    const CellId c = out[k];
    for (int i = 0; i < 4; ++i) {
      if (cells_[c].v[i] == v) continue;
      const CellId n = neighbor(c, i);
      bool known;
      if (out.size() <= kLinear) {
        known = std::find(out.begin(), out.end(), n) != out.end();
      } else {
        if (seen.empty()) seen.insert(out.begin(), out.end());
        known = seen.count(n) != 0;
      }
      if (!known) {
        out.push_back(n);
        if (!seen.empty()) seen.insert(n);
      }
    }
  }
}

std::vector<CellId> RegularTriangulation3::incident_cells(VertexId v) const {
  std::vector<CellId> out;
  incident_cells(v, out);
  return out;
}

std::vector<VertexId> RegularTriangulation3::adjacent_vertices(VertexId v) const {
  std::vector<VertexId> out;
  for (const CellId c : incident_cells(v)) {
    for (const VertexId u : cells_[c].v) {
      if (u != v && u != kInfiniteVertex) out.push_back(u);
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

bool RegularTriangulation3::is_on_convex_hull(VertexId v) const {
  for (const CellId c : incident_cells(v)) {
    if (is_infinite(c)) return true;
  }
  return false;
}

std::vector<CellId> RegularTriangulation3::cells_around_edge(const Edge& e) const {
  const VertexId a = vertex(e.cell, e.i);
  const VertexId b = vertex(e.cell, e.j);
  int face = 0;
  while (face == e.i || face == e.j) ++face;
  std::vector<CellId> out;
  CellId c = e.cell;
  do {
    out.push_back(c);
    RSTRUCT_ASSERT_MSG(out.size() <= cells_.size(), "cells around an edge do not close");
    const CellId next = neighbor(c, face);
    const int entry = mirror_index(c, face);
    const int ia = index(next, a);
    const int ib = index(next, b);
    RSTRUCT_ASSERT(ia >= 0 && ib >= 0);
    face = 6 - ia - ib - entry;
    c = next;
  } while (c != e.cell);
  return out;
}

std::vector<CellId> RegularTriangulation3::finite_cells() const {
  std::vector<CellId> out;
  out.reserve(number_of_finite_cells());
  for_each_finite_cell([&](CellId c) { out.push_back(c); });
  return out;
}

std::vector<Facet> RegularTriangulation3::convex_hull_facets() const {
  std::vector<Facet> out;
  for_each_cell([&](CellId c) {
    const int inf = infinite_index(c);
    if (inf >= 0) out.push_back(mirror_facet({c, inf}));
  });
  return out;
}

}  // namespace rstruct::triangulation
