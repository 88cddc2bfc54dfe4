// Round trips through every writer and reader keep every bit: coordinates, faces and (where
// the format holds them) vertex properties.

#include <unistd.h>

#include <rapidcheck/catch.h>

#include <catch2/catch.hpp>

#include "io/mesh_generators.hpp"
#include "rstruct/io/mesh_io.hpp"

using rstruct::TriangleMesh;
using namespace rstruct::io;
using namespace rstruct::io::testing;

namespace {

TriangleMesh round_trip(const TriangleMesh& m, Format format, bool ascii = false,
                        const std::string& xyz_column = {}) {
  WriteOptions w;
  w.format = format;
  w.ascii = ascii;
  const std::string bytes = write_mesh_to_string(m, w);
  ReadOptions r;
  r.xyz_fourth_column = xyz_column;
  return read_mesh_from_memory(bytes, format, r, "round-trip");
}

}  // namespace

TEST_CASE("binary PLY round trip keeps vertices, faces and properties bit for bit") {
  rc::prop("binary PLY", [] {
    const TriangleMesh m = *mesh();
    const TriangleMesh back = round_trip(m, Format::ply);
    RC_ASSERT(same_vertices(m, back));
    RC_ASSERT(m.faces == back.faces);
    RC_ASSERT(same_properties(m, back));
  });
}

TEST_CASE("ASCII PLY round trip keeps vertices, faces and properties bit for bit") {
  rc::prop("ASCII PLY", [] {
    const TriangleMesh m = *mesh();
    const TriangleMesh back = round_trip(m, Format::ply, /*ascii=*/true);
    RC_ASSERT(same_vertices(m, back));
    RC_ASSERT(m.faces == back.faces);
    RC_ASSERT(same_properties(m, back));
  });
}

TEST_CASE("OFF and OBJ round trips keep vertices and faces") {
  rc::prop("OFF", [] {
    const TriangleMesh m = *mesh(true, false);
    const TriangleMesh back = round_trip(m, Format::off);
    RC_ASSERT(same_vertices(m, back));
    RC_ASSERT(m.faces == back.faces);
    RC_ASSERT(back.vertex_properties.empty());
  });
  rc::prop("OBJ", [] {
    const TriangleMesh m = *mesh(true, false);
    const TriangleMesh back = round_trip(m, Format::obj);
    RC_ASSERT(same_vertices(m, back));
    RC_ASSERT(m.faces == back.faces);
  });
}

TEST_CASE("XYZ round trip keeps points and the fourth column") {
  rc::prop("XYZ points", [] {
    const TriangleMesh m = *mesh(false, false);
    const TriangleMesh back = round_trip(m, Format::xyz);
    RC_ASSERT(same_vertices(m, back));
    RC_ASSERT(back.faces.empty());
  });
  rc::prop("XYZ with properties", [] {
    TriangleMesh m = *mesh(false, true);
    RC_PRE(!m.vertex_properties.empty());
    const std::string first = m.vertex_properties.front().first;
    const TriangleMesh back = round_trip(m, Format::xyz, false, first);
    RC_ASSERT(same_vertices(m, back));
    m.vertex_properties.resize(1);  // the reader keeps the 4th column only
    RC_ASSERT(same_properties(m, back));
  });
}

TEST_CASE("writing then reading through files keeps the mesh (every format)") {
  // Same as above through write_mesh / read_mesh and extension-based formats.
  const auto dir = std::filesystem::temp_directory_path() /
                   ("rstruct_io_rt_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  rc::prop("files", [&] {
    const TriangleMesh m = *mesh(true, true);
    for (const char* ext : {".ply", ".off", ".obj", ".xyz"}) {
      const auto path = dir / (std::string("m") + ext);
      write_mesh(path, m);
      const TriangleMesh back = read_mesh(path);
      RC_ASSERT(same_vertices(m, back));
      if (std::string(ext) == ".ply") RC_ASSERT(same_properties(m, back));
      if (std::string(ext) != ".xyz") RC_ASSERT(m.faces == back.faces);
    }
  });
  std::filesystem::remove_all(dir);
}
