#pragma once
// RapidCheck generators of well-formed meshes for the I/O tests: coordinates from every
// corner of binary64 (random bit patterns, subnormals, ±0, small integers so that exact
// duplicates occur), optional named properties, triangles with valid indices.

#include <rapidcheck.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "rstruct/geometry/triangle_mesh.hpp"

namespace rstruct::io::testing {

inline rc::Gen<double> finite_double() {
  const auto any_bits = rc::gen::suchThat(
      rc::gen::map(rc::gen::arbitrary<std::uint64_t>(),
                   [](std::uint64_t bits) { return std::bit_cast<double>(bits); }),
      [](double x) { return std::isfinite(x); });
  const auto small_integer = rc::gen::map(rc::gen::inRange(-3, 4),
                                          [](int k) { return static_cast<double>(k); });
  const auto decimal = rc::gen::map(rc::gen::inRange(-100000, 100000),
                                    [](int k) { return k / 1000.0; });
  const auto special = rc::gen::element(0.0, -0.0, 5e-324, -2.2250738585072014e-308,
                                        1.7976931348623157e308, 0.1, 1.0 / 3.0);
  return rc::gen::oneOf(any_bits, small_integer, decimal, special);
}

inline rc::Gen<TriangleMesh> mesh(bool with_faces = true, bool with_properties = true) {
  return rc::gen::exec([=] {
    TriangleMesh m;
    const int n = *rc::gen::inRange(1, 40);
    for (int i = 0; i < n; ++i) {
      m.vertices.push_back({*finite_double(), *finite_double(), *finite_double()});
    }
    if (with_properties) {
      const std::vector<std::string> pool{"radius", "label", "vertex_id", "weight", "quality"};
      for (const std::string& name : pool) {
        if (!*rc::gen::arbitrary<bool>()) continue;
        std::vector<double> values;
        const bool integral = *rc::gen::arbitrary<bool>();
        for (int i = 0; i < n; ++i) {
          values.push_back(integral ? static_cast<double>(*rc::gen::inRange(-1000, 1000))
                                    : *finite_double());
        }
        m.vertex_properties.emplace_back(name, std::move(values));
      }
    }
    if (with_faces) {
      const int nf = *rc::gen::inRange(0, 30);
      const auto index = rc::gen::inRange<std::uint32_t>(0, static_cast<std::uint32_t>(n));
      for (int f = 0; f < nf; ++f) m.faces.push_back({*index, *index, *index});
    }
    return m;
  });
}

/// Bitwise equality of two doubles (so -0.0 != 0.0 and every bit must survive).
inline bool same_bits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

/// Empty if the vertices are bitwise equal, else the first difference (hexfloat).
inline std::string vertex_difference(const TriangleMesh& a, const TriangleMesh& b) {
  if (a.vertices.size() != b.vertices.size()) {
    return std::to_string(a.vertices.size()) + " vs " + std::to_string(b.vertices.size()) +
           " vertices";
  }
  for (std::size_t i = 0; i < a.vertices.size(); ++i) {
    for (std::size_t k = 0; k < 3; ++k) {
      if (!same_bits(a.vertices[i][k], b.vertices[i][k])) {
        char text[128];
        std::snprintf(text, sizeof text, "vertex %zu coordinate %zu: %a vs %a", i, k,
                      a.vertices[i][k], b.vertices[i][k]);
        return text;
      }
    }
  }
  return {};
}

inline bool same_vertices(const TriangleMesh& a, const TriangleMesh& b) {
  const std::string difference = vertex_difference(a, b);
  if (!difference.empty()) RC_LOG() << difference << '\n';
  return difference.empty();
}

inline bool same_properties(const TriangleMesh& a, const TriangleMesh& b) {
  if (a.vertex_properties.size() != b.vertex_properties.size()) return false;
  for (std::size_t k = 0; k < a.vertex_properties.size(); ++k) {
    const auto& [na, va] = a.vertex_properties[k];
    const auto& [nb, vb] = b.vertex_properties[k];
    if (na != nb || va.size() != vb.size()) return false;
    for (std::size_t i = 0; i < va.size(); ++i) {
      if (!same_bits(va[i], vb[i])) return false;
    }
  }
  return true;
}

}  // namespace rstruct::io::testing
