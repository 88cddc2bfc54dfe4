// OFF, OBJ and XYZ readers on the variants found in the wild: keyword prefixes, colours,
// comments everywhere, CRLF line ends, OBJ texture/normal indices and relative indices,
// XYZ commas and extra columns.

#include <catch2/catch.hpp>

#include "rstruct/core/error.hpp"
#include "rstruct/io/mesh_io.hpp"

using rstruct::Point3;
using rstruct::TriangleMesh;
using namespace rstruct::io;
using Tri = std::array<std::uint32_t, 3>;

namespace {

std::string error_of(std::string_view bytes, Format f, const ReadOptions& options = {}) {
  try {
    (void)read_mesh_from_memory(bytes, f, options, "in");
  } catch (const rstruct::InvalidInput& error) {
    return error.what();
  }
  return "accepted";
}

}  // namespace

TEST_CASE("OFF: keyword variants, colours, comments, counts anywhere") {
  const TriangleMesh a = read_mesh_from_memory(
      "# leading comment\r\nCOFF # colour\r\n\r\n4 2 5\r\n0 0 0 255 0 0 255\r\n"
      "1 0 0 0 255 0 255\r\n0 1 0 # comment\r\n0 0 1\r\n3 0 1 2 0.5 0.5 0.5\r\n"
      "4 0 1 2 3\r\n",
      Format::off);
  CHECK(a.vertices.size() == 4);
  CHECK(a.vertices[1] == Point3{1, 0, 0});
  CHECK(a.faces == std::vector<Tri>{{0, 1, 2}, {0, 1, 2}, {0, 2, 3}});
  // Counts on the keyword line, no edge count.
  const TriangleMesh b = read_mesh_from_memory("OFF 3 1\n0 0 0\n1 0 0\n0 1 0\n3 2 1 0\n", Format::off);
  CHECK(b.faces == std::vector<Tri>{{2, 1, 0}});
  // No keyword at all; STCNOFF prefixes.
  CHECK(read_mesh_from_memory("1 0 0\n+1.5 -2e3 .25\n", Format::off).vertices[0] ==
        Point3{1.5, -2000, 0.25});
  CHECK(read_mesh_from_memory("STCNOFF\n1 0 0\n1 2 3 0 0 1 1 1 1 1 0.5 0.5\n", Format::off)
            .vertices.size() == 1);
  CHECK(error_of("nOFF\n3\n1 0 0\n1 2 3\n", Format::off).find("unsupported OFF variant") !=
        std::string::npos);
}

TEST_CASE("OFF: messages name the line") {
  CHECK(error_of("OFF\n2 0 0\n0 0 0\n\n# x\n1 0 zz\n", Format::off) ==
        "in:6: vertex 1: expected a number, found 'zz'");
}

TEST_CASE("OBJ: vertices and faces among the other statements") {
  const TriangleMesh m = read_mesh_from_memory(
      "# comment\nmtllib a.mtl\no thing\ng group\nv 0 0 0 1.0\nv 1 0 0 1 0.5 0.5 0.5\n"
      "vt 0 0\nvn 0 0 1\nv 0 1 0\nv 0 0 1\nusemtl red\ns off\n"
      "f 1/1/1 2/1/1 3/1/1\nf 1//1 3//1 4//1\nf -4 -3 -2 -1\nl 1 2\np 1\n",
      Format::obj);
  CHECK(m.vertices.size() == 4);
  CHECK(m.vertices[3] == Point3{0, 0, 1});
  CHECK(m.faces == std::vector<Tri>{{0, 1, 2}, {0, 2, 3}, {0, 1, 2}, {0, 2, 3}});
  // Forward references are allowed (checked once the vertex count is known).
  CHECK(read_mesh_from_memory("f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n", Format::obj).faces.size() == 1);
  CHECK(error_of("v 0 0 0\nf 1 2 3\nv 1 0 0\n", Format::obj) ==
        "in:2: face vertex index 3 but the file has only 2 vertices");
}

TEST_CASE("XYZ: blanks or commas, extra columns, optional fourth column") {
  const TriangleMesh m =
      read_mesh_from_memory("# x y z\n1,2,3\n4 5 6 7 255 0 0\n\t7, 8 ,9,10\r\n", Format::xyz);
  CHECK(m.vertices == std::vector<Point3>{{1, 2, 3}, {4, 5, 6}, {7, 8, 9}});
  CHECK(m.vertex_properties.empty());
  ReadOptions r;
  r.xyz_fourth_column = "weight";
  const TriangleMesh w = read_mesh_from_memory("1 2 3 0.5\n4 5 6 -1 9\n", Format::xyz, r);
  REQUIRE(w.property("weight") != nullptr);
  CHECK(*w.property("weight") == std::vector<double>{0.5, -1});
  CHECK(error_of("1 2 3 0.5\n4 5 6\n", Format::xyz, r) ==
        "in:2: expected x y z weight (4 columns)");
  CHECK(error_of("1 2 3 inf\n", Format::xyz, r).find("NaN/Inf") != std::string::npos);
}

TEST_CASE("every reader rejects empty input") {
  for (Format f : {Format::ply, Format::off, Format::obj, Format::xyz}) {
    INFO(format_name(f));
    CHECK(error_of("", f) != "accepted");
    CHECK(error_of("\n\n", f) != "accepted");
  }
}
