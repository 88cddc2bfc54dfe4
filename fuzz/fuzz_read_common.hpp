#pragma once
// Shared body of the reader fuzz targets (fuzz_read_{ply,off,obj,xyz}.cpp): the reader
// either throws InvalidInput or returns a well-formed mesh; a well-formed mesh survives a
// round trip through binary PLY, ASCII PLY and its own format bit for bit. Anything else
// (another exception, a broken invariant, a sanitizer report) is a crash.

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "rstruct/core/error.hpp"
#include "rstruct/io/mesh_io.hpp"

namespace rstruct::fuzz {

[[noreturn]] inline void fuzz_fail(const char* what) {
  std::fprintf(stderr, "fuzz invariant violated: %s\n", what);
  std::abort();
}

inline bool same_bits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

inline void check_well_formed(const TriangleMesh& m) {
  if (m.vertices.empty()) fuzz_fail("reader returned no vertices");
  for (const Point3& p : m.vertices) {
    if (!is_finite(p)) fuzz_fail("non-finite coordinate");
  }
  for (const auto& f : m.faces) {
    for (std::uint32_t v : f) {
      if (v >= m.vertices.size()) fuzz_fail("face index out of range");
    }
  }
  for (const auto& [name, values] : m.vertex_properties) {
    if (values.size() != m.vertices.size()) fuzz_fail("property size");
    for (double v : values) {
      if (!std::isfinite(v)) fuzz_fail("non-finite property");
    }
  }
}

// Compares what `format` keeps of `a` with `b`.
inline void check_same(const TriangleMesh& a, const TriangleMesh& b, io::Format format,
                       const char* what) {
  if (a.vertices.size() != b.vertices.size()) fuzz_fail(what);
  for (std::size_t i = 0; i < a.vertices.size(); ++i) {
    for (std::size_t k = 0; k < 3; ++k) {
      if (!same_bits(a.vertices[i][k], b.vertices[i][k])) fuzz_fail(what);
    }
  }
  if (format != io::Format::xyz && a.faces != b.faces) fuzz_fail(what);
  if (format != io::Format::ply) return;
  if (a.vertex_properties.size() != b.vertex_properties.size()) fuzz_fail(what);
  for (std::size_t k = 0; k < a.vertex_properties.size(); ++k) {
    if (a.vertex_properties[k].first != b.vertex_properties[k].first) fuzz_fail(what);
    for (std::size_t i = 0; i < a.vertices.size(); ++i) {
      if (!same_bits(a.vertex_properties[k].second[i], b.vertex_properties[k].second[i])) {
        fuzz_fail(what);
      }
    }
  }
}

inline void round_trip(const TriangleMesh& m, io::Format format, bool ascii, const char* what) {
  const std::string bytes = io::write_mesh_to_string(m, io::WriteOptions{format, ascii});
  const TriangleMesh back = io::read_mesh_from_memory(bytes, format, {}, "round-trip");
  check_same(m, back, format, what);
}

// Reads `data` as `format`; checks the result and its round trips.
inline void fuzz_reader(const std::uint8_t* data, std::size_t size, io::Format format,
                        const io::ReadOptions& options = {}) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  TriangleMesh m;
  try {
    m = io::read_mesh_from_memory(bytes, format, options, "fuzz-input");
  } catch (const InvalidInput&) {
    return;
  }
  check_well_formed(m);
  round_trip(m, io::Format::ply, false, "binary PLY round trip");
  round_trip(m, io::Format::ply, true, "ASCII PLY round trip");
  if (format != io::Format::ply) round_trip(m, format, false, "own-format round trip");
  TriangleMesh copy = m;
  const std::size_t expected = io::count_duplicate_vertices(m);
  if (io::remove_duplicate_vertices(copy) != expected) fuzz_fail("duplicate count");
  if (io::count_duplicate_vertices(copy) != 0) fuzz_fail("duplicates left");
}

}  // namespace rstruct::fuzz
