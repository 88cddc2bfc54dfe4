#include "rstruct/core/atomic_file.hpp"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <system_error>

#include "rstruct/core/error.hpp"

namespace rstruct {

namespace {

std::filesystem::path temporary_beside(const std::filesystem::path& target) {
  static std::atomic<unsigned> counter{0};
  std::filesystem::path temp = target;
  temp += ".tmp." + std::to_string(::getpid()) + "." + std::to_string(counter++);
  return temp;
}

}  // namespace

AtomicFile::AtomicFile(std::filesystem::path target, bool binary)
    : target_(std::move(target)), temp_(temporary_beside(target_)) {
  std::ios::openmode mode = std::ios::out | std::ios::trunc;
  if (binary) mode |= std::ios::binary;
  out_.open(temp_, mode);
  if (!out_) {
    throw IoError("cannot create output file '" + target_.string() +
                  "' (temporary '" + temp_.string() + "'): " + std::strerror(errno));
  }
}

AtomicFile::~AtomicFile() {
  if (!committed_) {
    out_.close();
    std::error_code ignored;
    std::filesystem::remove(temp_, ignored);
  }
}

void AtomicFile::commit() {
  out_.flush();
  const bool ok = static_cast<bool>(out_);
  out_.close();
  if (!ok || out_.fail()) {
    std::error_code ignored;
    std::filesystem::remove(temp_, ignored);
    committed_ = true;
    throw IoError("write error on '" + target_.string() + "'");
  }
  std::error_code ec;
  std::filesystem::rename(temp_, target_, ec);
  committed_ = true;
  if (ec) {
    std::error_code ignored;
    std::filesystem::remove(temp_, ignored);
    throw IoError("cannot rename temporary file onto '" + target_.string() + "': " + ec.message());
  }
}

void write_file_atomically(const std::filesystem::path& target, const std::string& text) {
  AtomicFile file(target);
  file.stream() << text;
  file.commit();
}

}  // namespace rstruct
