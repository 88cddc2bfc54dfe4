// Marching tetrahedra meshes: closed oriented 2-manifolds with the right Euler
// characteristic; the double torus has genus 2.
#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <numbers>

#include "rstruct/core/error.hpp"
#include "rstruct/sampling/double_torus.hpp"
#include "rstruct/sampling/implicit_mesher.hpp"
#include "rstruct/sampling/sphere.hpp"
#include "rstruct/sampling/torus.hpp"

using namespace rstruct;
using namespace rstruct::sampling;

namespace {

/// Signed volume enclosed by the oriented triangles (divergence theorem).
double signed_volume(const TriangleMesh& m) {
  double v = 0;
  for (const auto& f : m.faces) {
    v += dot(m.vertices[f[0]], cross(m.vertices[f[1]], m.vertices[f[2]])) / 6.0;
  }
  return v;
}

/// Every directed edge appears exactly once (consistent orientation of a closed mesh).
bool consistently_oriented(const TriangleMesh& m) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (const auto& f : m.faces) {
    for (int c = 0; c < 3; ++c) ++directed[{f[c], f[(c + 1) % 3]}];
  }
  for (const auto& [edge, count] : directed) {
    if (count != 1 || directed.count({edge.second, edge.first}) != 1) return false;
  }
  return true;
}

}  // namespace

TEST_CASE("sphere and torus meshes: closed manifolds with chi 2 and 0") {
  Sphere sphere(1.0);
  const TriangleMesh ms = mesh_implicit_surface(sphere, 0.07, true);
  const MeshTopology ts = mesh_topology(ms);
  CHECK(ts.is_closed_manifold());
  CHECK(ts.components == 1);
  CHECK(ts.euler_characteristic == 2);
  CHECK(consistently_oriented(ms));
  CHECK(signed_volume(ms) == Approx(4.0 / 3.0 * std::numbers::pi).epsilon(0.01));
  CHECK(mesh_area(ms) == Approx(4 * std::numbers::pi).epsilon(0.01));

  Torus torus(3.0, 1.0);
  const TriangleMesh mt = mesh_implicit_surface(torus, 0.15, true);
  const MeshTopology tt = mesh_topology(mt);
  CHECK(tt.is_closed_manifold());
  CHECK(tt.components == 1);
  CHECK(tt.euler_characteristic == 0);
  CHECK(tt.genus() == 1);
  CHECK(consistently_oriented(mt));
  CHECK(signed_volume(mt) == Approx(2 * std::numbers::pi * std::numbers::pi * 3.0).epsilon(0.01));
}

TEST_CASE("double torus: genus 2, smooth, at two resolutions") {
  DoubleTorus dt;
  for (double step : {0.035, 0.022}) {
    const TriangleMesh m = mesh_implicit_surface(dt, step, true);
    const MeshTopology t = mesh_topology(m);
    INFO("step " << step << ": V " << t.vertices << " E " << t.edges << " F " << t.faces);
    CHECK(t.is_closed_manifold());
    CHECK(t.components == 1);
    CHECK(t.euler_characteristic == -2);
    CHECK(t.genus() == 2);
    CHECK(consistently_oriented(m));
    CHECK(signed_volume(m) > 0.0);
    // The implicit function is regular on F: |∇f| stays well away from 0.
    double min_gradient = HUGE_VAL;
    for (const Point3& p : m.vertices) {
      min_gradient = std::min(min_gradient, norm(dt.gradient(p)));
      REQUIRE(std::fabs(dt.value(p)) <= 1e-12);
    }
    CHECK(min_gradient > 0.5);
  }
  // Area: the lazily computed value (step 0.015) agrees with a coarser mesh (step 0.025):
  // with vertices projected onto F the area error is O(h²κ²); measured differences between
  // steps 0.03 and 0.007 are below 3e-5 relative.
  const double coarse = mesh_area(mesh_implicit_surface(dt, 0.025, true));
  CHECK(dt.area() == Approx(coarse).epsilon(1e-4));
}

TEST_CASE("mesh topology of small meshes") {
  TriangleMesh tet;
  tet.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  tet.faces = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  const MeshTopology t = mesh_topology(tet);
  CHECK(t.is_closed_manifold());
  CHECK(t.euler_characteristic == 2);
  CHECK(consistently_oriented(tet));
  TriangleMesh open = tet;
  open.faces.pop_back();
  CHECK_FALSE(mesh_topology(open).every_edge_in_two_faces);
  CHECK(mesh_topology(open).euler_characteristic == 1);
  // Two tetrahedra sharing one vertex: edges fine, but that vertex's link is two cycles.
  TriangleMesh pinched = tet;
  pinched.vertices.push_back({-1, 0, 0});
  pinched.vertices.push_back({0, -1, 0});
  pinched.vertices.push_back({0, 0, -1});
  pinched.faces.push_back({0, 4, 5});
  pinched.faces.push_back({0, 5, 6});
  pinched.faces.push_back({0, 6, 4});
  pinched.faces.push_back({4, 6, 5});
  const MeshTopology p = mesh_topology(pinched);
  CHECK(p.every_edge_in_two_faces);
  CHECK_FALSE(p.every_vertex_link_a_cycle);
  TriangleMesh bad = tet;
  bad.faces.push_back({0, 1, 9});
  CHECK_THROWS_AS(mesh_topology(bad), InvalidInput);
  CHECK_THROWS_AS(mesh_implicit_surface(Sphere(1.0), 0.0, false), InvalidInput);
  CHECK_THROWS_AS(mesh_implicit_surface(Sphere(1.0), 1e-6, false), InvalidInput);
}
