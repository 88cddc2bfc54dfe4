#pragma once
/// \file
/// Wall-clock timing and peak resident memory, for reports and benchmarks.

#include <chrono>
#include <cstddef>

namespace rstruct {

class Stopwatch {
 public:
  Stopwatch() : start_(Clock::now()) {}
  void reset() { start_ = Clock::now(); }
  /// Seconds since construction or the last reset().
  double seconds() const {
    return std::chrono::duration<double>(Clock::now() - start_).count();
  }

 private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point start_;
};

/// Peak resident set size of this process so far, in bytes (getrusage ru_maxrss).
std::size_t peak_memory_bytes();

/// Current resident set size in bytes (from /proc/self/statm; 0 where unavailable).
std::size_t current_memory_bytes();

}  // namespace rstruct
