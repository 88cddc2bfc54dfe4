#pragma once
/// \file
/// A progress bar on stderr for long stages. It draws only when stderr is a terminal,
/// progress is not disabled (--quiet), and the stage has been running for over a second;
/// redraws are rate-limited, so calling update() in an inner loop is cheap.

#include <cstdint>
#include <string>

#include "rstruct/core/stopwatch.hpp"

namespace rstruct {

class Progress {
 public:
  Progress(std::string label, std::uint64_t total);
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;
  ~Progress();

  /// Sets the amount done. Cheap unless a redraw is due.
  void update(std::uint64_t done) {
    if ((++calls_ & 1023u) == 0 || done >= total_) maybe_draw(done);
  }
  void finish();

  /// Globally enables or disables drawing (the CLI's --quiet turns it off).
  static void set_enabled(bool enabled);

 private:
  void maybe_draw(std::uint64_t done);
  std::string label_;
  std::uint64_t total_;
  std::uint64_t calls_ = 0;
  Stopwatch clock_;
  double last_draw_ = -1.0;
  bool drawn_ = false;
};

}  // namespace rstruct
