// RegularTriangulation3::is_valid(): combinatorics, then geometry with exact predicates.
// The geometric checks use the general perturbed power test even for unweighted input, so
// they also cross-check the in-sphere fast path of the construction.
#include <algorithm>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "rstruct/core/error.hpp"
#include "rstruct/predicates/predicates.hpp"
#include "rstruct/triangulation/regular_triangulation_3.hpp"

namespace rstruct::triangulation {

namespace pr = rstruct::predicates;

namespace {

class Checker {
 public:
  /// `processed[p]`: input point p has been inserted (or hidden, or merged) so far.
  Checker(const RegularTriangulation3& t, std::vector<char> processed)
      : t_(t), processed_(std::move(processed)) {}

  ValidityReport run();

 private:
  bool fail(const std::string& message) {
    report_.ok = false;
    report_.message = message;
    return false;
  }
  bool check_cells();
  bool check_euler();
  bool check_orientation_and_regularity();
  bool check_points();
  /// Perturbed conflict of input point p with cell c, from scratch (power test always).
  Sign conflict(CellId c, VertexId p) const;

  const RegularTriangulation3& t_;
  std::vector<char> processed_;
  ValidityReport report_;
  std::vector<char> used_;  // per input point: appears in a cell
  std::size_t live_ = 0;
};

std::string cell_text(const RegularTriangulation3& t, CellId c) {
  std::ostringstream s;
  s << "cell " << c << " (";
  for (int i = 0; i < 4; ++i) {
    const VertexId v = t.vertex(c, i);
    s << (i ? " " : "");
    if (v == kInfiniteVertex) {
      s << "inf";
    } else {
      s << v;
    }
  }
  s << ")";
  return s.str();
}

Sign Checker::conflict(CellId c, VertexId p) const {
  const auto v = t_.vertices(c);
  int inf = -1;
  for (int i = 0; i < 4; ++i) {
    if (v[i] == kInfiniteVertex) inf = i;
  }
  if (inf < 0) {
    return pr::power_test_sos(t_.weighted_point(v[0]), t_.weighted_point(v[1]),
                              t_.weighted_point(v[2]), t_.weighted_point(v[3]),
                              t_.weighted_point(p), v[0], v[1], v[2], v[3], p);
  }
  const Point3* q[4];
  for (int i = 0; i < 4; ++i) q[i] = i == inf ? &t_.point(p) : &t_.point(v[i]);
  const Sign o = pr::orient3d(*q[0], *q[1], *q[2], *q[3]);
  if (o != Sign::zero) return o;
  VertexId f[3];
  int m = 0;
  for (int i = 0; i < 4; ++i) {
    if (i != inf) f[m++] = v[i];
  }
  return pr::coplanar_power_test_sos(t_.weighted_point(f[0]), t_.weighted_point(f[1]),
                                     t_.weighted_point(f[2]), t_.weighted_point(p), f[0], f[1],
                                     f[2], p);
}

bool Checker::check_cells() {
  const std::size_t n = t_.number_of_points();
  used_.assign(n, 0);
  std::size_t infinite = 0;
  for (CellId c = 0; c < t_.cell_capacity(); ++c) {
    if (!t_.is_cell(c)) continue;
    ++live_;
    const auto v = t_.vertices(c);
    int inf = 0;
    for (int i = 0; i < 4; ++i) {
      if (v[i] == kInfiniteVertex) {
        ++inf;
        continue;
      }
      if (v[i] >= n) return fail(cell_text(t_, c) + " has a vertex id out of range");
      used_[v[i]] = 1;
      for (int j = 0; j < i; ++j) {
        if (v[j] == v[i]) return fail(cell_text(t_, c) + " repeats a vertex");
      }
    }
    if (inf > 1) return fail(cell_text(t_, c) + " has more than one infinite vertex");
    infinite += static_cast<std::size_t>(inf);
    for (int i = 0; i < 4; ++i) {
      const CellId d = t_.neighbor(c, i);
      const int m = t_.mirror_index(c, i);
      if (!t_.is_cell(d)) return fail(cell_text(t_, c) + ": neighbour " +
                                      std::to_string(i) + " is not a live cell");
      if (t_.neighbor(d, m) != c || t_.mirror_index(d, m) != i) {
        return fail(cell_text(t_, c) + ": neighbour " + std::to_string(i) +
                    " does not link back (mirror index)");
      }
      auto a = t_.facet_vertices({c, i});
      auto b = t_.facet_vertices({d, m});
      std::sort(a.begin(), a.end());
      std::sort(b.begin(), b.end());
      if (a != b) return fail(cell_text(t_, c) + " and " + cell_text(t_, d) +
                              " do not share their common facet");
    }
  }
  if (live_ != t_.number_of_cells()) return fail("cell count disagrees with the free list");
  if (t_.number_of_cells() - infinite != t_.number_of_finite_cells()) {
    return fail("finite cell count is stale");
  }
  for (VertexId v = 0; v < n; ++v) {
    if ((used_[v] != 0) != t_.is_vertex(v)) {
      return fail("point " + std::to_string(v) + ": incident_cell() disagrees with the cells");
    }
    if (used_[v] && t_.index(t_.incident_cell(v), v) < 0) {
      return fail("point " + std::to_string(v) + ": incident_cell() does not contain it");
    }
  }
  return true;
}

// V − E + F − C = 0 for a triangulated 3-sphere, and the cells form one connected piece.
bool Checker::check_euler() {
  std::size_t vertices = 1;  // the infinite vertex
  for (const char u : used_) vertices += u != 0;
  if (vertices - 1 != t_.number_of_vertices()) return fail("vertex count is stale");
  std::size_t edges = 0;
  for (CellId c = 0; c < t_.cell_capacity(); ++c) {
    if (!t_.is_cell(c)) continue;
    for (int i = 0; i < 4; ++i) {
      for (int j = i + 1; j < 4; ++j) {
        const std::vector<CellId> ring = t_.cells_around_edge({c, i, j});
        if (*std::min_element(ring.begin(), ring.end()) == c) ++edges;
      }
    }
  }
  const long long chi = static_cast<long long>(vertices) - static_cast<long long>(edges) +
                        2 * static_cast<long long>(live_) - static_cast<long long>(live_);
  if (chi != 0) {
    return fail("Euler characteristic V - E + F - C = " + std::to_string(chi) +
                " (expected 0 for the 3-sphere)");
  }
  std::vector<char> seen(t_.cell_capacity(), 0);
  std::vector<CellId> stack;
  for (CellId c = 0; c < t_.cell_capacity() && stack.empty(); ++c) {
    if (t_.is_cell(c)) stack.push_back(c), seen[c] = 1;
  }
  std::size_t reached = 0;
  while (!stack.empty()) {
    const CellId c = stack.back();
    stack.pop_back();
    ++reached;
    for (int i = 0; i < 4; ++i) {
      const CellId d = t_.neighbor(c, i);
      if (!seen[d]) seen[d] = 1, stack.push_back(d);
    }
  }
  if (reached != live_) return fail("the cells are not connected");
  return true;
}

bool Checker::check_orientation_and_regularity() {
  for (CellId c = 0; c < t_.cell_capacity(); ++c) {
    if (!t_.is_cell(c)) continue;
    const bool infinite = t_.is_infinite(c);
    if (!infinite) {
      const auto v = t_.vertices(c);
      if (pr::orient3d(t_.point(v[0]), t_.point(v[1]), t_.point(v[2]), t_.point(v[3])) !=
          Sign::positive) {
        return fail(cell_text(t_, c) + " is not positively oriented");
      }
    }
    for (int i = 0; i < 4; ++i) {
      const CellId d = t_.neighbor(c, i);
      const VertexId x = t_.vertex(d, t_.mirror_index(c, i));
      if (x == kInfiniteVertex) continue;  // never in conflict with a finite cell
      if (conflict(c, x) != Sign::negative) {
        return fail("facet " + std::to_string(i) + " of " + cell_text(t_, c) +
                    " is not locally regular: vertex " + std::to_string(x) + " of " +
                    cell_text(t_, d) + " is in conflict with it");
      }
    }
  }
  return true;
}

// Every processed point is exactly one of: a vertex, hidden (inside its reported cell and
// not in conflict with it), merged (same coordinates as its vertex, not in conflict with a
// cell of it). Unprocessed points are none of these.
bool Checker::check_points() {
  const std::size_t n = t_.number_of_points();
  std::vector<char> reported(n, 0);
  for (const HiddenPoint& h : t_.hidden_points()) {
    const std::string what = "hidden point " + std::to_string(h.point);
    if (h.point >= n || reported[h.point]++) return fail(what + " reported twice or invalid");
    if (used_[h.point]) return fail(what + " is a vertex");
    if (!t_.is_cell(h.cell) || t_.is_infinite(h.cell)) {
      return fail(what + " is not reported with a live finite cell");
    }
    const auto v = t_.vertices(h.cell);
    for (int i = 0; i < 4; ++i) {
      const Point3* q[4];
      for (int j = 0; j < 4; ++j) q[j] = i == j ? &t_.point(h.point) : &t_.point(v[j]);
      if (pr::orient3d(*q[0], *q[1], *q[2], *q[3]) == Sign::negative) {
        return fail(what + " is outside its " + cell_text(t_, h.cell));
      }
      if (t_.point(v[i]) == t_.point(h.point)) {
        return fail(what + " coincides with vertex " + std::to_string(v[i]) +
                    " but is not reported as a duplicate");
      }
    }
    if (conflict(h.cell, h.point) != Sign::negative) {
      return fail(what + " has non-positive power against the orthosphere of " +
                  cell_text(t_, h.cell));
    }
  }
  for (const DuplicatePoint& d : t_.duplicate_points()) {
    const std::string what = "duplicate point " + std::to_string(d.point);
    if (d.point >= n || reported[d.point]++) return fail(what + " reported twice or invalid");
    if (used_[d.point]) return fail(what + " is a vertex");
    if (d.vertex >= n || !used_[d.vertex]) return fail(what + ": its vertex is not a vertex");
    if (t_.point(d.vertex) != t_.point(d.point)) {
      return fail(what + " does not have the coordinates of vertex " + std::to_string(d.vertex));
    }
    CellId finite = kNoCell;
    for (const CellId c : t_.incident_cells(d.vertex)) {
      if (!t_.is_infinite(c)) finite = c;
    }
    if (finite == kNoCell || conflict(finite, d.point) != Sign::negative) {
      return fail(what + " would win against vertex " + std::to_string(d.vertex) +
                  " (larger or perturbed-larger weight)");
    }
  }
  for (VertexId p = 0; p < n; ++p) {
    const bool accounted = used_[p] || reported[p];
    if (processed_[p] && !accounted) {
      return fail("point " + std::to_string(p) + " is neither a vertex, hidden nor merged");
    }
    if (!processed_[p] && accounted) {
      return fail("point " + std::to_string(p) + " is accounted for before its insertion");
    }
  }
  return true;
}

ValidityReport Checker::run() {
  try {
    if (check_cells() && check_euler() && check_orientation_and_regularity()) check_points();
  } catch (const Error& e) {
    fail(std::string("exception during the check: ") + e.what());
  }
  return report_;
}

}  // namespace

ValidityReport RegularTriangulation3::is_valid() const {
  std::vector<char> processed(points_.size(), order_.empty() ? 1 : 0);
  if (!order_.empty()) {
    for (std::size_t k = 0; k < processed_; ++k) processed[order_[k]] = 1;
  }
  return Checker(*this, std::move(processed)).run();
}

}  // namespace rstruct::triangulation
