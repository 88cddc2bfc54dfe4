#include "rstruct/sampling/loop_subdivision.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <sstream>
#include <utility>
#include <vector>

#include "rstruct/core/error.hpp"

namespace rstruct::sampling {

namespace {

struct EdgeUse {
  std::uint64_t key;     // (min vertex) << 32 | (max vertex)
  std::uint32_t face;
  std::uint32_t opposite;  // vertex of `face` not on the edge
};

std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
  if (a > b) std::swap(a, b);
  return (std::uint64_t{a} << 32) | b;
}

void check_mesh(const TriangleMesh& mesh) {
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    if (!is_finite(mesh.vertices[i])) {
      std::ostringstream msg;
      msg << "Loop subdivision: vertex " << i << " is not finite";
      throw InvalidInput(msg.str());
    }
  }
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const auto& t = mesh.faces[f];
    for (std::uint32_t v : t) {
      if (v >= mesh.vertices.size()) {
        std::ostringstream msg;
        msg << "Loop subdivision: face " << f << " refers to vertex " << v
            << " but the mesh has " << mesh.vertices.size() << " vertices";
        throw InvalidInput(msg.str());
      }
    }
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) {
      std::ostringstream msg;
      msg << "Loop subdivision: face " << f << " repeats a vertex";
      throw InvalidInput(msg.str());
    }
  }
}

TriangleMesh subdivide_once(const TriangleMesh& mesh) {
  const std::size_t n = mesh.vertices.size();
  const std::size_t faces = mesh.faces.size();
  if (4 * faces > (std::size_t{1} << 31)) {
    throw InvalidInput("Loop subdivision: the result would exceed 2^31 faces");
  }
  std::vector<EdgeUse> uses;
  uses.reserve(3 * faces);
  for (std::size_t f = 0; f < faces; ++f) {
    const auto& t = mesh.faces[f];
    for (int k = 0; k < 3; ++k) {
      uses.push_back({edge_key(t[k], t[(k + 1) % 3]), static_cast<std::uint32_t>(f),
                      t[(k + 2) % 3]});
    }
  }
  std::sort(uses.begin(), uses.end(), [](const EdgeUse& x, const EdgeUse& y) {
    return x.key < y.key || (x.key == y.key && x.face < y.face);
  });
  // Every edge must appear exactly twice.
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    while (j < uses.size() && uses[j].key == uses[i].key) ++j;
    if (j - i != 2) {
      std::ostringstream msg;
      msg << "Loop subdivision: edge (" << (uses[i].key >> 32) << ", "
          << (uses[i].key & 0xffffffffU) << ") lies in " << (j - i)
          << " faces; the mesh must be closed with every edge in exactly two faces";
      throw InvalidInput(msg.str());
    }
    i = j;
  }
  const std::size_t edges = uses.size() / 2;

  TriangleMesh out;
  out.vertices.resize(n + edges);
  // Updated old vertices: neighbour sums and valences over the edges.
  std::vector<Vec3> sum(n, Vec3{});
  std::vector<std::uint32_t> valence(n, 0);
  for (std::size_t e = 0; e < edges; ++e) {
    const auto a = static_cast<std::uint32_t>(uses[2 * e].key >> 32);
    const auto b = static_cast<std::uint32_t>(uses[2 * e].key & 0xffffffffU);
    sum[a] += mesh.vertices[b];
    sum[b] += mesh.vertices[a];
    ++valence[a];
    ++valence[b];
    const Point3& pa = mesh.vertices[a];
    const Point3& pb = mesh.vertices[b];
    const Point3& pc = mesh.vertices[uses[2 * e].opposite];
    const Point3& pd = mesh.vertices[uses[2 * e + 1].opposite];
    out.vertices[n + e] = Point3{0.375 * (pa.x + pb.x) + 0.125 * (pc.x + pd.x),
                                 0.375 * (pa.y + pb.y) + 0.125 * (pc.y + pd.y),
                                 0.375 * (pa.z + pb.z) + 0.125 * (pc.z + pd.z)};
  }
  for (std::size_t v = 0; v < n; ++v) {
    if (valence[v] == 0) {  // a vertex in no face stays where it is
      out.vertices[v] = mesh.vertices[v];
      continue;
    }
    const double k = valence[v];
    const double c = 0.375 + 0.25 * std::cos(2.0 * std::numbers::pi / k);
    const double beta = (0.625 - c * c) / k;
    const Point3& p = mesh.vertices[v];
    const double keep = 1.0 - k * beta;
    out.vertices[v] = Point3{keep * p.x + beta * sum[v].x, keep * p.y + beta * sum[v].y,
                             keep * p.z + beta * sum[v].z};
  }
  // Edge vertex id per (face, side): side k is the edge (t[k], t[k+1]).
  std::vector<std::uint32_t> edge_vertex(3 * faces);
  for (std::size_t e = 0; e < edges; ++e) {
    for (int s = 0; s < 2; ++s) {
      const EdgeUse& u = uses[2 * e + s];
      const auto& t = mesh.faces[u.face];
      int side = 0;
      while (t[(side + 2) % 3] != u.opposite) ++side;
      edge_vertex[3 * std::size_t{u.face} + side] = static_cast<std::uint32_t>(n + e);
    }
  }
  out.faces.reserve(4 * faces);
  for (std::size_t f = 0; f < faces; ++f) {
    const auto& t = mesh.faces[f];
    const std::uint32_t ab = edge_vertex[3 * f];
    const std::uint32_t bc = edge_vertex[3 * f + 1];
    const std::uint32_t ca = edge_vertex[3 * f + 2];
    out.faces.push_back({t[0], ab, ca});
    out.faces.push_back({t[1], bc, ab});
    out.faces.push_back({t[2], ca, bc});
    out.faces.push_back({ab, bc, ca});
  }
  return out;
}

}  // namespace

TriangleMesh loop_subdivide(const TriangleMesh& mesh, unsigned levels) {
  check_mesh(mesh);
  if (levels > 0 && mesh.faces.empty()) {
    throw InvalidInput("Loop subdivision: the mesh has no faces");
  }
  TriangleMesh current;
  current.vertices = mesh.vertices;
  current.faces = mesh.faces;
  for (unsigned level = 0; level < levels; ++level) current = subdivide_once(current);
  return current;
}

}  // namespace rstruct::sampling
