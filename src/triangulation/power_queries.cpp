// Double constructions (circum/orthocentres) and power-diagram queries of
// RegularTriangulation3.
#include <cmath>
#include <gmpxx.h>
#include <string>

#include "rstruct/core/assert.hpp"
#include "rstruct/core/error.hpp"
#include "rstruct/predicates/predicates.hpp"
#include "rstruct/triangulation/regular_triangulation_3.hpp"

namespace rstruct::triangulation {

namespace pr = rstruct::predicates;

namespace {

struct Sphere {
  Point3 centre;
  double squared_radius;
};

/// Exact y (centre − a) of the orthosphere, rounded once per coordinate: the same formula
/// as below over GMP rationals. \pre abcd not flat.
Vec3 exact_offset(const Point3& a, double wa, const Point3& b, double wb, const Point3& c,
                  double wc, const Point3& d, double wd) {
  mpq_class u[3], v[3], w[3];
  for (std::size_t i = 0; i < 3; ++i) {
    u[i] = mpq_class(b[i]) - mpq_class(a[i]);
    v[i] = mpq_class(c[i]) - mpq_class(a[i]);
    w[i] = mpq_class(d[i]) - mpq_class(a[i]);
  }
  const mpq_class vw[3] = {v[1] * w[2] - v[2] * w[1], v[2] * w[0] - v[0] * w[2],
                           v[0] * w[1] - v[1] * w[0]};
  const mpq_class wu[3] = {w[1] * u[2] - w[2] * u[1], w[2] * u[0] - w[0] * u[2],
                           w[0] * u[1] - w[1] * u[0]};
  const mpq_class uv[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                           u[0] * v[1] - u[1] * v[0]};
  const mpq_class den = 2 * (u[0] * vw[0] + u[1] * vw[1] + u[2] * vw[2]);
  RSTRUCT_ASSERT_MSG(sgn(den) != 0, "orthosphere of a flat cell");
  const mpq_class qa(wa);
  const mpq_class su = u[0] * u[0] + u[1] * u[1] + u[2] * u[2] - mpq_class(wb) + qa;
  const mpq_class sv = v[0] * v[0] + v[1] * v[1] + v[2] * v[2] - mpq_class(wc) + qa;
  const mpq_class sw = w[0] * w[0] + w[1] * w[1] + w[2] * w[2] - mpq_class(wd) + qa;
  Vec3 y;
  for (std::size_t i = 0; i < 3; ++i) {
    const mpq_class x = (su * vw[i] + sv * wu[i] + sw * uv[i]) / den;
    y[i] = x.get_d();
  }
  return y;
}

/// The sphere orthogonal to four weighted points: with u = b − a etc. and lifted values
/// s_u = |u|² − w_b + w_a, the centre a + y solves 2 u·y = s_u (three equations), and the
/// squared radius is |y|² − w_a. Solved by Cramer's rule with cross products in doubles
/// when the cell is well shaped; when |det| < 2⁻²⁶·|u||v||w| (slivers, nearly flat cells,
/// where the double centre can be off by many circumradii) y is computed exactly with
/// rationals and rounded once. The lemma tests found double centres of sliver Delaunay
/// cells several local feature sizes away from the exact ones.
Sphere orthosphere(const Point3& a, double wa, const Point3& b, double wb, const Point3& c,
                   double wc, const Point3& d, double wd) {
  const Vec3 u = b - a;
  const Vec3 v = c - a;
  const Vec3 w = d - a;
  const double su = squared_norm(u) - wb + wa;
  const double sv = squared_norm(v) - wc + wa;
  const double sw = squared_norm(w) - wd + wa;
  const Vec3 vw = cross(v, w);
  const Vec3 wu = cross(w, u);
  const Vec3 uv = cross(u, v);
  const double det = dot(u, vw);
  const double scale = std::sqrt(squared_norm(u) * squared_norm(v) * squared_norm(w));
  Vec3 y;
  if (std::isfinite(det) && std::fabs(det) > 0x1p-26 * scale) {
    y = (su * vw + sv * wu + sw * uv) / (2.0 * det);
  } else {
    y = exact_offset(a, wa, b, wb, c, wc, d, wd);
  }
  return {a + y, squared_norm(y) - wa};
}

}  // namespace

Point3 RegularTriangulation3::circumcenter(CellId c) const {
  RSTRUCT_ASSERT_MSG(is_cell(c) && !is_infinite(c), "circumcenter of an infinite cell");
  const Cell& k = cells_[c];
  return orthosphere(points_[k.v[0]], 0, points_[k.v[1]], 0, points_[k.v[2]], 0,
                     points_[k.v[3]], 0)
      .centre;
}

double RegularTriangulation3::squared_circumradius(CellId c) const {
  RSTRUCT_ASSERT_MSG(is_cell(c) && !is_infinite(c), "circumradius of an infinite cell");
  const Cell& k = cells_[c];
  return orthosphere(points_[k.v[0]], 0, points_[k.v[1]], 0, points_[k.v[2]], 0,
                     points_[k.v[3]], 0)
      .squared_radius;
}

Point3 RegularTriangulation3::orthocenter(CellId c) const {
  RSTRUCT_ASSERT_MSG(is_cell(c) && !is_infinite(c), "orthocenter of an infinite cell");
  const Cell& k = cells_[c];
  return orthosphere(points_[k.v[0]], weight(k.v[0]), points_[k.v[1]], weight(k.v[1]),
                     points_[k.v[2]], weight(k.v[2]), points_[k.v[3]], weight(k.v[3]))
      .centre;
}

double RegularTriangulation3::squared_orthoradius(CellId c) const {
  RSTRUCT_ASSERT_MSG(is_cell(c) && !is_infinite(c), "orthoradius of an infinite cell");
  const Cell& k = cells_[c];
  return orthosphere(points_[k.v[0]], weight(k.v[0]), points_[k.v[1]], weight(k.v[1]),
                     points_[k.v[2]], weight(k.v[2]), points_[k.v[3]], weight(k.v[3]))
      .squared_radius;
}

std::vector<CellId> RegularTriangulation3::power_cell_vertices(VertexId v) const {
  if (!is_vertex(v)) {
    throw InvalidInput("power_cell_vertices: point " + std::to_string(v) + " is not a vertex");
  }
  std::vector<CellId> out;
  for (const CellId c : incident_cells(v)) {
    if (!is_infinite(c)) out.push_back(c);
  }
  return out;
}

DualSegment RegularTriangulation3::dual(const Facet& f) const {
  if (is_infinite(f)) {
    throw InvalidInput("dual: the facet has the infinite vertex (no power-diagram edge)");
  }
  const Facet g = mirror_facet(f);
  const bool f_inf = is_infinite(f.cell);
  const bool g_inf = is_infinite(g.cell);
  DualSegment out;
  if (!f_inf && !g_inf) {
    out.source = orthocenter(f.cell);
    out.target = orthocenter(g.cell);
    return out;
  }
  const Facet inner = f_inf ? g : f;  // the finite cell's side; the facet is on the hull
  const std::array<VertexId, 3> t = facet_vertices(inner);
  out.source = orthocenter(inner.cell);
  out.target = out.source;
  out.direction = cross(points_[t[1]] - points_[t[0]], points_[t[2]] - points_[t[0]]);
  out.is_ray = true;
  return out;
}

VertexId RegularTriangulation3::nearest_power_vertex(const Point3& q, CellId hint) const {
  const CellId c = locate(q, hint);
  VertexId best = kInfiniteVertex;
  for (const VertexId v : cells_[c].v) {
    if (v == kInfiniteVertex) continue;
    if (best == kInfiniteVertex ||
        pr::compare_power_distance(q, weighted_point(v), weighted_point(best)) ==
            Sign::negative) {
      best = v;
    }
  }
  // Greedy descent in the adjacency graph: a power cell is cut out by the vertex's
  // neighbours alone, so a vertex with no nearer neighbour owns q; the power distance
  // decreases strictly, so the descent ends.
  std::vector<CellId> around;
  for (bool improved = true; improved;) {
    improved = false;
    incident_cells(best, around);
    for (const CellId d : around) {
      for (const VertexId u : cells_[d].v) {
        if (u == kInfiniteVertex || u == best) continue;
        if (pr::compare_power_distance(q, weighted_point(u), weighted_point(best)) ==
            Sign::negative) {
          best = u;
          improved = true;
          break;
        }
      }
      if (improved) break;
    }
  }
  return best;
}

}  // namespace rstruct::triangulation
