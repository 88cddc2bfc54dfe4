#pragma once
// The header of a PLY file (Turk's polygon file format): encoding, and the elements with
// their counts and properties, validated before any body data is read.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace rstruct::io::detail {

enum class PlyType { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

/// Size in bytes of a binary value of this type.
std::size_t ply_type_size(PlyType type);
bool ply_type_is_integer(PlyType type);
/// The canonical header name ("char", "uchar", ..., "double").
const char* ply_type_name(PlyType type);

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::float64;  // for lists: the item type
  bool is_list = false;
  PlyType count_type = PlyType::uint8;  // lists only
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
  std::size_t header_line = 0;

  /// The smallest number of bytes one binary instance can take (lists empty).
  std::size_t min_binary_size() const;
  /// Index of the property named `name`, or -1.
  int find(std::string_view property_name) const;
};

enum class PlyEncoding { ascii, binary_little_endian, binary_big_endian };

struct PlyHeader {
  PlyEncoding encoding = PlyEncoding::ascii;
  std::vector<PlyElement> elements;
  /// Byte offset of the first body byte (just after "end_header\n").
  std::size_t body_offset = 0;
  /// Line number of the first body line (ASCII).
  std::size_t body_first_line = 0;
};

/// Parses and validates the header at the start of `bytes`.
/// \throws InvalidInput naming `name` and the header line for anything malformed.
PlyHeader parse_ply_header(std::string_view bytes, const std::string& name);

}  // namespace rstruct::io::detail
