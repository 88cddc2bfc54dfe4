// Loop subdivision: hand-computed positions on the octahedron, counts and Euler
// characteristic, orientation kept, convergence towards a smooth surface (the largest
// dihedral turning angle shrinks level by level), and clear errors on meshes that are not
// closed edge-manifolds. Also sample_mesh_weighted's density.
#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <set>
#include <utility>

#include "rstruct/core/error.hpp"
#include "rstruct/sampling/loop_subdivision.hpp"
#include "rstruct/sampling/uniform_sampling.hpp"

using namespace rstruct;
using namespace rstruct::sampling;

namespace {

/// Octahedron with outward-oriented faces.
TriangleMesh octahedron() {
  TriangleMesh m;
  m.vertices = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  m.faces = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
             {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return m;
}

std::size_t edge_count(const TriangleMesh& m) {
  std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
  for (const auto& f : m.faces) {
    for (int k = 0; k < 3; ++k) {
      edges.insert(std::minmax(f[k], f[(k + 1) % 3]));
    }
  }
  return edges.size();
}

Vec3 face_normal(const TriangleMesh& m, const std::array<std::uint32_t, 3>& f) {
  return cross(m.vertices[f[1]] - m.vertices[f[0]], m.vertices[f[2]] - m.vertices[f[0]]);
}

/// Largest angle between the normals of two faces sharing an edge.
double max_turning_angle(const TriangleMesh& m) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t> first;
  double worst = 0;
  for (std::size_t i = 0; i < m.faces.size(); ++i) {
    const auto& f = m.faces[i];
    for (int k = 0; k < 3; ++k) {
      const auto key = std::minmax(f[k], f[(k + 1) % 3]);
      const auto [it, fresh] = first.emplace(key, i);
      if (fresh) continue;
      const Vec3 a = normalized(face_normal(m, m.faces[it->second]));
      const Vec3 b = normalized(face_normal(m, f));
      worst = std::max(worst, std::acos(std::clamp(dot(a, b), -1.0, 1.0)));
    }
  }
  return worst;
}

/// Every directed edge appears once: consistently oriented closed surface.
bool consistently_oriented(const TriangleMesh& m) {
  std::set<std::pair<std::uint32_t, std::uint32_t>> directed;
  for (const auto& f : m.faces) {
    for (int k = 0; k < 3; ++k) {
      if (!directed.emplace(f[k], f[(k + 1) % 3]).second) return false;
    }
  }
  for (const auto& [a, b] : directed) {
    if (directed.count({b, a}) != 1) return false;
  }
  return true;
}

}  // namespace

TEST_CASE("Loop subdivision of the octahedron: Loop's rules, computed by hand") {
  const TriangleMesh m = loop_subdivide(octahedron(), 1);
  REQUIRE(m.vertices.size() == 6 + 12);
  REQUIRE(m.faces.size() == 32);
  // Valence 4: beta = (5/8 - (3/8 + cos(pi/2)/4)^2) / 4 = 31/256; the neighbours of (1,0,0)
  // sum to 0, so it moves to (1 - 4 beta) (1,0,0) = (132/256) (1,0,0).
  CHECK(m.vertices[0].x == Approx(132.0 / 256.0).epsilon(1e-15));
  CHECK(m.vertices[0].y == Approx(0.0).margin(1e-15));
  CHECK(m.vertices[0].z == Approx(0.0).margin(1e-15));
  // The edge (1,0,0)-(0,1,0) with opposite vertices (0,0,±1): 3/8 (1,1,0) + 1/8 (0,0,0).
  bool found = false;
  for (std::size_t v = 6; v < m.vertices.size(); ++v) {
    const Point3& p = m.vertices[v];
    if (p.x > 0 && p.y > 0 && std::fabs(p.z) < 1e-15) {
      CHECK(p.x == Approx(0.375).epsilon(1e-15));
      CHECK(p.y == Approx(0.375).epsilon(1e-15));
      found = true;
    }
  }
  CHECK(found);
}

TEST_CASE("Loop subdivision keeps the topology and the orientation, and smooths") {
  TriangleMesh m = octahedron();
  double previous = max_turning_angle(m);
  for (unsigned level = 1; level <= 4; ++level) {
    const TriangleMesh s = loop_subdivide(octahedron(), level);
    const std::size_t v = s.vertices.size();
    const std::size_t e = edge_count(s);
    const std::size_t f = s.faces.size();
    CHECK(f == 8u << (2 * level));
    CHECK(static_cast<long>(v) - static_cast<long>(e) + static_cast<long>(f) == 2);
    CHECK(consistently_oriented(s));
    const double turning = max_turning_angle(s);
    INFO("level " << level << ": largest turning angle " << turning);
    CHECK(turning < 0.75 * previous);  // roughly halves at every level
    previous = turning;
    // The limit surface of a convex mesh stays inside it.
    for (const Point3& p : s.vertices) {
      CHECK(std::fabs(p.x) + std::fabs(p.y) + std::fabs(p.z) <= 1.0 + 1e-12);
    }
  }
}

TEST_CASE("Loop subdivision rejects meshes that are not closed edge-manifolds") {
  TriangleMesh open = octahedron();
  open.faces.pop_back();
  CHECK_THROWS_WITH(loop_subdivide(open, 1), Catch::Contains("lies in 1 faces"));
  TriangleMesh fin = octahedron();
  fin.vertices.push_back({2, 2, 2});
  fin.faces.push_back({0, 2, 6});  // a third face on the edge (0, 2)
  CHECK_THROWS_WITH(loop_subdivide(fin, 1), Catch::Contains("lies in 3 faces"));
  TriangleMesh bad = octahedron();
  bad.faces[0][1] = 17;
  CHECK_THROWS_WITH(loop_subdivide(bad, 1), Catch::Contains("refers to vertex 17"));
  TriangleMesh nan = octahedron();
  nan.vertices[3].y = std::nan("");
  CHECK_THROWS_AS(loop_subdivide(nan, 1), InvalidInput);
  TriangleMesh repeated = octahedron();
  repeated.faces[0] = {0, 0, 4};
  CHECK_THROWS_WITH(loop_subdivide(repeated, 1), Catch::Contains("repeats a vertex"));
  CHECK(loop_subdivide(octahedron(), 0).faces.size() == 8);
}

TEST_CASE("weighted mesh sampling: face frequencies follow area times density") {
  const TriangleMesh m = octahedron();  // 8 faces of equal area
  std::vector<double> density = {1, 0, 3, 0, 0, 0, 0, 4};
  const std::size_t n = 80000;
  const auto points = sample_mesh_weighted(m, density, n, 5);
  REQUIRE(points.size() == n);
  std::array<std::size_t, 8> hits{};
  for (const Point3& p : points) {
    // Octant of the point identifies its face (faces are the 8 octants).
    const int face_of[2][2][2] = {{{6, 2}, {5, 1}}, {{7, 3}, {4, 0}}};  // [x>0][y>0][z>0]
    ++hits[face_of[p.x > 0][p.y > 0][p.z > 0]];
  }
  const double total = 8.0;
  for (int f = 0; f < 8; ++f) {
    const double p = density[f] / total;
    const double sd = std::sqrt(p * (1 - p) / static_cast<double>(n));
    INFO("face " << f << ": " << hits[f]);
    CHECK(std::fabs(static_cast<double>(hits[f]) / static_cast<double>(n) - p) <= 5 * sd + 1e-12);
  }
  CHECK_THROWS_AS(sample_mesh_weighted(m, std::vector<double>(7, 1.0), 10, 1), InvalidInput);
  CHECK_THROWS_AS(sample_mesh_weighted(m, std::vector<double>(8, 0.0), 10, 1), InvalidInput);
  std::vector<double> negative(8, 1.0);
  negative[2] = -1;
  CHECK_THROWS_AS(sample_mesh_weighted(m, negative, 10, 1), InvalidInput);
}
