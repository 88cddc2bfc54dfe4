#pragma once
/// \file
/// A point set with optional triangles and per-vertex scalar properties: what the readers
/// produce and the writers consume.

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "rstruct/geometry/vec3.hpp"

namespace rstruct {

struct TriangleMesh {
  std::vector<Point3> vertices;
  /// Triangles as 0-based vertex indices (polygons are fan-triangulated by readers).
  std::vector<std::array<std::uint32_t, 3>> faces;
  /// Optional per-vertex scalars (e.g. "radius", "label", "vertex_id", "weight"); each
  /// vector has vertices.size() entries.
  std::vector<std::pair<std::string, std::vector<double>>> vertex_properties;

  /// The property named `name`, or nullptr.
  const std::vector<double>* property(const std::string& name) const {
    for (const auto& [n, v] : vertex_properties) {
      if (n == name) return &v;
    }
    return nullptr;
  }
};

}  // namespace rstruct
