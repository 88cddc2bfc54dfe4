// The pole labeling's queue (src/poles/indexed_max_heap.hpp) against the queue it replaced:
// a std::priority_queue<std::pair<double, std::uint32_t>> that gets a new entry on every
// raise and skips entries that are no longer an id's current priority when popped. The
// labels must not change, so both must pop the same (priority, id) sequence.

#include "poles/indexed_max_heap.hpp"

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <map>
#include <queue>
#include <vector>

using rstruct::poles::detail::IndexedMaxHeap;

namespace {

/// The replaced queue: stale entries left behind, filtered on pop.
class StaleEntryQueue {
 public:
  void raise(std::uint32_t id, double priority) {
    const auto it = current_.find(id);
    if (it != current_.end() && priority <= it->second) return;
    current_[id] = priority;
    heap_.emplace(priority, id);
  }
  bool empty() {
    drop_stale();
    return heap_.empty();
  }
  std::pair<double, std::uint32_t> pop() {
    drop_stale();
    const auto top = heap_.top();
    heap_.pop();
    current_.erase(top.second);
    return top;
  }

 private:
  void drop_stale() {
    while (!heap_.empty()) {
      const auto it = current_.find(heap_.top().second);
      if (it != current_.end() && it->second == heap_.top().first) return;
      heap_.pop();
    }
  }
  std::priority_queue<std::pair<double, std::uint32_t>> heap_;
  std::map<std::uint32_t, double> current_;
};

}  // namespace

TEST_CASE("indexed max-heap pops what the stale-entry priority queue pops") {
  rc::prop("same pop sequence under random raises and pops", [] {
    const auto ids = *rc::gen::inRange<std::uint32_t>(1, 40);
    // Few distinct priorities: ties (then the larger id first) are frequent.
    const auto steps = *rc::gen::container<std::vector<std::pair<int, int>>>(
        rc::gen::pair(rc::gen::inRange(-1, 6), rc::gen::inRange(0, 1000)));
    IndexedMaxHeap heap(ids);
    StaleEntryQueue model;
    for (const auto& [priority, id_seed] : steps) {
      if (priority < 0) {  // a pop
        RC_ASSERT(heap.empty() == model.empty());
        if (!heap.empty()) RC_ASSERT(heap.pop() == model.pop());
      } else {
        const auto id = static_cast<std::uint32_t>(id_seed) % ids;
        heap.raise(id, 0.25 * priority);
        model.raise(id, 0.25 * priority);
      }
    }
    while (!model.empty()) {
      RC_ASSERT(!heap.empty());
      RC_ASSERT(heap.pop() == model.pop());
    }
    RC_ASSERT(heap.empty());
  });
}

TEST_CASE("indexed max-heap keeps one entry per id") {
  IndexedMaxHeap heap(3);
  heap.raise(1, 0.5);
  heap.raise(1, 0.25);  // lower: ignored
  heap.raise(1, 0.75);
  heap.raise(2, 0.75);
  CHECK(heap.size() == 2);
  CHECK(heap.pop() == std::pair<double, std::uint32_t>{0.75, 2});  // tie: larger id first
  CHECK(heap.pop() == std::pair<double, std::uint32_t>{0.75, 1});
  CHECK(heap.empty());
  heap.raise(1, 0.1);  // popped ids may come back
  CHECK(heap.pop() == std::pair<double, std::uint32_t>{0.1, 1});
}
