// PLY writer: binary little endian (default) or ASCII. Coordinates and properties are
// written as double, except integer-valued properties with integer names (label, vertex_id,
// id, index), which are written as int; faces as "list uchar int" (uint past 2^31 - 1).

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>

#include "io/formats.hpp"
#include "io/text_lines.hpp"

namespace rstruct::io::detail {

namespace {

bool has_integer_name(const std::string& name) {
  return name == "label" || name == "vertex_id" || name == "id" || name == "index";
}

// Int only when every value converts back to the same double bits (so no -0.0).
bool fits_int32(const std::vector<double>& values) {
  for (double v : values) {
    if (!(v >= std::numeric_limits<std::int32_t>::min() &&
          v <= std::numeric_limits<std::int32_t>::max()) ||
        v != std::trunc(v) || std::signbit(v) != (v < 0)) {
      return false;
    }
  }
  return true;
}

template <class T>
void append_le(std::string& out, T value) {
  static_assert(std::endian::native == std::endian::little || std::endian::native == std::endian::big);
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  if constexpr (std::endian::native == std::endian::big) {
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(bytes[i], bytes[sizeof(T) - 1 - i]);
  }
  out.append(bytes, sizeof(T));
}

void write_ascii_body(std::string& out, const TriangleMesh& mesh, const std::vector<bool>& as_int) {
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    for (std::size_t axis = 0; axis < 3; ++axis) {
      if (axis > 0) out += ' ';
      append_double(out, mesh.vertices[i][axis]);
    }
    for (std::size_t k = 0; k < mesh.vertex_properties.size(); ++k) {
      out += ' ';
      const double v = mesh.vertex_properties[k].second[i];
      if (as_int[k]) {
        out += std::to_string(static_cast<std::int64_t>(v));
      } else {
        append_double(out, v);
      }
    }
    out += '\n';
  }
  for (const auto& f : mesh.faces) {
    out += "3 " + std::to_string(f[0]) + " " + std::to_string(f[1]) + " " +
           std::to_string(f[2]) + "\n";
  }
}

void write_binary_body(std::string& out, const TriangleMesh& mesh, const std::vector<bool>& as_int) {
  out.reserve(out.size() + mesh.vertices.size() * 8 * (3 + mesh.vertex_properties.size()) +
              mesh.faces.size() * 13);
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    for (std::size_t axis = 0; axis < 3; ++axis) append_le(out, mesh.vertices[i][axis]);
    for (std::size_t k = 0; k < mesh.vertex_properties.size(); ++k) {
      const double v = mesh.vertex_properties[k].second[i];
      if (as_int[k]) {
        append_le(out, static_cast<std::int32_t>(v));
      } else {
        append_le(out, v);
      }
    }
  }
  // uint32 indices below 2^31 have the same bytes as int32 ones.
  for (const auto& f : mesh.faces) {
    append_le(out, std::uint8_t{3});
    for (std::uint32_t v : f) append_le(out, v);
  }
}

}  // namespace

void write_ply(std::string& out, const TriangleMesh& mesh, bool ascii) {
  std::vector<bool> as_int;
  for (const auto& [name, values] : mesh.vertex_properties) {
    as_int.push_back(has_integer_name(name) && fits_int32(values));
  }
  out += "ply\nformat ";
  out += ascii ? "ascii" : "binary_little_endian";
  out += " 1.0\ncomment written by rstruct\nelement vertex " +
         std::to_string(mesh.vertices.size()) +
         "\nproperty double x\nproperty double y\nproperty double z\n";
  for (std::size_t k = 0; k < mesh.vertex_properties.size(); ++k) {
    out += std::string("property ") + (as_int[k] ? "int " : "double ") +
           mesh.vertex_properties[k].first + "\n";
  }
  if (!mesh.faces.empty()) {
    const bool big = mesh.vertices.size() > static_cast<std::size_t>(INT32_MAX);
    out += "element face " + std::to_string(mesh.faces.size()) + "\nproperty list uchar " +
           (big ? "uint" : "int") + " vertex_indices\n";
  }
  out += "end_header\n";
  if (ascii) {
    write_ascii_body(out, mesh, as_int);
  } else {
    write_binary_body(out, mesh, as_int);
  }
}

}  // namespace rstruct::io::detail
