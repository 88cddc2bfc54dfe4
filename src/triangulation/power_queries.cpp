// Double constructions (circum/orthocentres) and power-diagram queries of
// RegularTriangulation3.
#include <string>

#include "rstruct/core/assert.hpp"
#include "rstruct/core/error.hpp"
#include "rstruct/predicates/predicates.hpp"
#include "rstruct/triangulation/orthosphere.hpp"
#include "rstruct/triangulation/regular_triangulation_3.hpp"

namespace rstruct::triangulation {

namespace pr = rstruct::predicates;

namespace {

struct Sphere {
  Point3 centre;
  double squared_radius;
};

/// The sphere orthogonal to four weighted points (orthosphere.hpp), centre and squared
/// radius |y|² − w_a.
Sphere orthosphere(const Point3& a, double wa, const Point3& b, double wb, const Point3& c,
                   double wc, const Point3& d, double wd) {
  const Vec3 y = orthosphere_offset(a, wa, b, wb, c, wc, d, wd);
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
