// The PLY reader against an encoder written here, independently of the library's writer:
// ASCII and binary little/big endian, float and double coordinates, integer properties of
// every width, skipped elements and list properties, polygons, header variants.

#include <rapidcheck/catch.h>

#include <bit>
#include <catch2/catch.hpp>
#include <cstring>

#include "io/mesh_generators.hpp"
#include "rstruct/core/error.hpp"
#include "rstruct/io/mesh_io.hpp"

using rstruct::TriangleMesh;
using namespace rstruct::io;
using namespace rstruct::io::testing;

namespace {

enum class Enc { ascii, little, big };

struct Encoder {
  Enc enc;
  std::string body;

  template <class T>
  void put(T value) {
    if (enc == Enc::ascii) {
      if (!body.empty() && body.back() != '\n') body += ' ';
      if constexpr (std::is_floating_point_v<T>) {
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.17g", static_cast<double>(value));
        body += buf;
      } else {
        body += std::to_string(static_cast<long long>(value));
      }
      return;
    }
    unsigned char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    const bool host_little = std::endian::native == std::endian::little;
    if ((enc == Enc::little) != host_little) std::reverse(bytes, bytes + sizeof(T));
    body.append(reinterpret_cast<const char*>(bytes), sizeof(T));
  }
  void end_line() {
    if (enc == Enc::ascii) body += '\n';
  }
};

const char* format_line(Enc e) {
  return e == Enc::ascii ? "format ascii 1.0\n"
                         : e == Enc::little ? "format binary_little_endian 1.0\n"
                                            : "format binary_big_endian 1.0\n";
}

// A PLY with coordinates as float (if `as_float`) or double, an "edge" element before the
// vertices with a list property (skipped), a vertex list property (skipped), the mesh's
// properties as double and a `flags` uchar property on faces (skipped).
std::string encode(const TriangleMesh& m, Enc e, bool as_float) {
  std::string h = "ply\n";
  h += format_line(e);
  h += "comment independent encoder\nelement edge 1\nproperty list uchar int vertex_indices\n";
  h += "element vertex " + std::to_string(m.vertices.size()) + "\n";
  const char* ct = as_float ? "float" : "double";
  h += std::string("property ") + ct + " x\nproperty list ushort short junk\nproperty " + ct +
       " y\nproperty " + ct + " z\n";
  for (const auto& [name, values] : m.vertex_properties) h += "property double " + name + "\n";
  h += "element face " + std::to_string(m.faces.size()) +
       "\nproperty uchar flags\nproperty list uint uint vertex_indices\nend_header\n";
  Encoder out{e, {}};
  out.put(std::uint8_t{2});
  out.put(std::int32_t{0});
  out.put(std::int32_t{0});
  out.end_line();
  for (std::size_t i = 0; i < m.vertices.size(); ++i) {
    if (as_float) out.put(static_cast<float>(m.vertices[i].x)); else out.put(m.vertices[i].x);
    out.put(std::uint16_t{1});
    out.put(std::int16_t{-7});
    for (std::size_t k = 1; k < 3; ++k) {
      if (as_float) out.put(static_cast<float>(m.vertices[i][k])); else out.put(m.vertices[i][k]);
    }
    for (const auto& [name, values] : m.vertex_properties) out.put(values[i]);
    out.end_line();
  }
  for (const auto& f : m.faces) {
    out.put(std::uint8_t{9});
    out.put(std::uint32_t{3});
    for (std::uint32_t v : f) out.put(v);
    out.end_line();
  }
  return h + out.body;
}

// GCC 12.2 at -O2 miscompiles `p[k] = double(float(p[k]))` over k = 0, 1, 2: the SLP
// vectorizer turns the first two into a V2DF->V2SF->V2DF pair and folds it away as the
// identity (reproducer in the io branch's note). Rounding one value per call avoids it.
[[gnu::noinline]] double through_float(double x) {
  return static_cast<double>(static_cast<float>(x));
}

// Coordinates rounded to float (what a float PLY holds), as doubles.
TriangleMesh rounded_to_float(TriangleMesh m) {
  for (auto& p : m.vertices) {
    for (std::size_t k = 0; k < 3; ++k) p[k] = through_float(p[k]);
  }
  return m;
}

rc::Gen<TriangleMesh> float_safe_mesh() {
  // Values whose float rounding is finite (the reader rejects inf from overflow).
  return rc::gen::suchThat(mesh(), [](const TriangleMesh& m) {
    for (const auto& p : m.vertices) {
      for (std::size_t k = 0; k < 3; ++k) {
        if (!std::isfinite(static_cast<float>(p[k]))) return false;
      }
    }
    return true;
  });
}

}  // namespace

TEST_CASE("PLY reader: every encoding, float and double coordinates, skipped data") {
  for (Enc e : {Enc::ascii, Enc::little, Enc::big}) {
    rc::prop("double coordinates", [e] {
      const TriangleMesh m = *mesh();
      const TriangleMesh back = read_mesh_from_memory(encode(m, e, false), Format::ply);
      RC_ASSERT(same_vertices(m, back));
      RC_ASSERT(m.faces == back.faces);
      RC_ASSERT(same_properties(m, back));
    });
    rc::prop("float coordinates", [e] {
      RC_LOG() << "encoding " << static_cast<int>(e) << '\n';
      const TriangleMesh m = rounded_to_float(*float_safe_mesh());
      const TriangleMesh back = read_mesh_from_memory(encode(m, e, true), Format::ply);
      RC_ASSERT(same_vertices(m, back));
      RC_ASSERT(m.faces == back.faces);
    });
  }
}

TEST_CASE("PLY reader: integer property types are read exactly, polygons fan-triangulated") {
  const std::string text =
      "ply\r\nformat ascii 1.0\r\nobj_info made by hand\r\nelement vertex 4\r\n"
      "property float32 x\r\nproperty float32 y\r\nproperty float32 z\r\n"
      "property char c\r\nproperty uint8 u\r\nproperty int16 s\r\nproperty ushort us\r\n"
      "property int i\r\nproperty uint ui\r\n"
      "element face 1\r\nproperty list uint8 int32 vertex_index\r\nend_header\r\n"
      "0 0 0 -128 255 -32768 65535 -2147483648 4294967295\r\n"
      "1 0 0 127 0 32767 0 2147483647 0\r\n"
      "\r\n"
      "1 1 0 0 0 0 0 0 0\r\n0 1 0 +1 1 1 1 1 1\r\n"
      "4 0 1 2 3\r\n";
  const TriangleMesh m = read_mesh_from_memory(text, Format::ply);
  REQUIRE(m.vertices.size() == 4);
  REQUIRE(m.vertex_properties.size() == 6);
  CHECK((*m.property("c"))[0] == -128);
  CHECK((*m.property("u"))[0] == 255);
  CHECK((*m.property("s"))[0] == -32768);
  CHECK((*m.property("us"))[0] == 65535);
  CHECK((*m.property("i"))[0] == -2147483648.0);
  CHECK((*m.property("ui"))[0] == 4294967295.0);
  CHECK((*m.property("c"))[3] == 1);
  REQUIRE(m.faces.size() == 2);
  CHECK(m.faces[0] == std::array<std::uint32_t, 3>{0, 1, 2});
  CHECK(m.faces[1] == std::array<std::uint32_t, 3>{0, 2, 3});
}

TEST_CASE("PLY reader: binary integer types of both endiannesses") {
  for (Enc e : {Enc::little, Enc::big}) {
    Encoder out{e, {}};
    out.put(1.5f);
    out.put(-2.0f);
    out.put(0.25f);
    out.put(std::int8_t{-5});
    out.put(std::uint16_t{60000});
    out.put(std::int32_t{-123456789});
    out.put(std::uint32_t{4000000000u});
    out.put(-0.0);
    std::string text = std::string("ply\n") + format_line(e) +
                       "element vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
                       "property char a\nproperty ushort b\nproperty int c\nproperty uint d\n"
                       "property double e\nend_header\n" + out.body;
    const TriangleMesh m = read_mesh_from_memory(text, Format::ply);
    REQUIRE(m.vertices.size() == 1);
    CHECK(m.vertices[0] == rstruct::Point3{1.5, -2.0, 0.25});
    CHECK((*m.property("a"))[0] == -5);
    CHECK((*m.property("b"))[0] == 60000);
    CHECK((*m.property("c"))[0] == -123456789);
    CHECK((*m.property("d"))[0] == 4000000000.0);
    CHECK(std::signbit((*m.property("e"))[0]));
    // Trailing bytes after the last element are tolerated.
    CHECK_NOTHROW(read_mesh_from_memory(text + "trailing", Format::ply));
    // One byte less is a truncation, reported with its byte offset.
    try {
      (void)read_mesh_from_memory(text.substr(0, text.size() - 1), Format::ply, {}, "t.ply");
      FAIL("accepted a truncated file");
    } catch (const rstruct::InvalidInput& error) {
      CHECK(std::string(error.what()).find("t.ply") != std::string::npos);
    }
  }
}

TEST_CASE("PLY reader: elements with no properties take no bytes, whatever their count") {
  const std::string text =
      "ply\nformat binary_little_endian 1.0\nelement nothing 999999999999\n"
      "element vertex 1\nproperty double x\nproperty double y\nproperty double z\nend_header\n" +
      std::string(24, '\0');
  const TriangleMesh m = read_mesh_from_memory(text, Format::ply);
  CHECK(m.vertices.size() == 1);
}

TEST_CASE("PLY reader: every prefix of a valid binary file is rejected, never accepted") {
  rc::prop("prefixes", [] {
    const TriangleMesh m = *mesh();
    const std::string bytes = encode(m, *rc::gen::element(Enc::little, Enc::big), false);
    const std::size_t cut = *rc::gen::inRange<std::size_t>(0, bytes.size());
    RC_ASSERT_THROWS_AS(read_mesh_from_memory(bytes.substr(0, cut), Format::ply),
                        rstruct::InvalidInput);
  });
}
