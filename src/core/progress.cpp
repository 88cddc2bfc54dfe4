#include "rstruct/core/progress.hpp"

#include <unistd.h>

#include <atomic>
#include <cstdio>

namespace rstruct {

namespace {
std::atomic<bool> g_enabled{true};
}

void Progress::set_enabled(bool enabled) { g_enabled = enabled; }

Progress::Progress(std::string label, std::uint64_t total)
    : label_(std::move(label)), total_(total == 0 ? 1 : total) {}

Progress::~Progress() { finish(); }

void Progress::maybe_draw(std::uint64_t done) {
  if (!g_enabled || !isatty(STDERR_FILENO)) return;
  const double t = clock_.seconds();
  if (t < 1.0 || (t - last_draw_ < 0.1 && done < total_)) return;
  last_draw_ = t;
  const double fraction = done >= total_ ? 1.0 : static_cast<double>(done) / total_;
  const int width = 30;
  const int filled = static_cast<int>(fraction * width);
  std::fprintf(stderr, "\r  %-24s [", label_.c_str());
  for (int i = 0; i < width; ++i) std::fputc(i < filled ? '#' : '.', stderr);
  std::fprintf(stderr, "] %5.1f%%  %6.1f s", 100.0 * fraction, t);
  std::fflush(stderr);
  drawn_ = true;
}

void Progress::finish() {
  if (drawn_) {
    std::fprintf(stderr, "\r%*s\r", 80, "");
    std::fflush(stderr);
    drawn_ = false;
  }
}

}  // namespace rstruct
