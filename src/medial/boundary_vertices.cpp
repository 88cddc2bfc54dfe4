#include "rstruct/medial/boundary_vertices.hpp"

#include <algorithm>
#include <cmath>

#include "rstruct/core/assert.hpp"
#include "rstruct/predicates/predicates.hpp"
#include "rstruct/triangulation/regular_triangulation_3.hpp"
#include "medial/union_triangulation.hpp"

namespace rstruct::medial {

namespace {

using complex::FacetClass;
using triangulation::CellId;

// The two points of S_i ∩ S_j ∩ S_k: z ± h·n̂, z the point of the centres' plane with
// equal power to the three balls, h = sqrt(−π(z)). Double construction, relative to c_i.
struct SpherePair {
  Point3 plus;
  Point3 minus;
};

SpherePair three_sphere_points(const Ball& bi, const Ball& bj, const Ball& bk) {
  const Vec3 u = bj.c - bi.c;
  const Vec3 v = bk.c - bi.c;
  // z − c_i = α u + β v with 2⟨z − c_i, u⟩ = |u|² − r_j² + r_i² (same for v).
  const double uu = dot(u, u), uv = dot(u, v), vv = dot(v, v);
  const double bu = 0.5 * (uu - bj.r * bj.r + bi.r * bi.r);
  const double bv = 0.5 * (vv - bk.r * bk.r + bi.r * bi.r);
  const double det = uu * vv - uv * uv;
  const double alpha = (bu * vv - bv * uv) / det;
  const double beta = (bv * uu - bu * uv) / det;
  const Vec3 zc = alpha * u + beta * v;
  const double h2 = bi.r * bi.r - dot(zc, zc);
  const double h = h2 > 0 ? std::sqrt(h2) : 0.0;
  // n = u × v / |u × v|: orient3d(c_i, c_j, c_k, c_i + n) > 0, so `plus` is side +1.
  const Vec3 n = normalized(cross(u, v));
  return {bi.c + zc + h * n, bi.c + zc - h * n};
}

}  // namespace

bool has_ball(const BoundaryVertex& v, std::uint32_t ball) {
  return v.balls[0] == ball || v.balls[1] == ball || v.balls[2] == ball;
}

std::vector<BoundaryVertex> boundary_vertices(std::span<const Ball> balls,
                                              const triangulation::RegularTriangulation3& rt,
                                              const complex::DualComplex& k) {
  const auto& tri = k.triangulation;
  std::vector<BoundaryVertex> out;
  std::vector<bool> done(tri.size(2), false);
  const auto n = static_cast<std::uint32_t>(balls.size());
  rt.for_each_finite_cell([&](CellId c) {
    std::array<std::uint32_t, 4> cell = rt.vertices(c);
    std::array<std::uint32_t, 4> sorted_cell = cell;
    std::sort(sorted_cell.begin(), sorted_cell.end());
    const auto tet_index = tri.find(complex::Tetrahedron{sorted_cell});
    RSTRUCT_ASSERT(tet_index.has_value());
    const bool tet_in_k = k.in_k[3][*tet_index];
    for (int f = 0; f < 4; ++f) {
      std::array<std::uint32_t, 3> t{};
      int m = 0;
      for (int q = 0; q < 4; ++q) {
        if (q != f) t[m++] = cell[q];
      }
      std::sort(t.begin(), t.end());
      if (t[2] >= n) continue;  // a far point, not a ball
      const auto index = tri.find(complex::Triangle{t});
      RSTRUCT_ASSERT(index.has_value());
      const FacetClass cls = k.facet_class[*index];
      if (cls == FacetClass::singular) {
        if (done[*index]) continue;
        done[*index] = true;
        const SpherePair p = three_sphere_points(balls[t[0]], balls[t[1]], balls[t[2]]);
        const auto first = static_cast<std::uint32_t>(out.size());
        out.push_back({p.plus, t, first + 1, +1});
        out.push_back({p.minus, t, first, -1});
      } else if (cls == FacetClass::regular && tet_in_k) {
        // Lemma (Edelsbrunner 1995): the dual power edge runs from the orthocentre of the
        // tetrahedron in K (power ≤ 0) outwards across the facet; its point on the spheres
        // lies on the side of the facet's plane away from the apex cell[f].
        const SpherePair p = three_sphere_points(balls[t[0]], balls[t[1]], balls[t[2]]);
        const Point3& a = balls[t[0]].c;
        const Point3& b = balls[t[1]].c;
        const Point3& d = balls[t[2]].c;
        const Sign apex = predicates::orient3d(a, b, d, rt.point(cell[f]));
        const Sign plus = predicates::orient3d(a, b, d, p.plus);
        out.push_back(plus == apex ? BoundaryVertex{p.minus, t, kNoTwin, -1}
                                   : BoundaryVertex{p.plus, t, kNoTwin, +1});
      }
    }
  });
  return out;
}

std::vector<BoundaryVertex> boundary_vertices_of_union(std::span<const Ball> balls) {
  check_balls(balls);
  if (balls.empty()) return {};
  const triangulation::RegularTriangulation3 rt = ball_triangulation(balls);
  return boundary_vertices(balls, rt, complex::dual_complex(rt));
}

}  // namespace rstruct::medial
