#include "io/ply_header.hpp"

#include <array>
#include <limits>
#include <utility>

#include "io/text_lines.hpp"
#include "rstruct/core/error.hpp"

namespace rstruct::io::detail {

namespace {

struct TypeName {
  const char* name;
  PlyType type;
};

// Both the original PLY names and the sized aliases of later writers.
constexpr std::array<TypeName, 16> kTypeNames{{
    {"char", PlyType::int8},     {"uchar", PlyType::uint8},    {"short", PlyType::int16},
    {"ushort", PlyType::uint16}, {"int", PlyType::int32},      {"uint", PlyType::uint32},
    {"float", PlyType::float32}, {"double", PlyType::float64}, {"int8", PlyType::int8},
    {"uint8", PlyType::uint8},   {"int16", PlyType::int16},    {"uint16", PlyType::uint16},
    {"int32", PlyType::int32},   {"uint32", PlyType::uint32},  {"float32", PlyType::float32},
    {"float64", PlyType::float64},
}};

PlyType parse_type(std::string_view token, const LineReader& where) {
  for (const TypeName& t : kTypeNames) {
    if (token == t.name) return t.type;
  }
  where.fail("unknown PLY property type " + quoted(token));
}

// Rest of the line after the keyword must be exactly `expected` tokens.
void expect_tokens(Tokens tokens, std::size_t expected, const LineReader& where,
                   const char* usage) {
  if (tokens.count_left() != expected) where.fail(std::string("malformed header line, expected '") + usage + "'");
}

void parse_format_line(Tokens tokens, PlyHeader& header, const LineReader& where) {
  expect_tokens(tokens, 2, where, "format ascii|binary_little_endian|binary_big_endian 1.0");
  std::string_view encoding, version;
  tokens.next(encoding);
  tokens.next(version);
  if (encoding == "ascii") {
    header.encoding = PlyEncoding::ascii;
  } else if (encoding == "binary_little_endian") {
    header.encoding = PlyEncoding::binary_little_endian;
  } else if (encoding == "binary_big_endian") {
    header.encoding = PlyEncoding::binary_big_endian;
  } else {
    where.fail("unknown PLY format " + quoted(encoding));
  }
  if (version != "1.0" && version != "1") where.fail("unsupported PLY version " + quoted(version));
}

void parse_element_line(Tokens tokens, PlyHeader& header, const LineReader& where) {
  expect_tokens(tokens, 2, where, "element NAME COUNT");
  std::string_view name, count;
  tokens.next(name);
  tokens.next(count);
  for (const PlyElement& e : header.elements) {
    if (e.name == name) where.fail("duplicate element " + quoted(name));
  }
  if (!is_ply_name(name)) where.fail("invalid element name " + quoted(name));
  PlyElement element;
  element.name = std::string(name);
  element.count = static_cast<std::uint64_t>(
      parse_integer(count, 0, std::numeric_limits<std::int64_t>::max(), where,
                    "count of element " + quoted(name)));
  element.header_line = where.line_number();
  header.elements.push_back(std::move(element));
}

void parse_property_line(Tokens tokens, PlyHeader& header, const LineReader& where) {
  if (header.elements.empty()) where.fail("property declared before any element");
  PlyElement& element = header.elements.back();
  PlyProperty property;
  std::string_view first;
  if (!tokens.next(first)) where.fail("malformed header line, expected 'property TYPE NAME'");
  if (first == "list") {
    expect_tokens(tokens, 3, where, "property list COUNT_TYPE ITEM_TYPE NAME");
    std::string_view count_type, item_type;
    tokens.next(count_type);
    tokens.next(item_type);
    property.is_list = true;
    property.count_type = parse_type(count_type, where);
    if (!ply_type_is_integer(property.count_type)) {
      where.fail("list count type must be an integer type, found " + quoted(count_type));
    }
    property.type = parse_type(item_type, where);
  } else {
    expect_tokens(tokens, 1, where, "property TYPE NAME");
    property.type = parse_type(first, where);
  }
  std::string_view name;
  tokens.next(name);
  if (element.find(name) >= 0) {
    where.fail("duplicate property " + quoted(name) + " in element " + quoted(element.name));
  }
  if (!is_ply_name(name)) where.fail("invalid property name " + quoted(name));
  property.name = std::string(name);
  element.properties.push_back(std::move(property));
}

}  // namespace

std::size_t ply_type_size(PlyType type) {
  switch (type) {
    case PlyType::int8:
    case PlyType::uint8: return 1;
    case PlyType::int16:
    case PlyType::uint16: return 2;
    case PlyType::int32:
    case PlyType::uint32:
    case PlyType::float32: return 4;
    case PlyType::float64: return 8;
  }
  return 8;
}

bool ply_type_is_integer(PlyType type) {
  return type != PlyType::float32 && type != PlyType::float64;
}

const char* ply_type_name(PlyType type) {
  return kTypeNames[static_cast<std::size_t>(type)].name;
}

std::size_t PlyElement::min_binary_size() const {
  std::size_t size = 0;
  for (const PlyProperty& p : properties) {
    size += ply_type_size(p.is_list ? p.count_type : p.type);
  }
  return size;
}

int PlyElement::find(std::string_view property_name) const {
  for (std::size_t i = 0; i < properties.size(); ++i) {
    if (properties[i].name == property_name) return static_cast<int>(i);
  }
  return -1;
}

PlyHeader parse_ply_header(std::string_view bytes, const std::string& name) {
  LineReader lines(bytes, name);
  std::string_view line;
  if (!lines.next(line) || line != "ply") {
    throw InvalidInput(name + ": not a PLY file (the first line must be 'ply')");
  }
  PlyHeader header;
  bool have_format = false;
  while (true) {
    if (!lines.next(line)) {
      throw InvalidInput(name + ": PLY header has no 'end_header' line (truncated file?)");
    }
    Tokens tokens(line);
    std::string_view keyword;
    if (!tokens.next(keyword)) continue;
    if (keyword == "comment" || keyword == "obj_info") continue;
    if (keyword == "end_header") break;
    if (keyword == "format") {
      if (have_format) lines.fail("second 'format' line");
      parse_format_line(tokens, header, lines);
      have_format = true;
    } else if (!have_format) {
      lines.fail("PLY header must give 'format' before " + quoted(keyword));
    } else if (keyword == "element") {
      parse_element_line(tokens, header, lines);
    } else if (keyword == "property") {
      parse_property_line(tokens, header, lines);
    } else {
      lines.fail("unknown PLY header keyword " + quoted(keyword));
    }
  }
  if (!have_format) lines.fail("PLY header has no 'format' line");
  header.body_first_line = lines.line_number() + 1;
  // The body starts right after the end_header line's '\n'.
  const std::size_t end = static_cast<std::size_t>(line.data() - bytes.data()) + line.size();
  const std::size_t newline = bytes.find('\n', end);
  header.body_offset = newline == std::string_view::npos ? bytes.size() : newline + 1;
  return header;
}

}  // namespace rstruct::io::detail
