// Exact duplicate vertices (DESIGN.md §0: coordinates are never rounded, so only points
// with equal doubles are the same point). Equality of doubles is bitwise equality except
// for ±0, which is why the hash key maps -0.0 to 0.0.

#include <bit>
#include <cstdint>
#include <unordered_map>

#include "rstruct/core/error.hpp"
#include "rstruct/io/mesh_io.hpp"

namespace rstruct::io {

namespace {

struct PointKey {
  std::uint64_t bits[3];
  friend bool operator==(const PointKey&, const PointKey&) = default;
};

struct PointKeyHash {
  std::size_t operator()(const PointKey& k) const {
    std::uint64_t h = 0x9e3779b97f4a7c15ull;
    for (std::uint64_t b : k.bits) {
      h ^= b + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
      h *= 0xff51afd7ed558ccdull;
    }
    return static_cast<std::size_t>(h ^ (h >> 33));
  }
};

PointKey key_of(const Point3& p) {
  // Adding 0.0 turns -0.0 into +0.0 and leaves every other (finite) value unchanged.
  return {{std::bit_cast<std::uint64_t>(p.x + 0.0), std::bit_cast<std::uint64_t>(p.y + 0.0),
           std::bit_cast<std::uint64_t>(p.z + 0.0)}};
}

// first_of[i] = index of the first vertex equal to vertex i.
std::vector<std::uint32_t> first_occurrences(const TriangleMesh& mesh) {
  std::unordered_map<PointKey, std::uint32_t, PointKeyHash> seen;
  seen.reserve(mesh.vertices.size());
  std::vector<std::uint32_t> first_of(mesh.vertices.size());
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const auto [it, inserted] = seen.try_emplace(key_of(mesh.vertices[i]),
                                                 static_cast<std::uint32_t>(i));
    first_of[i] = it->second;
  }
  return first_of;
}

}  // namespace

std::size_t count_duplicate_vertices(const TriangleMesh& mesh) {
  const std::vector<std::uint32_t> first_of = first_occurrences(mesh);
  std::size_t duplicates = 0;
  for (std::size_t i = 0; i < first_of.size(); ++i) duplicates += first_of[i] != i;
  return duplicates;
}

std::size_t remove_duplicate_vertices(TriangleMesh& mesh, std::vector<std::uint32_t>* old_to_new) {
  for (const auto& [name, values] : mesh.vertex_properties) {
    if (values.size() != mesh.vertices.size()) {
      throw InvalidInput("vertex property '" + name + "' has " + std::to_string(values.size()) +
                         " values for " + std::to_string(mesh.vertices.size()) + " vertices");
    }
  }
  for (const auto& face : mesh.faces) {
    for (std::uint32_t v : face) {
      if (v >= mesh.vertices.size()) {
        throw InvalidInput("a face refers to vertex " + std::to_string(v) + " of " +
                           std::to_string(mesh.vertices.size()));
      }
    }
  }
  const std::vector<std::uint32_t> first_of = first_occurrences(mesh);
  std::vector<std::uint32_t> map(mesh.vertices.size());
  std::uint32_t kept = 0;
  for (std::size_t i = 0; i < first_of.size(); ++i) {
    if (first_of[i] == i) {
      map[i] = kept;
      mesh.vertices[kept] = mesh.vertices[i];
      for (auto& [name, values] : mesh.vertex_properties) values[kept] = values[i];
      ++kept;
    } else {
      map[i] = map[first_of[i]];
    }
  }
  const std::size_t removed = mesh.vertices.size() - kept;
  mesh.vertices.resize(kept);
  for (auto& [name, values] : mesh.vertex_properties) values.resize(kept);
  for (auto& face : mesh.faces) {
    for (std::uint32_t& v : face) v = map[v];
  }
  if (old_to_new != nullptr) *old_to_new = std::move(map);
  return removed;
}

}  // namespace rstruct::io
