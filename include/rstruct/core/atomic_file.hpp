#pragma once
/// \file
/// Output files appear whole or not at all: data goes to a temporary file in the target's
/// folder and is renamed over the target by commit(). If commit() is never called (an
/// exception, a failed computation), the destructor removes the temporary file.

#include <filesystem>
#include <fstream>
#include <string>

namespace rstruct {

class AtomicFile {
 public:
  /// Opens a temporary file beside `target`. \throws IoError if it cannot be created.
  explicit AtomicFile(std::filesystem::path target, bool binary = false);
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  ~AtomicFile();

  /// The stream to write to.
  std::ostream& stream() { return out_; }

  /// Flushes, checks the stream, and renames the temporary file onto the target.
  /// \throws IoError on any write or rename failure (the temporary file is removed).
  void commit();

  const std::filesystem::path& target() const { return target_; }

 private:
  std::filesystem::path target_;
  std::filesystem::path temp_;
  std::ofstream out_;
  bool committed_ = false;
};

/// Writes `text` to `target` atomically.
void write_file_atomically(const std::filesystem::path& target, const std::string& text);

}  // namespace rstruct
