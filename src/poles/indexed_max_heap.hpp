#pragma once
// A max-heap of (priority, id) pairs holding at most one entry per id: raising the priority
// of an id already queued moves its entry up instead of adding a second one. The pole
// labeling's queue: with std::priority_queue every raise left a stale entry behind, the
// heap grew to several entries per pole, and its sift-downs were most of the labeling's
// time (10⁶ torus samples: 3.6 s, of which a third in heap pops).
//
// Order: the larger priority first, ties by the larger id, as
// std::priority_queue<std::pair<double, std::uint32_t>> pops them. 4-ary: shallower than
// binary, and a node's children share a cache line.

#include <cstdint>
#include <utility>
#include <vector>

namespace rstruct::poles::detail {

class IndexedMaxHeap {
 public:
  /// Ids must be < capacity.
  explicit IndexedMaxHeap(std::size_t capacity) : position_(capacity, kAbsent) {}

  bool empty() const { return heap_.empty(); }
  std::size_t size() const { return heap_.size(); }

  /// Queues `id` with `priority`, or raises its priority to `priority` if that is larger.
  /// An id popped before may be queued again.
  void raise(std::uint32_t id, double priority) {
    std::uint32_t k = position_[id];
    if (k == kAbsent) {
      k = static_cast<std::uint32_t>(heap_.size());
      heap_.push_back({priority, id});
    } else if (priority > heap_[k].priority) {
      heap_[k].priority = priority;
    } else {
      return;
    }
    sift_up(k);
  }

  /// The id of the first entry. \pre !empty().
  std::uint32_t top_id() const { return heap_.front().id; }

  /// Removes and returns the first entry. \pre !empty().
  std::pair<double, std::uint32_t> pop() {
    const Entry top = heap_.front();
    position_[top.id] = kAbsent;
    const Entry last = heap_.back();
    heap_.pop_back();
    if (!heap_.empty()) {
      heap_.front() = last;
      sift_down(0);
    }
    return {top.priority, top.id};
  }

 private:
  struct Entry {
    double priority;
    std::uint32_t id;
  };
  static constexpr std::uint32_t kAbsent = 0xffffffffU;
  static bool before(const Entry& a, const Entry& b) {
    return a.priority > b.priority || (a.priority == b.priority && a.id > b.id);
  }

  void sift_up(std::uint32_t k) {
    const Entry moving = heap_[k];
    while (k > 0) {
      const std::uint32_t parent = (k - 1) / 4;
      if (!before(moving, heap_[parent])) break;
      heap_[k] = heap_[parent];
      position_[heap_[k].id] = k;
      k = parent;
    }
    heap_[k] = moving;
    position_[moving.id] = k;
  }

  void sift_down(std::uint32_t k) {
    const Entry moving = heap_[k];
    const auto n = static_cast<std::uint32_t>(heap_.size());
    for (;;) {
      const std::uint32_t first = 4 * k + 1;
      if (first >= n) break;
      std::uint32_t best = first;
      const std::uint32_t last = first + 4 < n ? first + 4 : n;
      for (std::uint32_t c = first + 1; c < last; ++c) {
        if (before(heap_[c], heap_[best])) best = c;
      }
      if (!before(heap_[best], moving)) break;
      heap_[k] = heap_[best];
      position_[heap_[k].id] = k;
      k = best;
    }
    heap_[k] = moving;
    position_[moving.id] = k;
  }

  std::vector<Entry> heap_;
  std::vector<std::uint32_t> position_;  // id → index in heap_, or kAbsent
};

}  // namespace rstruct::poles::detail
