// Every file of the malformed corpus (tests/data/io/malformed/, listed with the expected
// message fragment in malformed.tsv) is rejected by its reader with InvalidInput, and the
// message names the file and the problem.

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "rstruct/core/error.hpp"
#include "rstruct/io/mesh_io.hpp"

namespace fs = std::filesystem;

namespace {

struct Entry {
  std::string file;
  std::string fragment;
};

std::vector<Entry> manifest() {
  std::ifstream in(fs::path(RSTRUCT_IO_DATA_DIR) / "malformed.tsv");
  REQUIRE(in);
  std::vector<Entry> entries;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    const auto tab = line.find('\t');
    REQUIRE(tab != std::string::npos);
    entries.push_back({line.substr(0, tab), line.substr(tab + 1)});
  }
  return entries;
}

}  // namespace

TEST_CASE("every malformed corpus file is rejected with its expected message") {
  const fs::path dir = fs::path(RSTRUCT_IO_DATA_DIR) / "malformed";
  const std::vector<Entry> entries = manifest();
  REQUIRE(entries.size() >= 60);
  std::set<std::string> listed;
  for (const Entry& e : entries) {
    INFO("file " << e.file << ", expected fragment '" << e.fragment << "'");
    listed.insert(e.file);
    const fs::path path = dir / e.file;
    REQUIRE(fs::is_regular_file(path));
    std::string message;
    try {
      (void)rstruct::io::read_mesh(path);
      FAIL("accepted");
    } catch (const rstruct::InvalidInput& error) {
      message = error.what();
    }
    INFO("message: " << message);
    CHECK(message.find(e.fragment) != std::string::npos);
    CHECK(message.find(e.file) != std::string::npos);
  }
  // No file in the folder escapes the manifest.
  for (const auto& f : fs::directory_iterator(dir)) {
    INFO("unlisted corpus file " << f.path());
    CHECK(listed.count(f.path().filename().string()) == 1);
  }
}

TEST_CASE("every corpus file is also rejected from memory, whatever the format") {
  // Readers must not crash on another format's malformed bytes either.
  const fs::path dir = fs::path(RSTRUCT_IO_DATA_DIR) / "malformed";
  using rstruct::io::Format;
  for (const Entry& e : manifest()) {
    std::ifstream in(dir / e.file, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (Format f : {Format::ply, Format::off, Format::obj, Format::xyz}) {
      try {
        (void)rstruct::io::read_mesh_from_memory(bytes, f, {}, e.file);
      } catch (const rstruct::InvalidInput&) {
      }
    }
  }
  SUCCEED("no reader crashed or threw anything but InvalidInput");
}
