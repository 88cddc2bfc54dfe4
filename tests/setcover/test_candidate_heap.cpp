// The greedy's queue (src/setcover/candidate_heap.hpp) against an ordered set: after every
// push, pop and replace_top, the same first and second candidates in (score, col) order.
#include "setcover/candidate_heap.hpp"

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <iterator>
#include <set>

using rstruct::setcover::detail::Candidate;
using rstruct::setcover::detail::CandidateHeap;

namespace {

struct Before {
  bool operator()(const Candidate& a, const Candidate& b) const { return b > a; }
};

}  // namespace

TEST_CASE("the candidate heap keeps the first two candidates of an ordered set") {
  rc::prop("random pushes, pops and replacements, with equal scores", [] {
    CandidateHeap heap;
    std::set<Candidate, Before> reference;
    std::int32_t next_col = 0;
    const auto fresh = [&] {
      // Scores on a coarse grid tie often; columns are distinct, as in the greedy.
      return Candidate{0.5 * *rc::gen::inRange(0, 16), next_col++, 0};
    };
    const int steps = *rc::gen::inRange(1, 400);
    for (int s = 0; s < steps; ++s) {
      const int op = *rc::gen::inRange(0, 10);
      if (reference.empty() || op < 5) {
        const Candidate c = fresh();
        heap.push(c);
        reference.insert(c);
      } else if (op < 7) {
        heap.pop();
        reference.erase(reference.begin());
      } else {
        const Candidate c = fresh();
        heap.replace_top(c);
        reference.erase(reference.begin());
        reference.insert(c);
      }
      RC_ASSERT(heap.size() == reference.size());
      if (reference.empty()) continue;
      RC_ASSERT(heap.top().col == reference.begin()->col);
      if (reference.size() > 1) RC_ASSERT(heap.second().col == std::next(reference.begin())->col);
    }
  });
}
