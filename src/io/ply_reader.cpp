// PLY body reader: one loop over the header's elements, templated on the value source
// (ASCII lines or binary bytes of either endianness). Every count is checked against what
// is left of the file before anything is allocated from it.

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "io/formats.hpp"
#include "io/ply_header.hpp"
#include "io/text_lines.hpp"
#include "rstruct/core/error.hpp"

namespace rstruct::io::detail {

namespace {

// What the reader does with one property of one element.
enum class Action { skip, coordinate, store, face_list };

struct ElementPlan {
  std::vector<Action> actions;  // one per property
  std::vector<int> slot;        // coordinate 0..2 or vertex_properties index
  bool is_vertex = false;
};

std::string describe(const PlyElement& e, std::uint64_t index) {
  return "element '" + e.name + "' #" + std::to_string(index);
}

template <class T>
T byte_swapped(T bits) {
  if constexpr (sizeof(T) == 2) return static_cast<T>(__builtin_bswap16(bits));
  if constexpr (sizeof(T) == 4) return static_cast<T>(__builtin_bswap32(bits));
  if constexpr (sizeof(T) == 8) return static_cast<T>(__builtin_bswap64(bits));
  return bits;
}

class BinarySource {
 public:
  BinarySource(std::string_view bytes, std::size_t offset, bool little_endian, std::string name)
      : bytes_(bytes), pos_(offset), name_(std::move(name)),
        swap_(little_endian != (std::endian::native == std::endian::little)) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw InvalidInput(name_ + ": byte offset " + std::to_string(pos_) + ", " +
                       describe(*element_, index_) + ": " + what);
  }

  void begin_element(const PlyElement& e) {
    element_ = &e;
    index_ = 0;
    const std::size_t min = e.min_binary_size();
    const std::size_t left = bytes_.size() - pos_;
    if (e.count > left / min) {
      throw InvalidInput(name_ + ": element '" + e.name + "' declares " + std::to_string(e.count) +
                         " instances of at least " + std::to_string(min) +
                         " bytes, but only " + std::to_string(left) + " bytes are left at offset " +
                         std::to_string(pos_) + " (truncated file or bad count)");
    }
  }
  void begin_instance(std::uint64_t index) { index_ = index; }
  void end_instance() {}

  double scalar(PlyType type) {
    switch (type) {
      case PlyType::int8: return static_cast<std::int8_t>(raw<std::uint8_t>());
      case PlyType::uint8: return raw<std::uint8_t>();
      case PlyType::int16: return static_cast<std::int16_t>(raw<std::uint16_t>());
      case PlyType::uint16: return raw<std::uint16_t>();
      case PlyType::int32: return static_cast<std::int32_t>(raw<std::uint32_t>());
      case PlyType::uint32: return raw<std::uint32_t>();
      case PlyType::float32: return std::bit_cast<float>(raw<std::uint32_t>());
      case PlyType::float64: return std::bit_cast<double>(raw<std::uint64_t>());
    }
    return 0;
  }
  // Integer types only (the header parser and the plan guarantee it); exact in int64.
  std::int64_t integer(PlyType type) { return static_cast<std::int64_t>(scalar(type)); }

  // Makes sure a list of `n` items fits before it is read or skipped.
  void reserve_list(std::int64_t n, PlyType item) {
    const std::size_t size = ply_type_size(item);
    if (static_cast<std::uint64_t>(n) > (bytes_.size() - pos_) / size) {
      fail("list of " + std::to_string(n) + " items runs past the end of the file (truncated)");
    }
  }
  void skip(PlyType type) { advance(ply_type_size(type)); }
  void skip_list(std::int64_t n, PlyType item) {
    reserve_list(n, item);
    pos_ += static_cast<std::size_t>(n) * ply_type_size(item);
  }

 private:
  void advance(std::size_t n) {
    if (bytes_.size() - pos_ < n) fail("file ends in the middle of the element (truncated)");
    pos_ += n;
  }
  template <class T>
  T raw() {
    const std::size_t at = pos_;
    advance(sizeof(T));
    T bits;
    std::memcpy(&bits, bytes_.data() + at, sizeof(T));
    return swap_ ? byte_swapped(bits) : bits;
  }

  std::string_view bytes_;
  std::size_t pos_;
  std::string name_;
  bool swap_;
  const PlyElement* element_ = nullptr;
  std::uint64_t index_ = 0;
};

class AsciiSource {
 public:
  AsciiSource(std::string_view body, std::size_t first_line, const std::string& name)
      : lines_(body, name, first_line) {}

  [[noreturn]] void fail(const std::string& what) const {
    lines_.fail(describe(*element_, index_) + ": " + what);
  }

  void begin_element(const PlyElement& e) {
    element_ = &e;
    index_ = 0;
    // One line per instance, and at least one value plus a separator per property.
    const std::size_t left = lines_.lines_left();
    const std::size_t fit = (lines_.bytes_left() + 1) / (2 * e.properties.size());
    if (e.count > left || e.count > fit) {
      throw InvalidInput(lines_.name() + ": element '" + e.name + "' declares " +
                         std::to_string(e.count) + " instances (one per line) but only " +
                         std::to_string(left) + " lines (" + std::to_string(lines_.bytes_left()) +
                         " bytes) are left after line " +
                         std::to_string(lines_.line_number()) + " (truncated file or bad count)");
    }
  }
  void begin_instance(std::uint64_t index) {
    index_ = index;
    std::string_view line;
    if (!lines_.next_content(line, 0)) {
      lines_.fail("unexpected end of file: element '" + element_->name + "' declares " +
                  std::to_string(element_->count) + " instances, found " + std::to_string(index));
    }
    tokens_ = Tokens(line);
  }
  void end_instance() {
    if (tokens_.count_left() != 0) fail("extra values at the end of the line");
  }

  double scalar(PlyType type) {
    const std::string_view token = next_token();
    if (ply_type_is_integer(type)) return static_cast<double>(integer_of(token, type));
    return parse_finite_double(token, lines_, [this] { return describe(*element_, index_); });
  }
  std::int64_t integer(PlyType type) { return integer_of(next_token(), type); }
  void reserve_list(std::int64_t n, PlyType) {
    if (static_cast<std::uint64_t>(n) > tokens_.count_left()) {
      fail("list of " + std::to_string(n) + " items but fewer values are left on the line");
    }
  }
  void skip(PlyType) { next_token(); }
  void skip_list(std::int64_t n, PlyType item) {
    reserve_list(n, item);
    for (std::int64_t i = 0; i < n; ++i) next_token();
  }

 private:
  std::string_view next_token() {
    std::string_view token;
    if (!tokens_.next(token)) fail("too few values on the line");
    return token;
  }
  std::int64_t integer_of(std::string_view token, PlyType type) {
    std::int64_t lo = 0, hi = 0;
    switch (type) {
      case PlyType::int8: lo = INT8_MIN, hi = INT8_MAX; break;
      case PlyType::uint8: hi = UINT8_MAX; break;
      case PlyType::int16: lo = INT16_MIN, hi = INT16_MAX; break;
      case PlyType::uint16: hi = UINT16_MAX; break;
      case PlyType::int32: lo = INT32_MIN, hi = INT32_MAX; break;
      default: hi = UINT32_MAX; break;
    }
    return parse_integer(token, lo, hi, lines_, [this, type] {
      return describe(*element_, index_) + " (" + ply_type_name(type) + " value)";
    });
  }

  LineReader lines_;
  Tokens tokens_{std::string_view()};
  const PlyElement* element_ = nullptr;
  std::uint64_t index_ = 0;
};

[[noreturn]] void header_fail(const std::string& name, const PlyElement& e,
                              const std::string& what) {
  throw InvalidInput(name + ":" + std::to_string(e.header_line) + ": element '" + e.name +
                     "': " + what);
}

ElementPlan plan_vertex(const PlyElement& e, TriangleMesh& mesh, const std::string& name) {
  if (e.count > std::numeric_limits<std::uint32_t>::max()) {
    header_fail(name, e, "more than 2^32 - 1 vertices are not supported");
  }
  ElementPlan plan;
  plan.is_vertex = true;
  int coordinates_found = 0;
  for (const PlyProperty& p : e.properties) {
    const int axis = p.name == "x" ? 0 : p.name == "y" ? 1 : p.name == "z" ? 2 : -1;
    if (axis >= 0) {
      if (p.is_list || ply_type_is_integer(p.type)) {
        header_fail(name, e, "property '" + p.name + "' must be float or double, not " +
                                 (p.is_list ? std::string("a list") : ply_type_name(p.type)));
      }
      plan.actions.push_back(Action::coordinate);
      plan.slot.push_back(axis);
      ++coordinates_found;
    } else if (p.is_list) {
      plan.actions.push_back(Action::skip);
      plan.slot.push_back(-1);
    } else {
      plan.actions.push_back(Action::store);
      plan.slot.push_back(static_cast<int>(mesh.vertex_properties.size()));
      mesh.vertex_properties.emplace_back(p.name, std::vector<double>());
    }
  }
  if (coordinates_found != 3) header_fail(name, e, "needs float or double properties x, y and z");
  return plan;
}

ElementPlan plan_face(const PlyElement& e, const std::string& name) {
  ElementPlan plan;
  bool found = false;
  for (const PlyProperty& p : e.properties) {
    const bool is_indices = p.name == "vertex_indices" || p.name == "vertex_index";
    if (is_indices && (!p.is_list || !ply_type_is_integer(p.type))) {
      header_fail(name, e, "property '" + p.name + "' must be a list of integers");
    }
    if (is_indices && found) header_fail(name, e, "has both vertex_indices and vertex_index");
    found = found || is_indices;
    plan.actions.push_back(is_indices ? Action::face_list : Action::skip);
    plan.slot.push_back(-1);
  }
  if (!found && e.count > 0) header_fail(name, e, "has no 'vertex_indices' list property");
  return plan;
}

template <class Source>
void read_face_list(Source& src, const PlyProperty& p, std::uint64_t vertex_count,
                    TriangleMesh& mesh) {
  const std::int64_t n = src.integer(p.count_type);
  if (n < 3) src.fail("face has " + std::to_string(n) + " vertices (at least 3 needed)");
  src.reserve_list(n, p.type);
  std::uint32_t first = 0, previous = 0;
  for (std::int64_t k = 0; k < n; ++k) {
    const std::int64_t index = src.integer(p.type);
    if (index < 0 || static_cast<std::uint64_t>(index) >= vertex_count) {
      src.fail("face vertex index " + std::to_string(index) + " is outside [0, " +
               std::to_string(vertex_count) + ")");
    }
    const auto v = static_cast<std::uint32_t>(index);
    if (k == 0) first = v;
    if (k >= 2) mesh.faces.push_back({first, previous, v});
    previous = v;
  }
}

template <class Source>
void read_element(Source& src, const PlyElement& e, const ElementPlan& plan,
                  std::uint64_t vertex_count, TriangleMesh& mesh) {
  src.begin_element(e);
  if (plan.is_vertex) {
    mesh.vertices.resize(static_cast<std::size_t>(e.count));
    for (auto& [property_name, values] : mesh.vertex_properties) values.resize(mesh.vertices.size());
  }
  for (std::uint64_t i = 0; i < e.count; ++i) {
    src.begin_instance(i);
    for (std::size_t k = 0; k < e.properties.size(); ++k) {
      const PlyProperty& p = e.properties[k];
      switch (plan.actions[k]) {
        case Action::coordinate:
        case Action::store: {
          const double value = src.scalar(p.type);
          if (!std::isfinite(value)) src.fail("property '" + p.name + "' is NaN or infinite");
          const auto slot = static_cast<std::size_t>(plan.slot[k]);
          if (plan.actions[k] == Action::coordinate) {
            mesh.vertices[i][slot] = value;
          } else {
            mesh.vertex_properties[slot].second[i] = value;
          }
          break;
        }
        case Action::face_list: read_face_list(src, p, vertex_count, mesh); break;
        case Action::skip:
          if (p.is_list) {
            const std::int64_t n = src.integer(p.count_type);
            if (n < 0) src.fail("negative list length " + std::to_string(n));
            src.skip_list(n, p.type);
          } else {
            src.skip(p.type);
          }
          break;
      }
    }
    src.end_instance();
  }
}

template <class Source>
void read_body(Source& src, const PlyHeader& header, const std::vector<ElementPlan>& plans,
               std::uint64_t vertex_count, TriangleMesh& mesh) {
  for (std::size_t k = 0; k < header.elements.size(); ++k) {
    // An element without properties occupies no bytes, whatever its count.
    if (header.elements[k].properties.empty()) continue;
    read_element(src, header.elements[k], plans[k], vertex_count, mesh);
  }
}

}  // namespace

TriangleMesh read_ply(std::string_view bytes, const std::string& name) {
  const PlyHeader header = parse_ply_header(bytes, name);
  TriangleMesh mesh;
  std::vector<ElementPlan> plans;
  std::uint64_t vertex_count = 0;
  bool have_vertex = false;
  for (const PlyElement& e : header.elements) {
    if (e.name == "vertex") {
      plans.push_back(plan_vertex(e, mesh, name));
      vertex_count = e.count;
      have_vertex = true;
    } else if (e.name == "face") {
      plans.push_back(plan_face(e, name));
    } else {
      plans.push_back(ElementPlan{std::vector<Action>(e.properties.size(), Action::skip),
                                  std::vector<int>(e.properties.size(), -1), false});
    }
  }
  if (!have_vertex) throw InvalidInput(name + ": PLY header declares no 'vertex' element");
  if (vertex_count == 0) require_vertices(mesh, name);
  if (header.encoding == PlyEncoding::ascii) {
    AsciiSource src(bytes.substr(header.body_offset), header.body_first_line, name);
    read_body(src, header, plans, vertex_count, mesh);
  } else {
    BinarySource src(bytes, header.body_offset,
                     header.encoding == PlyEncoding::binary_little_endian, name);
    read_body(src, header, plans, vertex_count, mesh);
  }
  return mesh;
}

}  // namespace rstruct::io::detail
