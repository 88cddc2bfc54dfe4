#include "rstruct/sampling/implicit_mesher.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <sstream>
#include <vector>

#include "rstruct/core/assert.hpp"
#include "rstruct/core/error.hpp"

namespace rstruct::sampling {

namespace {

using Corner = std::array<int, 3>;  // cube-local corner in {0, 1}³

/// The six tetrahedra of the Kuhn triangulation: for each permutation σ of the axes,
/// 0 → e_σ0 → e_σ0 + e_σ1 → (1, 1, 1).
std::array<std::array<Corner, 4>, 6> kuhn_tetrahedra() {
  std::array<std::array<Corner, 4>, 6> tets{};
  std::array<int, 3> sigma{0, 1, 2};
  int t = 0;
  do {
    Corner c{0, 0, 0};
    tets[static_cast<std::size_t>(t)][0] = c;
    for (std::size_t s = 0; s < 3; ++s) {
      c[static_cast<std::size_t>(sigma[s])] = 1;
      tets[static_cast<std::size_t>(t)][s + 1] = c;
    }
    ++t;
  } while (std::next_permutation(sigma.begin(), sigma.end()));
  return tets;
}

/// Grid geometry and the slab of node values for two consecutive z layers.
struct Grid {
  Point3 origin;
  double step = 0;
  std::int64_t nx = 0, ny = 0, nz = 0;
  Point3 node(std::int64_t i, std::int64_t j, std::int64_t k) const {
    return {origin.x + step * static_cast<double>(i), origin.y + step * static_cast<double>(j),
            origin.z + step * static_cast<double>(k)};
  }
};

/// Builds the mesh one cube layer at a time, creating one vertex per crossed grid edge.
class Mesher {
 public:
  Mesher(const Surface& surface, const Grid& grid) : surface_(surface), grid_(grid) {
    for (auto& ids : edge_ids_)
      ids.assign(static_cast<std::size_t>(7 * grid_.nx * grid_.ny), kNone);
  }

  TriangleMesh run() {
    std::vector<double> below = layer(0);
    for (std::int64_t k = 0; k + 1 < grid_.nz; ++k) {
      std::vector<double> above = layer(k + 1);
      for (std::int64_t j = 0; j + 1 < grid_.ny; ++j) {
        for (std::int64_t i = 0; i + 1 < grid_.nx; ++i) cube(i, j, k, below, above);
      }
      below.swap(above);
      // Edges whose lower end is in layer k + 1 become the lower layer's.
      edge_ids_[0].swap(edge_ids_[1]);
      std::fill(edge_ids_[1].begin(), edge_ids_[1].end(), kNone);
    }
    return std::move(mesh_);
  }

 private:
  std::vector<double> layer(std::int64_t k) const {
    std::vector<double> values(static_cast<std::size_t>(grid_.nx * grid_.ny));
    for (std::int64_t j = 0; j < grid_.ny; ++j) {
      for (std::int64_t i = 0; i < grid_.nx; ++i) {
        values[static_cast<std::size_t>(i + grid_.nx * j)] = surface_.value(grid_.node(i, j, k));
      }
    }
    return values;
  }

  void cube(std::int64_t i, std::int64_t j, std::int64_t k, const std::vector<double>& below,
            const std::vector<double>& above) {
    std::array<double, 8> v{};
    bool any_in = false, any_out = false;
    for (int c = 0; c < 8; ++c) {
      const int dx = c & 1, dy = (c >> 1) & 1, dz = (c >> 2) & 1;
      const auto& slab = dz == 0 ? below : above;
      v[static_cast<std::size_t>(c)] =
          slab[static_cast<std::size_t>((i + dx) + grid_.nx * (j + dy))];
      (v[static_cast<std::size_t>(c)] < 0.0 ? any_in : any_out) = true;
    }
    if (!any_in || !any_out) return;
    static const auto tets = kuhn_tetrahedra();
    for (const auto& tet : tets) tetrahedron(i, j, k, tet, v);
  }

  void tetrahedron(std::int64_t i, std::int64_t j, std::int64_t k, const std::array<Corner, 4>& tet,
                   const std::array<double, 8>& v) {
    std::array<int, 4> inside{}, outside{};
    int n_in = 0, n_out = 0;
    for (int t = 0; t < 4; ++t) {
      const Corner& c = tet[static_cast<std::size_t>(t)];
      const double value = v[static_cast<std::size_t>(c[0] + 2 * c[1] + 4 * c[2])];
      if (value < 0.0) {
        inside[static_cast<std::size_t>(n_in++)] = t;
      } else {
        outside[static_cast<std::size_t>(n_out++)] = t;
      }
    }
    if (n_in == 0 || n_out == 0) return;
    auto cut = [&](int a, int b) { return edge_vertex(i, j, k, tet, v, a, b); };
    auto half = [&](int a, int b) { return midpoint2(tet, a, b); };
    auto twice = [&](int a) {
      const Corner& c = tet[static_cast<std::size_t>(a)];
      return Corner{2 * c[0], 2 * c[1], 2 * c[2]};
    };
    if (n_in == 1 || n_out == 1) {
      const int apex = n_in == 1 ? inside[0] : outside[0];
      std::array<int, 3> o{};
      int n = 0;
      for (int t = 0; t < 4; ++t) {
        if (t != apex) o[static_cast<std::size_t>(n++)] = t;
      }
      emit({cut(apex, o[0]), cut(apex, o[1]), cut(apex, o[2])},
           {half(apex, o[0]), half(apex, o[1]), half(apex, o[2])}, twice(apex), n_in == 1);
      return;
    }
    const int a = inside[0], b = inside[1], c = outside[0], d = outside[1];
    // The quad a-c, a-d, b-d, b-c (consecutive edges share a tetrahedron vertex), split
    // into two triangles, each with an inside reference vertex on two of its edges.
    emit({cut(a, c), cut(a, d), cut(b, d)}, {half(a, c), half(a, d), half(b, d)}, twice(a), true);
    emit({cut(a, c), cut(b, d), cut(b, c)}, {half(a, c), half(b, d), half(b, c)}, twice(b), true);
  }

  /// Twice the midpoint of tet vertices a and b, in cube-local integer coordinates.
  static Corner midpoint2(const std::array<Corner, 4>& tet, int a, int b) {
    const Corner& p = tet[static_cast<std::size_t>(a)];
    const Corner& q = tet[static_cast<std::size_t>(b)];
    return {p[0] + q[0], p[1] + q[1], p[2] + q[2]};
  }

  /// Appends a triangle with its normal pointing away from the inside region. `mid` are
  /// twice the midpoints of the triangle's grid edges and `ref` twice a tetrahedron vertex
  /// that is an end of at least two of those edges. For the triangles marching tetrahedra
  /// makes, det[x₁ − r, x₂ − r, x₃ − r] factors as a positive multiple (products of the
  /// interpolation parameters t and 1 − t) of a determinant of tetrahedron edge vectors,
  /// so its sign is the same for the true vertices and for the midpoints: the decision is
  /// exact integer arithmetic. The normal points away from r iff that determinant is > 0;
  /// we want that when r is inside.
  void emit(std::array<std::uint32_t, 3> tri, const std::array<Corner, 3>& mid, const Corner& ref,
            bool ref_inside) {
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) return;
    std::array<std::array<long long, 3>, 3> m{};
    for (std::size_t r = 0; r < 3; ++r) {
      for (std::size_t c = 0; c < 3; ++c) m[r][c] = mid[r][c] - ref[c];
    }
    const long long det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                          m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                          m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    RSTRUCT_ASSERT(det != 0);
    if ((det > 0) != ref_inside) std::swap(tri[1], tri[2]);
    mesh_.faces.push_back(tri);
  }

  /// The vertex on the grid edge between tet vertices a and b, created on first use.
  /// Edges of the Kuhn triangulation join a corner p to a corner q ≥ p componentwise, so
  /// an edge is identified by its lower end and the direction q − p ∈ {0, 1}³ \ {0}; ids
  /// are kept for the two node layers of the current cube layer.
  std::uint32_t edge_vertex(std::int64_t i, std::int64_t j, std::int64_t k,
                            const std::array<Corner, 4>& tet, const std::array<double, 8>& v, int a,
                            int b) {
    const Corner* p = &tet[static_cast<std::size_t>(a)];
    const Corner* q = &tet[static_cast<std::size_t>(b)];
    if ((*p)[0] + (*p)[1] + (*p)[2] > (*q)[0] + (*q)[1] + (*q)[2]) std::swap(p, q);
    const int direction = ((*q)[0] - (*p)[0]) + 2 * ((*q)[1] - (*p)[1]) + 4 * ((*q)[2] - (*p)[2]);
    RSTRUCT_ASSERT(direction >= 1 && direction <= 7);
    const auto slot =
        static_cast<std::size_t>(7 * ((i + (*p)[0]) + grid_.nx * (j + (*p)[1])) + (direction - 1));
    std::uint32_t& id = edge_ids_[static_cast<std::size_t>((*p)[2])][slot];
    if (id == kNone) {
      id = static_cast<std::uint32_t>(mesh_.vertices.size());
      const double fa = v[static_cast<std::size_t>((*p)[0] + 2 * (*p)[1] + 4 * (*p)[2])];
      const double fb = v[static_cast<std::size_t>((*q)[0] + 2 * (*q)[1] + 4 * (*q)[2])];
      const Point3 pa = grid_.node(i + (*p)[0], j + (*p)[1], k + (*p)[2]);
      const Point3 pb = grid_.node(i + (*q)[0], j + (*q)[1], k + (*q)[2]);
      const double t = fa / (fa - fb);  // fa and fb have opposite signs (or one is 0)
      mesh_.vertices.push_back(pa + (pb - pa) * t);
    }
    return id;
  }

  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;
  const Surface& surface_;
  Grid grid_;
  TriangleMesh mesh_;
  std::array<std::vector<std::uint32_t>, 2> edge_ids_;
};

}  // namespace

TriangleMesh mesh_implicit_surface(const Surface& surface, double step, bool project_vertices) {
  if (!std::isfinite(step) || step <= 0.0) {
    std::ostringstream msg;
    msg << "implicit mesher: grid step must be finite and > 0, got " << step;
    throw InvalidInput(msg.str());
  }
  const Box3 box = surface.bounding_box();
  Grid grid;
  grid.step = step;
  grid.origin = box.lo - Vec3{2 * step, 2 * step, 2 * step};
  const Vec3 extent = box.extent();
  const double counts[3] = {std::ceil(extent.x / step) + 5, std::ceil(extent.y / step) + 5,
                            std::ceil(extent.z / step) + 5};
  if (counts[0] * counts[1] * counts[2] > 2147483647.0) {
    throw InvalidInput("implicit mesher: grid step too small (more than 2^31 nodes)");
  }
  grid.nx = static_cast<std::int64_t>(counts[0]);
  grid.ny = static_cast<std::int64_t>(counts[1]);
  grid.nz = static_cast<std::int64_t>(counts[2]);
  TriangleMesh mesh = Mesher(surface, grid).run();
  if (project_vertices) {
    for (Point3& p : mesh.vertices) p = project_along_gradient(surface, p);
  }
  return mesh;
}

double mesh_area(const TriangleMesh& mesh) {
  double total = 0.0;
  for (const auto& f : mesh.faces) {
    const Point3& a = mesh.vertices[f[0]];
    total += 0.5 * norm(cross(mesh.vertices[f[1]] - a, mesh.vertices[f[2]] - a));
  }
  return total;
}

}  // namespace rstruct::sampling
