#pragma once
// Triangulations with known Z₂ Betti numbers, written out explicitly (the bigger ones as a
// short construction whose result is checked by the tests: manifold, Euler characteristic).

#include <algorithm>
#include <array>
#include <map>
#include <vector>

#include "rstruct/complex/simplicial_complex.hpp"

namespace rstruct::complex::testing {

/// Boundary of the tetrahedron: a 2-sphere, β = (1, 0, 1, 0).
inline std::vector<Triangle> tetrahedron_boundary() {
  return {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
}

/// Octahedron ±x = 0/1, ±y = 2/3, ±z = 4/5: a 2-sphere.
inline std::vector<Triangle> octahedron() {
  return {{0, 2, 4}, {0, 2, 5}, {0, 3, 4}, {0, 3, 5},
          {1, 2, 4}, {1, 2, 5}, {1, 3, 4}, {1, 3, 5}};
}

/// Möbius's 7-vertex torus (triangles {i, i+1, i+3}, {i, i+2, i+3} mod 7):
/// β = (1, 2, 1, 0).
inline std::vector<Triangle> torus7() {
  return {{0, 1, 3}, {0, 2, 3}, {1, 2, 4}, {1, 3, 4}, {2, 3, 5}, {2, 4, 5}, {3, 4, 6},
          {3, 5, 6}, {0, 4, 5}, {0, 4, 6}, {1, 5, 6}, {0, 1, 5}, {0, 2, 6}, {1, 2, 6}};
}

/// The 6-vertex real projective plane (hemi-icosahedron): Z₂ β = (1, 1, 1, 0).
inline std::vector<Triangle> projective_plane6() {
  return {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}, {0, 5, 1},
          {1, 2, 4}, {2, 3, 5}, {3, 4, 1}, {4, 5, 2}, {5, 1, 3}};
}

/// Klein bottle from a 4×4 grid: vertex (i, j) = i + 4j, rows glued with a reflection
/// (i, 4) ~ (−i, 0). Z₂ β = (1, 2, 1, 0), not orientable.
inline std::vector<Triangle> klein_bottle() {
  return {{0, 1, 5},    {0, 5, 4},    {1, 2, 6},    {1, 6, 5},    {2, 3, 7},   {2, 7, 6},
          {3, 0, 4},    {3, 4, 7},    {4, 5, 9},    {4, 9, 8},    {5, 6, 10},  {5, 10, 9},
          {6, 7, 11},   {6, 11, 10},  {7, 4, 8},    {7, 8, 11},   {8, 9, 13},  {8, 13, 12},
          {9, 10, 14},  {9, 14, 13},  {10, 11, 15}, {10, 15, 14}, {11, 8, 12}, {11, 12, 15},
          {12, 13, 3},  {12, 3, 0},   {13, 14, 2},  {13, 2, 3},   {14, 15, 1}, {14, 1, 2},
          {15, 12, 0},  {15, 0, 1}};
}

/// Genus-2 surface: connected sum of two 7-vertex tori along the triangle (0, 1, 3)
/// (second copy relabelled 2→7, 4→8, 5→9, 6→10). β = (1, 4, 1, 0), χ = −2.
inline std::vector<Triangle> genus2() {
  return {{0, 2, 3},  {1, 2, 4},  {1, 3, 4},  {2, 3, 5}, {2, 4, 5},  {3, 4, 6},  {3, 5, 6},
          {0, 4, 5},  {0, 4, 6},  {1, 5, 6},  {0, 1, 5}, {0, 2, 6},  {1, 2, 6},  {0, 7, 3},
          {1, 7, 8},  {1, 3, 8},  {7, 3, 9},  {7, 8, 9}, {3, 8, 10}, {3, 9, 10}, {0, 8, 9},
          {0, 8, 10}, {1, 9, 10}, {0, 1, 9}, {0, 7, 10}, {1, 7, 10}};
}

/// Wedge of three circles (three triangles' boundaries sharing vertex 0): β = (1, 3, 0, 0).
inline std::vector<Edge> wedge_of_three_circles() {
  return {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {3, 4}, {4, 0}, {0, 5}, {5, 6}, {6, 0}};
}

/// Kuhn (Freudenthal) triangulation of the box [0, nx] × [0, ny] × [0, nz] of unit cubes:
/// every cube split into the six tetrahedra along its main diagonal; vertex (x, y, z) has
/// id x + (nx + 1)(y + (ny + 1) z). A solid ball, β = (1, 0, 0, 0).
inline std::vector<Tetrahedron> subdivided_box(int nx, int ny, int nz) {
  const auto id = [&](int x, int y, int z) {
    return static_cast<VertexId>(x + (nx + 1) * (y + (ny + 1) * z));
  };
  static constexpr std::array<std::array<int, 3>, 6> kOrders = {
      {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
  std::vector<Tetrahedron> tets;
  for (int z = 0; z < nz; ++z) {
    for (int y = 0; y < ny; ++y) {
      for (int x = 0; x < nx; ++x) {
        for (const auto& order : kOrders) {
          std::array<int, 3> p = {x, y, z};
          Tetrahedron t{};
          t[0] = id(p[0], p[1], p[2]);
          for (int s = 0; s < 3; ++s) {
            ++p[order[s]];
            t[s + 1] = id(p[0], p[1], p[2]);
          }
          tets.push_back(t);
        }
      }
    }
  }
  return tets;
}

/// The triangles of a list of tetrahedra that lie in exactly one of them (the boundary of
/// a 3-manifold with boundary).
inline std::vector<Triangle> boundary_triangles(const std::vector<Tetrahedron>& tets) {
  std::map<Triangle, int> count;
  for (Tetrahedron t : tets) {
    std::sort(t.begin(), t.end());
    for (int i = 0; i < 4; ++i) {
      Triangle f{};
      for (int j = 0, o = 0; j < 4; ++j) {
        if (j != i) f[o++] = t[j];
      }
      ++count[f];
    }
  }
  std::vector<Triangle> out;
  for (const auto& [f, c] : count) {
    if (c == 1) out.push_back(f);
  }
  return out;
}

}  // namespace rstruct::complex::testing
