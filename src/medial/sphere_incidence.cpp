#include "medial/sphere_incidence.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <unordered_set>

#include "rstruct/predicates/predicates.hpp"
#include "rstruct/triangulation/regular_triangulation_3.hpp"

namespace rstruct::medial {
namespace {

using Q3 = std::array<mpq_class, 3>;

Q3 q(const Point3& p) { return {mpq_class(p.x), mpq_class(p.y), mpq_class(p.z)}; }
Q3 sub(const Q3& a, const Q3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Q3 add(const Q3& a, const Q3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Q3 scale(const mpq_class& s, const Q3& a) { return {s * a[0], s * a[1], s * a[2]}; }
mpq_class dot(const Q3& a, const Q3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Q3 cross(const Q3& a, const Q3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

}  // namespace

ExactVertex exact_vertex(const BoundaryVertex& v, std::span<const Ball> balls) {
  const Ball& bi = balls[v.balls[0]];
  const Ball& bj = balls[v.balls[1]];
  const Ball& bk = balls[v.balls[2]];
  const Q3 ci = q(bi.c);
  const Q3 u = sub(q(bj.c), ci), w = sub(q(bk.c), ci);
  const mpq_class ri2 = mpq_class(bi.r) * bi.r, rj2 = mpq_class(bj.r) * bj.r,
                  rk2 = mpq_class(bk.r) * bk.r;
  const mpq_class uu = dot(u, u), uw = dot(u, w), ww = dot(w, w);
  const mpq_class bu = (uu - rj2 + ri2) / 2, bw = (ww - rk2 + ri2) / 2;
  const mpq_class det = uu * ww - uw * uw;  // > 0: the three centres span a facet of K
  const mpq_class alpha = (bu * ww - bw * uw) / det, beta = (bw * uu - bu * uw) / det;
  const Q3 z = add(scale(alpha, u), scale(beta, w));
  ExactVertex e;
  e.o = add(ci, z);
  e.n = cross(u, w);
  e.h = (ri2 - dot(z, z)) / dot(e.n, e.n);
  e.side = v.side;
  return e;
}

namespace {

/// |P − c|² − r² = A + 2·side·√H·B with A = |o − c|² + H|N|² − r², B = (o − c)·N.
bool on_sphere(const ExactVertex& e, const Ball& m) {
  const Q3 d = sub(e.o, q(m.c));
  const mpq_class a = dot(d, d) + e.h * dot(e.n, e.n) - mpq_class(m.r) * m.r;
  const mpq_class b = dot(d, e.n);
  if (sgn(b) == 0 || sgn(e.h) <= 0) return sgn(a) == 0;
  // a + 2·side·√H·b = 0  ⇔  a = −2·side·√H·b  ⇔  sign(a) = −side·sign(b) and a² = 4Hb².
  if (sgn(a) != -e.side * sgn(b)) return false;
  return a * a == 4 * e.h * b * b;
}

/// Double prefilter: is the rounded point within a generous tolerance of sphere m?
bool near_sphere(const Point3& p, const Ball& m) {
  const double d2 = dot(p - m.c, p - m.c);
  const double r2 = m.r * m.r;
  return std::fabs(d2 - r2) <= 1e-9 * (d2 + r2);
}

/// Sign of N₁·N₂ for the centre triangles of two vertices (exact).
int normal_agreement(const BoundaryVertex& a, const BoundaryVertex& b,
                     std::span<const Ball> balls) {
  auto normal = [&](const BoundaryVertex& v) {
    const Q3 ci = q(balls[v.balls[0]].c);
    return cross(sub(q(balls[v.balls[1]].c), ci), sub(q(balls[v.balls[2]].c), ci));
  };
  return sgn(dot(normal(a), normal(b)));
}

}  // namespace

bool lies_on_sphere(const BoundaryVertex& v, std::span<const Ball> balls, const Ball& m) {
  return on_sphere(exact_vertex(v, balls), m);
}

DistinctVertices distinct_vertices(std::span<const BoundaryVertex> bv, std::span<const Ball> balls,
                                   const triangulation::RegularTriangulation3& rt) {
  const auto n = static_cast<std::uint32_t>(balls.size());
  std::vector<std::vector<std::uint32_t>> on(bv.size());
  // Neighbours of each ball in rt, computed once on first use.
  std::vector<std::vector<std::uint32_t>> neighbours(n);
  std::vector<bool> have_neighbours(n, false);
  auto adjacent = [&](std::uint32_t x) -> const std::vector<std::uint32_t>& {
    if (!have_neighbours[x]) {
      neighbours[x] = rt.adjacent_vertices(x);
      have_neighbours[x] = true;
    }
    return neighbours[x];
  };
  std::vector<std::uint32_t> frontier;
  std::unordered_set<std::uint32_t> tested;
  for (std::size_t v = 0; v < bv.size(); ++v) {
    std::vector<std::uint32_t>& found = on[v];
    found.assign(bv[v].balls.begin(), bv[v].balls.end());
    tested.clear();
    tested.insert(found.begin(), found.end());
    frontier = found;
    std::optional<ExactVertex> exact;
    while (!frontier.empty()) {
      const std::uint32_t x = frontier.back();
      frontier.pop_back();
      if (x >= n || !rt.is_vertex(x)) continue;
      for (const auto y : adjacent(x)) {
        if (y >= n || !tested.insert(y).second) continue;
        if (!near_sphere(bv[v].point, balls[y])) continue;
        if (!exact) exact = exact_vertex(bv[v], balls);
        if (on_sphere(*exact, balls[y])) {
          found.push_back(y);
          frontier.push_back(y);
        }
      }
    }
    std::sort(found.begin(), found.end());
  }

  // One point per exact point: vertices on the same four or more spheres are one point,
  // unless all those centres are coplanar, when the spheres meet in two mirror points and
  // the sides tell them apart. Three spheres give two distinct points (or one double point,
  // whose two roundings are equal doubles, merged by the Delaunay triangulation).
  DistinctVertices out;
  std::map<std::vector<std::uint32_t>, std::vector<std::uint32_t>> groups;  // by ball set
  for (std::uint32_t v = 0; v < bv.size(); ++v) {
    if (on[v].size() < 4) {
      out.vertex.push_back(bv[v]);
      out.on.push_back(on[v]);
      continue;
    }
    auto& members = groups[on[v]];  // representatives of this ball set so far
    bool same_point = false;
    for (const std::uint32_t r : members) {
      const BoundaryVertex& rep = out.vertex[r];
      bool coplanar = true;
      for (const std::uint32_t m : on[v]) {
        if (predicates::orient3d(balls[rep.balls[0]].c, balls[rep.balls[1]].c,
                                 balls[rep.balls[2]].c, balls[m].c) != Sign::zero) {
          coplanar = false;
          break;
        }
      }
      if (!coplanar || rep.side == bv[v].side * normal_agreement(rep, bv[v], balls)) {
        same_point = true;
        break;
      }
    }
    if (!same_point) {
      members.push_back(static_cast<std::uint32_t>(out.vertex.size()));
      out.vertex.push_back(bv[v]);
      out.on.push_back(on[v]);
    }
  }
  return out;
}

}  // namespace rstruct::medial
