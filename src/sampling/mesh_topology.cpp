#include "rstruct/sampling/mesh_topology.hpp"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <sstream>
#include <utility>
#include <vector>

#include "rstruct/core/error.hpp"

namespace rstruct::sampling {

namespace {

std::size_t find_root(std::vector<std::size_t>& parent, std::size_t x) {
  while (parent[x] != x) {
    parent[x] = parent[parent[x]];
    x = parent[x];
  }
  return x;
}

/// Whether the link edges of one vertex (pairs of neighbour ids) form a single cycle.
bool is_single_cycle(std::vector<std::pair<std::uint32_t, std::uint32_t>>& link) {
  if (link.size() < 3) return false;
  std::vector<std::uint32_t> ends;
  for (const auto& [a, b] : link) {
    ends.push_back(a);
    ends.push_back(b);
  }
  std::sort(ends.begin(), ends.end());
  for (std::size_t i = 0; i < ends.size(); i += 2) {
    if (ends[i] != ends[i + 1] || (i + 2 < ends.size() && ends[i + 2] == ends[i])) return false;
  }
  // Every link vertex has degree 2: walk from the first edge and count the steps.
  std::size_t steps = 1;
  std::uint32_t current = link[0].second;
  std::vector<bool> used(link.size(), false);
  used[0] = true;
  while (current != link[0].first) {
    bool advanced = false;
    for (std::size_t e = 0; e < link.size() && !advanced; ++e) {
      if (used[e]) continue;
      if (link[e].first == current || link[e].second == current) {
        const std::uint32_t next = link[e].first == current ? link[e].second : link[e].first;
        used[e] = true;
        current = next;
        ++steps;
        advanced = true;
      }
    }
    if (!advanced) return false;
  }
  return steps == link.size();
}

}  // namespace

MeshTopology mesh_topology(const TriangleMesh& mesh) {
  MeshTopology t;
  const std::size_t nv = mesh.vertices.size();
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  edges.reserve(3 * mesh.faces.size());
  std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> links(nv);
  std::vector<std::size_t> parent(nv);
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  std::vector<bool> used(nv, false);
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const auto& tri = mesh.faces[f];
    for (std::size_t c = 0; c < 3; ++c) {
      if (tri[c] >= nv) {
        std::ostringstream msg;
        msg << "mesh: face " << f << " refers to vertex " << tri[c] << " of " << nv;
        throw InvalidInput(msg.str());
      }
    }
    for (std::size_t c = 0; c < 3; ++c) {
      const std::uint32_t a = tri[c], b = tri[(c + 1) % 3], o = tri[(c + 2) % 3];
      edges.emplace_back(std::min(a, b), std::max(a, b));
      links[o].emplace_back(a, b);
      used[a] = true;
      parent[find_root(parent, a)] = find_root(parent, b);
    }
  }
  std::sort(edges.begin(), edges.end());
  t.every_edge_in_two_faces = true;
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    if (j - i != 2) t.every_edge_in_two_faces = false;
    ++t.edges;
    i = j;
  }
  t.every_vertex_link_a_cycle = true;
  for (std::size_t v = 0; v < nv; ++v) {
    if (!used[v]) continue;
    ++t.vertices;
    if (find_root(parent, v) == v) ++t.components;
    if (!is_single_cycle(links[v])) t.every_vertex_link_a_cycle = false;
  }
  t.faces = mesh.faces.size();
  t.euler_characteristic = static_cast<long long>(t.vertices) - static_cast<long long>(t.edges) +
                           static_cast<long long>(t.faces);
  return t;
}

}  // namespace rstruct::sampling
