// File access: formats from extensions, I/O errors, atomic writes, the writers'
// preconditions.

#include <unistd.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "rstruct/core/error.hpp"
#include "rstruct/io/mesh_io.hpp"

namespace fs = std::filesystem;
using rstruct::TriangleMesh;
using namespace rstruct::io;

namespace {

fs::path fresh_dir() {
  const fs::path dir = fs::temp_directory_path() / ("rstruct_io_files_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TriangleMesh triangle() {
  TriangleMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.faces = {{0, 1, 2}};
  m.vertex_properties.emplace_back("label", std::vector<double>{1, 2, 3});
  return m;
}

}  // namespace

TEST_CASE("formats from extensions and names") {
  CHECK(format_from_extension("a/b.PLY") == Format::ply);
  CHECK(format_from_extension("b.off") == Format::off);
  CHECK(format_from_extension("b.Obj") == Format::obj);
  CHECK(format_from_extension("b.xyz") == Format::xyz);
  CHECK_THROWS_WITH(format_from_extension("b.stl"), Catch::Contains("--format"));
  CHECK_THROWS_AS(format_from_extension("noext"), rstruct::InvalidInput);
  CHECK(parse_format("OFF") == Format::off);
  CHECK_THROWS_AS(parse_format("stl"), rstruct::InvalidInput);
  CHECK_THROWS_AS(read_mesh_from_memory("1 2 3", Format::automatic), rstruct::InvalidInput);
}

TEST_CASE("missing files and folders are I/O errors; --format overrides the extension") {
  const fs::path dir = fresh_dir();
  CHECK_THROWS_AS(read_mesh(dir / "missing.ply"), rstruct::IoError);
  CHECK_THROWS_AS(read_mesh(dir, ReadOptions{Format::ply, {}}), rstruct::IoError);
  CHECK_THROWS_AS(write_mesh(dir / "no" / "such" / "dir.ply", triangle()), rstruct::IoError);
  std::ofstream(dir / "points.txt") << "1 2 3\n4 5 6\n";
  CHECK_THROWS_AS(read_mesh(dir / "points.txt"), rstruct::InvalidInput);
  CHECK(read_mesh(dir / "points.txt", ReadOptions{Format::xyz, {}}).vertices.size() == 2);
  fs::remove_all(dir);
}

TEST_CASE("a rejected write leaves the old file and no temporary file") {
  const fs::path dir = fresh_dir();
  const fs::path target = dir / "out.ply";
  write_mesh(target, triangle());
  const auto size = fs::file_size(target);
  TriangleMesh bad = triangle();
  bad.vertices[1].y = std::nan("");
  CHECK_THROWS_AS(write_mesh(target, bad), rstruct::InvalidInput);
  CHECK(fs::file_size(target) == size);
  CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator()) == 1);
  CHECK(read_mesh(target).faces.size() == 1);
  fs::remove_all(dir);
}

TEST_CASE("writers check their preconditions") {
  const WriteOptions ply{Format::ply, false};
  TriangleMesh m = triangle();
  m.faces.push_back({0, 1, 3});
  CHECK_THROWS_WITH(write_mesh_to_string(m, ply), Catch::Contains("face 1"));
  m = triangle();
  m.vertex_properties.emplace_back("x", std::vector<double>{0, 0, 0});
  CHECK_THROWS_AS(write_mesh_to_string(m, ply), rstruct::InvalidInput);
  m = triangle();
  m.vertex_properties.emplace_back("two words", std::vector<double>{0, 0, 0});
  CHECK_THROWS_AS(write_mesh_to_string(m, ply), rstruct::InvalidInput);
  m = triangle();
  m.vertex_properties.emplace_back("label", std::vector<double>{0, 0, 0});
  CHECK_THROWS_WITH(write_mesh_to_string(m, ply), Catch::Contains("duplicate"));
  m = triangle();
  m.vertex_properties[0].second.pop_back();
  CHECK_THROWS_WITH(write_mesh_to_string(m, ply), Catch::Contains("2 values for 3 vertices"));
  m = triangle();
  m.vertex_properties[0].second[2] = INFINITY;
  CHECK_THROWS_AS(write_mesh_to_string(m, ply), rstruct::InvalidInput);
}

TEST_CASE("integer-named integral properties are written as int, others as double") {
  TriangleMesh m = triangle();
  m.vertex_properties.emplace_back("vertex_id", std::vector<double>{0, 1.5, 2});
  m.vertex_properties.emplace_back("radius", std::vector<double>{1, 2, 3});
  const std::string text = write_mesh_to_string(m, WriteOptions{Format::ply, true});
  CHECK(text.find("property int label\n") != std::string::npos);
  CHECK(text.find("property double vertex_id\n") != std::string::npos);
  CHECK(text.find("property double radius\n") != std::string::npos);
  CHECK(text.find("property list uchar int vertex_indices\n") != std::string::npos);
}
