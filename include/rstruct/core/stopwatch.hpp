#pragma once
/// \file
/// Wall-clock and process CPU timing and peak resident memory, for reports and benchmarks.

#include <chrono>
#include <cstddef>

namespace rstruct {

/// CPU seconds (user + system) consumed so far by all threads of this process.
double process_cpu_seconds();

class Stopwatch {
 public:
  Stopwatch() : start_(Clock::now()), cpu_start_(process_cpu_seconds()) {}
  void reset() {
    start_ = Clock::now();
    cpu_start_ = process_cpu_seconds();
  }
  /// Wall-clock seconds since construction or the last reset().
  double seconds() const {
    return std::chrono::duration<double>(Clock::now() - start_).count();
  }
  /// CPU seconds of the whole process (every thread) since construction or reset(): with
  /// several threads at work this exceeds seconds(); on a loaded machine it is the figure
  /// that does not depend on what else runs.
  double cpu_seconds() const { return process_cpu_seconds() - cpu_start_; }

 private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point start_;
  double cpu_start_ = 0;
};

/// Peak resident set size of this process so far, in bytes (getrusage ru_maxrss).
std::size_t peak_memory_bytes();

/// Current resident set size in bytes (from /proc/self/statm; 0 where unavailable).
std::size_t current_memory_bytes();

}  // namespace rstruct
