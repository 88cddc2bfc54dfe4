#include "greedy.hpp"

#include <algorithm>
#include <queue>

#include "rstruct/core/assert.hpp"

namespace rstruct::setcover::detail {

namespace {

struct Candidate {
  double score;
  std::int32_t col;
  bool operator>(const Candidate& o) const {
    return score > o.score || (score == o.score && col > o.col);
  }
};

}  // namespace

std::vector<std::int32_t> greedy_cover(const Instance& inst, std::span<const double> u,
                                       std::span<const char> allowed,
                                       std::span<const std::int32_t> start) {
  std::vector<char> covered(static_cast<std::size_t>(inst.num_rows()), 0);
  std::int32_t uncovered = inst.num_rows();
  std::vector<std::int32_t> chosen;
  auto take = [&](std::int32_t j) {
    chosen.push_back(j);
    for (std::int32_t i : inst.column(j)) {
      if (!covered[i]) {
        covered[i] = 1;
        --uncovered;
      }
    }
  };
  for (std::int32_t j : start) take(j);
  auto score = [&](std::int32_t j) {
    std::int32_t mu = 0;
    double gamma = inst.cost(j);
    for (std::int32_t i : inst.column(j)) {
      if (covered[i]) continue;
      ++mu;
      if (!u.empty()) gamma -= u[i];
    }
    if (mu == 0) return Candidate{0.0, -1};
    if (u.empty()) return Candidate{gamma / mu, j};
    return Candidate{gamma > 0 ? gamma / mu : gamma * mu, j};
  };
  std::priority_queue<Candidate, std::vector<Candidate>, std::greater<Candidate>> heap;
  for (std::int32_t j = 0; j < inst.num_cols(); ++j) {
    if (!allowed.empty() && !allowed[j]) continue;
    const Candidate c = score(j);
    if (c.col >= 0) heap.push(c);
  }
  while (uncovered > 0) {
    RSTRUCT_ASSERT_MSG(!heap.empty(), "greedy: allowed columns do not cover every row");
    const Candidate top = heap.top();
    heap.pop();
    const Candidate fresh = score(top.col);
    if (fresh.col < 0) continue;
    if (fresh.score > top.score && !heap.empty() && fresh > heap.top()) {
      heap.push(fresh);  // stale and no longer the best: re-queue with its true score
      continue;
    }
    take(top.col);
  }
  remove_redundant(inst, chosen);
  return chosen;
}

void remove_redundant(const Instance& inst, std::vector<std::int32_t>& cols) {
  std::sort(cols.begin(), cols.end());
  cols.erase(std::unique(cols.begin(), cols.end()), cols.end());
  std::vector<std::int32_t> count(static_cast<std::size_t>(inst.num_rows()), 0);
  for (std::int32_t j : cols) {
    for (std::int32_t i : inst.column(j)) ++count[i];
  }
  std::vector<std::int32_t> order = cols;
  std::sort(order.begin(), order.end(), [&](std::int32_t a, std::int32_t b) {
    return inst.cost(a) > inst.cost(b) || (inst.cost(a) == inst.cost(b) && a > b);
  });
  std::vector<char> keep(static_cast<std::size_t>(inst.num_cols()), 0);
  for (std::int32_t j : order) {
    bool redundant = true;
    for (std::int32_t i : inst.column(j)) {
      if (count[i] < 2) {
        redundant = false;
        break;
      }
    }
    if (redundant) {
      for (std::int32_t i : inst.column(j)) --count[i];
    } else {
      keep[j] = 1;
    }
  }
  std::erase_if(cols, [&](std::int32_t j) { return !keep[j]; });
}

}  // namespace rstruct::setcover::detail
