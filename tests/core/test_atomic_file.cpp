#include "rstruct/core/atomic_file.hpp"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "rstruct/core/error.hpp"

namespace fs = std::filesystem;
using rstruct::AtomicFile;

namespace {

fs::path fresh_dir() {
  fs::path dir = fs::temp_directory_path() / ("rstruct_atomic_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::size_t entries(const fs::path& dir) {
  return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

}  // namespace

TEST_CASE("committed file appears whole, replacing the old one") {
  const fs::path dir = fresh_dir();
  const fs::path target = dir / "out.txt";
  rstruct::write_file_atomically(target, "old");
  {
    AtomicFile f(target);
    f.stream() << "new contents";
    // Before commit the target still holds the old contents.
    CHECK(slurp(target) == "old");
    f.commit();
  }
  CHECK(slurp(target) == "new contents");
  CHECK(entries(dir) == 1);
  fs::remove_all(dir);
}

TEST_CASE("an uncommitted file leaves no trace and keeps the old target") {
  const fs::path dir = fresh_dir();
  const fs::path target = dir / "out.txt";
  rstruct::write_file_atomically(target, "old");
  try {
    AtomicFile f(target);
    f.stream() << "half written";
    throw std::runtime_error("computation failed midway");
  } catch (const std::runtime_error&) {
  }
  CHECK(slurp(target) == "old");
  CHECK(entries(dir) == 1);
  fs::remove_all(dir);
}

TEST_CASE("an unwritable location is an IoError") {
  CHECK_THROWS_AS(AtomicFile("/nonexistent_dir_rstruct/x.ply"), rstruct::IoError);
}
