#pragma once
// The greedy's queue of columns (src/setcover/greedy.cpp). Private to src/setcover.

#include <algorithm>
#include <cstdint>
#include <vector>

namespace rstruct::setcover::detail {

/// A column scored by the greedy: the smaller (score, col) first.
struct Candidate {
  double score;
  std::int32_t col;
  std::int32_t mu;  // the column's uncovered rows when scored; not part of the order
  bool operator>(const Candidate& o) const {
    return score > o.score || (score == o.score && col > o.col);
  }
};

/// A 4-ary min-heap of candidates in the order of Candidate::operator> (std::greater, as
/// std::priority_queue<..., std::greater<>> orders them), with replace_top(): a stale
/// candidate rescored and queued again costs one sift-down instead of a pop and a push.
/// Every decision reads only the first candidate and the set queued, never the layout.
class CandidateHeap {
 public:
  void reserve(std::size_t n) { h_.reserve(n); }
  bool empty() const { return h_.empty(); }
  const Candidate& top() const { return h_.front(); }
  /// The first candidate after the top. \pre size() > 1.
  const Candidate& second() const {
    std::size_t best = 1;
    for (std::size_t c = 2; c < std::min<std::size_t>(5, h_.size()); ++c) {
      if (h_[best] > h_[c]) best = c;
    }
    return h_[best];
  }
  std::size_t size() const { return h_.size(); }
  void push(const Candidate& c) {
    std::size_t k = h_.size();
    h_.push_back(c);
    while (k > 0) {
      const std::size_t parent = (k - 1) / 4;
      if (!(h_[parent] > c)) break;
      h_[k] = h_[parent];
      k = parent;
    }
    h_[k] = c;
  }
  void pop() {
    const Candidate last = h_.back();
    h_.pop_back();
    if (!h_.empty()) sift_down(last);
  }
  /// pop() then push(c), in one sift-down. \pre !empty().
  void replace_top(const Candidate& c) { sift_down(c); }

 private:
  void sift_down(const Candidate& c) {
    const std::size_t n = h_.size();
    std::size_t k = 0;
    for (;;) {
      const std::size_t first = 4 * k + 1;
      if (first >= n) break;
      std::size_t child = first;
      const std::size_t last = std::min(n, first + 4);
      for (std::size_t x = first + 1; x < last; ++x) {
        if (h_[child] > h_[x]) child = x;
      }
      if (!(c > h_[child])) break;
      h_[k] = h_[child];
      k = child;
    }
    h_[k] = c;
  }
  std::vector<Candidate> h_;
};

}  // namespace rstruct::setcover::detail
