// The .ma and PLY writers and the .xyzr reader.

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "rstruct/core/error.hpp"
#include "rstruct/medial/medial_axis_io.hpp"
#include "rstruct/medial/xyzr_format.hpp"

using namespace rstruct;
using namespace rstruct::medial;

TEST_CASE(".ma of three balls in a triangle", "[medial][io]") {
  const std::vector<Ball> balls{{{0, 0, 0}, 1.3}, {{2, 0, 0}, 1.3}, {{1, 1.75, 0}, 1.3}};
  const MedialAxis axis = medial_axis_of_union(balls);
  std::ostringstream out;
  write_ma(out, axis);
  std::istringstream in(out.str());
  std::size_t nv = 0, ne = 0, nf = 0;
  in >> nv >> ne >> nf;
  CHECK(nv == 3);
  CHECK(ne == 3);
  CHECK(nf == 1);
  std::string tag;
  double x, y, z, r;
  in >> tag >> x >> y >> z >> r;
  CHECK(tag == "v");
  CHECK(r == 1.3);
}

TEST_CASE(".ma lists fan diagonals as edges", "[medial][io]") {
  MedialAxis axis;
  axis.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  axis.radius = {1, 1, 1, 1};
  axis.kind.assign(4, MedialVertexKind::cut);
  axis.source.assign(4, 0);
  axis.faces = {{0, 1, 2, 3}};
  std::ostringstream out;
  write_ma(out, axis);
  CHECK(out.str().rfind("4 5 2\n", 0) == 0);
}

TEST_CASE("PLY and .ma files are written by extension", "[medial][io]") {
  const std::vector<Ball> balls{{{0, 0, 0}, 1.0}, {{1.5, 0, 0}, 0.75}};
  const MedialAxis axis = medial_axis_of_union(balls);
  const auto dir = std::filesystem::temp_directory_path();
  const auto ply = dir / "rstruct_test_medial_axis.ply";
  const auto ma = dir / "rstruct_test_medial_axis.ma";
  write_medial_axis(ply, axis);
  write_medial_axis(ma, axis);
  std::ifstream a(ply), b(ma);
  std::string first;
  std::getline(a, first);
  CHECK(first == "ply");
  std::getline(b, first);
  CHECK(first == "2 1 0");
  std::filesystem::remove(ply);
  std::filesystem::remove(ma);
}

TEST_CASE("xyzr: comments, blank lines, commas and tabs", "[medial][io]") {
  const auto balls = parse_xyzr("# balls\n\n1 2 3 0.5\n4,5,6,1e-1\r\n\t7\t8 9 2  \n");
  REQUIRE(balls.size() == 3);
  CHECK(balls[1].c == Point3{4, 5, 6});
  CHECK(balls[1].r == 0.1);
  CHECK(balls[2].r == 2);
}

TEST_CASE("xyzr: malformed input names the line", "[medial][io]") {
  auto message = [](const char* text) {
    try {
      parse_xyzr(text, "in.xyzr");
    } catch (const InvalidInput& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CHECK(message("1 2 3 1\n1 2 3\n") == "in.xyzr:2: expected 4 numbers 'x y z r', found 3");
  CHECK(message("1 2 3 1 5\n") == "in.xyzr:1: expected 4 numbers 'x y z r', found more");
  CHECK(message("1 2 x 1\n") == "in.xyzr:1: not a number: 'x'");
  CHECK(message("1 2 3 -1\n") == "in.xyzr:1: the radius must be positive");
  CHECK(message("1 2 3 0\n") == "in.xyzr:1: the radius must be positive");
  CHECK(message("nan 2 3 1\n") == "in.xyzr:1: numbers must be finite");
  CHECK(message("1 2 3 1e999\n") == "in.xyzr:1: not a number: '1e999'");
  CHECK_THROWS_AS(read_xyzr("/nonexistent/balls.xyzr"), IoError);
}
