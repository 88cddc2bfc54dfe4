#include "rstruct/complex/collapse.hpp"

#include <deque>
#include <limits>

#include "rstruct/complex/coface_index.hpp"

namespace rstruct::complex {
namespace {

constexpr SimplexIndex kNone = std::numeric_limits<SimplexIndex>::max();

class Collapser {
 public:
  Collapser(const SimplicialComplex& complex, CollapseOrder order)
      : k_(complex), cof_(complex), order_(order) {
    for (int d = 0; d < 4; ++d) {
      alive_[d].assign(k_.size(d), true);
      coface_count_[d].assign(k_.size(d), 0);
    }
    for (int d = 0; d < 3; ++d) {
      for (SimplexIndex i = 0; i < k_.size(d); ++i) {
        coface_count_[d][i] = static_cast<std::uint32_t>(cof_.degree(d, i));
        if (coface_count_[d][i] == 1) queue_[d].push_back(i);
      }
    }
  }

  CollapseResult run() {
    CollapseResult result;
    for (;;) {
      int d = 2;
      while (d >= 0 && queue_[d].empty()) --d;
      if (d < 0) break;
      const SimplexIndex sigma = take(d);
      const SimplexIndex tau = free_coface(d, sigma);
      if (tau == kNone) continue;
      remove(d + 1, tau);
      remove(d, sigma);
      ++result.removed[d];
      ++result.removed[d + 1];
      ++result.collapses;
    }
    result.complex = k_.subcomplex(alive_);
    return result;
  }

 private:
  /// Next candidate of dimension d, oldest (breadth-first) or newest (depth-first) first.
  SimplexIndex take(int d) {
    auto& queue = queue_[d];
    SimplexIndex s = 0;
    if (order_ == CollapseOrder::depth_first) {
      s = queue.back();
      queue.pop_back();
    } else {
      s = queue.front();
      queue.pop_front();
    }
    return s;
  }

  /// The only coface of sigma if sigma is free, else kNone.
  SimplexIndex free_coface(int d, SimplexIndex sigma) const {
    if (!alive_[d][sigma] || coface_count_[d][sigma] != 1) return kNone;
    for (const SimplexIndex tau : cof_.cofaces(d, sigma)) {
      if (alive_[d + 1][tau]) return coface_count_[d + 1][tau] == 0 ? tau : kNone;
    }
    return kNone;
  }

  /// Removes a maximal simplex and queues the faces that may have become free: a face
  /// whose coface count drops to one, and the faces of a face that became maximal.
  void remove(int d, SimplexIndex s) {
    alive_[d][s] = false;
    if (d == 0) return;
    for (const SimplexIndex f : k_.faces(d, s)) {
      const std::uint32_t left = --coface_count_[d - 1][f];
      if (left == 1) {
        queue_[d - 1].push_back(f);
      } else if (left == 0 && d >= 2) {
        for (const SimplexIndex g : k_.faces(d - 1, f)) {
          if (coface_count_[d - 2][g] == 1) queue_[d - 2].push_back(g);
        }
      }
    }
  }

  const SimplicialComplex& k_;
  CofaceIndex cof_;
  CollapseOrder order_;
  std::array<std::vector<bool>, 4> alive_;
  std::array<std::vector<std::uint32_t>, 4> coface_count_;
  std::array<std::deque<SimplexIndex>, 3> queue_;
};

}  // namespace

CollapseResult collapse_free_faces(const SimplicialComplex& complex, CollapseOrder order) {
  return Collapser(complex, order).run();
}

}  // namespace rstruct::complex
