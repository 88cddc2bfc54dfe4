#pragma once
// Runs fn(k) for k = 0..blocks−1, block 0 in the calling thread and the others in
// std::jthreads; an exception thrown by any block is rethrown in the caller after all
// blocks finished (the first one caught wins).

#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace rstruct::poles::detail {

template <class F>
void run_blocks(unsigned blocks, F&& fn) {
  std::exception_ptr error;
  std::mutex mutex;
  auto guarded = [&](unsigned k) {
    try {
      fn(k);
    } catch (...) {
      const std::lock_guard<std::mutex> lock(mutex);
      if (!error) error = std::current_exception();
    }
  };
  {
    std::vector<std::jthread> workers;
    workers.reserve(blocks > 0 ? blocks - 1 : 0);
    for (unsigned k = 1; k < blocks; ++k) workers.emplace_back(guarded, k);
    if (blocks > 0) guarded(0);
  }  // join
  if (error) std::rethrow_exception(error);
}

}  // namespace rstruct::poles::detail
