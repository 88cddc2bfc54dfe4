// End-to-end check of the complex module on the union of surface balls of a torus sample
// (DESIGN.md §2, §4, §5): K is homotopy-equivalent to the union (nerve theorem), which is
// a thickened torus, so β(K) = (1, 2, 1, 0); collapsing keeps that.

#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "rstruct/complex/collapse.hpp"
#include "rstruct/complex/dual_complex.hpp"
#include "rstruct/complex/homology.hpp"
#include "rstruct/complex/manifold.hpp"
#include "rstruct/triangulation/regular_triangulation_3.hpp"

using namespace rstruct;
using namespace rstruct::complex;

namespace {

/// Jittered grid on the torus with major radius 1 and minor radius 0.4 (lfs ≡ 0.4), and
/// the surface balls B(s, ρ · lfs(s)).
triangulation::RegularTriangulation3 torus_surface_balls(int nu, int nv, double rho,
                                                        std::uint32_t seed) {
  const double pi = std::acos(-1.0);
  const double major = 1.0, minor = 0.4;
  std::mt19937 engine(seed);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  std::vector<Point3> centres;
  std::vector<double> weights;
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      const double u = 2 * pi * (i + jitter(engine)) / nu;
      const double v = 2 * pi * (j + jitter(engine)) / nv;
      const double ring = major + minor * std::cos(v);
      centres.push_back({ring * std::cos(u), ring * std::sin(u), minor * std::sin(v)});
      const double r = rho * minor;
      weights.push_back(r * r);
    }
  }
  return triangulation::RegularTriangulation3(centres, weights);
}

void check_torus_shell(const triangulation::RegularTriangulation3& r) {
  const auto k = dual_complex(r).complex();
  CHECK(betti_numbers(k) == BettiNumbers{{1, 2, 1, 0}});
  CHECK(betti_numbers(k, HomologyMethod::reduction) == BettiNumbers{{1, 2, 1, 0}});
  for (const auto order : {CollapseOrder::breadth_first, CollapseOrder::depth_first}) {
    CHECK(betti_numbers(collapse_free_faces(k, order).complex) == BettiNumbers{{1, 2, 1, 0}});
  }
  // Depth-first ends on a closed torus (see collapse.hpp).
  CHECK(is_closed_2_manifold(collapse_free_faces(k, CollapseOrder::depth_first).complex));
}

}  // namespace

TEST_CASE("surface balls of a torus sample: K has the torus's Betti numbers") {
  for (const double rho : {0.24, 0.4, 0.56}) {
    check_torus_shell(torus_surface_balls(80, 32, rho, 7));
  }
}

TEST_CASE("surface balls: the collapse ends on a closed torus") {
  const auto r = torus_surface_balls(80, 32, 0.4, 7);
  const auto dual = dual_complex(r);
  const auto k = dual.complex();
  INFO("K: " << k.size(0) << " vertices, " << k.size(1) << " edges, " << k.size(2)
             << " triangles, " << k.size(3) << " tetrahedra");
  CHECK(k.size(0) == 80 * 32);
  CHECK(betti_numbers(k) == BettiNumbers{{1, 2, 1, 0}});
  const auto collapsed = collapse_free_faces(k, CollapseOrder::depth_first);
  CHECK(betti_numbers(collapsed.complex) == BettiNumbers{{1, 2, 1, 0}});
  const auto manifold = check_closed_2_manifold(collapsed.complex);
  INFO("collapsed: " << collapsed.complex.size(2) << " triangles, " << manifold.first_problem);
  CHECK(manifold.is_closed_2_manifold);
  const auto oriented = orient_triangles(collapsed.complex);
  CHECK(oriented.has_value());
}

TEST_CASE("balls too small to overlap give isolated vertices, large ones fill the hole") {
  const auto tiny = dual_complex(torus_surface_balls(40, 16, 0.02, 3));
  CHECK(betti_numbers(tiny.complex()) == BettiNumbers{{40 * 16, 0, 0, 0}});
  // Radius 0.48 > minor radius 0.4: the tube is filled, the union is a solid torus (the
  // ring's hole, radius 0.6 at the inner equator, stays open by 0.12).
  const auto fat = dual_complex(torus_surface_balls(40, 16, 1.2, 3));
  CHECK(betti_numbers(fat.complex()) == BettiNumbers{{1, 1, 0, 0}});
}
