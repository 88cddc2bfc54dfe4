#include "greedy.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>

#include "candidate_heap.hpp"
#include "rstruct/core/assert.hpp"

namespace rstruct::setcover::detail {

namespace {

/// The largest count μ_j of an allowed column if every allowed column costs the same
/// positive amount c and every count is below 2^26 (then c / μ falls strictly as μ grows:
/// consecutive values differ by a relative 1/μ, far above the rounding, so the score order
/// is the order of μ); otherwise -1.
std::int32_t largest_count_if_equal_costs(const Instance& inst, std::span<const char> allowed,
                                          const std::vector<std::int32_t>& mu) {
  double c = 0.0;
  std::int32_t top = 0;
  for (std::int32_t j = 0; j < inst.num_cols(); ++j) {
    if (!allowed.empty() && !allowed[j]) continue;
    if (c == 0.0) c = inst.cost(j);
    if (!(inst.cost(j) == c && c > 0.0 && mu[j] < (1 << 26))) return -1;
    top = std::max(top, mu[j]);
  }
  return top;
}

/// Takes columns in (score, index) order, lazily, until `uncovered()` is 0: the candidates
/// are the allowed columns (all when `allowed` is empty) of the `columns` that cover some
/// row; `mu(j)` is column j's count of uncovered rows now, `score(j)` its candidate now
/// (col −1 if it covers nothing more), and take(j) takes it. A queued candidate whose
/// count has not changed is current; one that has is rescored when it comes first, and
/// taken if it still is. Scores only grow as rows get covered, so the column taken is
/// always the first of all. The candidates enter the queue `batch` at a time in the order
/// of their first scores (all at once, unsorted, when the batch holds them all): one not
/// yet queued scores at least the first score of the next batch, `next`, so a column is
/// taken only if it comes before that. Used by greedy_cover (one batch) and
/// lagrangian_greedy (batches).
template <class Mu, class Score, class Take, class Uncovered>
void take_in_score_order(std::int32_t columns, std::span<const char> allowed, std::size_t batch,
                         Mu&& mu, Score&& score, Take&& take, Uncovered&& uncovered) {
  std::vector<Candidate> waiting;
  for (std::int32_t j = 0; j < columns; ++j) {
    if (!allowed.empty() && !allowed[j]) continue;
    const Candidate c = score(j);
    if (c.col >= 0) waiting.push_back(c);
  }
  batch = std::max<std::size_t>(1, batch);
  if (batch < waiting.size()) {
    std::sort(waiting.begin(), waiting.end(),
              [](const Candidate& a, const Candidate& b) { return b > a; });
  }
  constexpr Candidate kNone{HUGE_VAL, std::numeric_limits<std::int32_t>::max(), 0};
  CandidateHeap heap;
  heap.reserve(std::min(waiting.size(), batch));
  std::size_t fed = 0;
  Candidate next = kNone;
  const auto feed = [&] {
    const std::size_t end = fed + std::min(batch, waiting.size() - fed);
    for (; fed < end; ++fed) {
      const Candidate& c = waiting[fed];
      const Candidate now = mu(c.col) == c.mu ? c : score(c.col);
      if (now.col >= 0) heap.push(now);
    }
    next = fed < waiting.size() ? waiting[fed] : kNone;
  };
  feed();
  while (uncovered() > 0) {
    if (fed < waiting.size() && (heap.empty() || !(next > heap.top()))) {
      feed();
      continue;
    }
    RSTRUCT_ASSERT_MSG(!heap.empty(), "greedy: allowed columns do not cover every row");
    const Candidate top = heap.top();
    if (mu(top.col) == top.mu) {  // nothing changed since it was scored
      heap.pop();
      take(top.col);
      continue;
    }
    const Candidate fresh = score(top.col);
    if (fresh.col < 0) {
      heap.pop();
      continue;
    }
    // Stale and no longer the first, or not before the next batch (which is queued
    // before it is taken): re-queued with its true score.
    if ((fresh.score > top.score && heap.size() > 1 && fresh > heap.second()) || !(next > fresh)) {
      heap.replace_top(fresh);
      continue;
    }
    heap.pop();
    take(top.col);
  }
}

}  // namespace

// The greedy with multipliers u (CFT's Lagrangian greedy); see greedy_cover.
//
// γ_j is kept up to date like μ_j: it starts at c_j minus the multipliers of all of j's
// rows, and covering row i adds u_i to the γ of every column through it; a rescore is then
// one division or product. Its rounding differs from a fresh sum over the uncovered rows,
// so a near tie may go the other way, but γ only grows (u ≥ 0), so the scores still only
// grow and lazy evaluation stays exact. The Lagrangian greedy of the 10^6-sample torus
// level (bench_seed --torus 1000000 --levels 0.5:0.03) runs on a thread of its own after
// the last subgradient iteration, and the set cover waited 0.6 s for it: 6 interleaved
// pairs, subgradient stage 1.25-1.49 s (median 1.34) -> 0.99-1.32 s (median 1.07), the same
// cover (58,150) and output. On the double torus, level 2 went from 4,600 to 4,574 balls (a
// near tie going the other way).
//
// Each column's γ and μ sit side by side (covering a row updates both for every column
// through it, at scattered places), and the allowed columns enter the queue in batches, in
// the order of their first scores: a column not yet queued scores at least the first score
// of the next batch (scores only grow), so the queue's first column, once it is scored
// fresh and comes before that, is the first of all, as before. A column enters the queue
// only once the columns before it have been taken or rescored past it, so short runs queue
// few of them. The same columns in the same order. That
// 10^6-sample torus level (351,115 of 835,613 columns allowed): the greedy 0.42-0.46 s ->
// 0.37-0.39 s (instrumented, not committed, with batches doubling from 8,192 columns
// instead of these); with these batches, the subgradient stage, 4 interleaved pairs,
// 0.884-0.916 s (median 0.908) -> 0.841-0.878 s (median 0.863), every pair faster, the same
// output. Double torus: the same outputs.
std::vector<std::int32_t> lagrangian_greedy(const Instance& inst, std::span<const double> u,
                                            std::span<const char> allowed,
                                            std::span<const std::int32_t> start,
                                            std::size_t batch) {
  RSTRUCT_ASSERT_MSG(std::all_of(u.begin(), u.end(), [](double x) { return x >= 0.0; }),
                     "greedy: negative multiplier");
  struct Column {
    double gamma;
    std::int32_t mu;
  };
  std::vector<Column> col(static_cast<std::size_t>(inst.num_cols()));
  for (std::int32_t j = 0; j < inst.num_cols(); ++j) {
    double g = inst.cost(j);
    for (std::int32_t i : inst.column(j)) g -= u[i];
    col[j] = {g, static_cast<std::int32_t>(inst.column(j).size())};
  }
  std::vector<char> covered(static_cast<std::size_t>(inst.num_rows()), 0);
  std::int32_t uncovered = inst.num_rows();
  std::vector<std::int32_t> chosen;
  const auto take = [&](std::int32_t j) {
    chosen.push_back(j);
    for (std::int32_t i : inst.column(j)) {
      if (covered[i]) continue;
      covered[i] = 1;
      --uncovered;
      const double ui = u[i];
      for (std::int32_t k : inst.row(i)) {
        --col[k].mu;
        col[k].gamma += ui;
      }
    }
  };
  for (std::int32_t j : start) take(j);
  const auto score = [&](std::int32_t j) {
    const Column c = col[j];
    if (c.mu == 0) return Candidate{0.0, -1, 0};
    return Candidate{c.gamma > 0 ? c.gamma / c.mu : c.gamma * c.mu, j, c.mu};
  };
  take_in_score_order(
      inst.num_cols(), allowed, batch, [&](std::int32_t j) { return col[j].mu; }, score, take,
      [&] { return uncovered; });
  remove_redundant(inst, chosen);
  return chosen;
}

// Lazy greedy: a popped column is rescored, and taken if it is still first. Scores only
// grow as rows get covered, so this takes the first column in (score, index) order at every
// step.
//
// The uncovered-row count μ of every column is kept up to date as rows get covered (each
// row once: one pass over the matrix in all), so a column whose μ has not changed since it
// was scored is taken without rescoring. 10^6 torus samples (2.5·10^7 entries, no
// multipliers, medians of interleaved runs): 0.97 -> 0.75 s, the same cover.
//
// A stale column re-queued replaces the top of the queue (CandidateHeap) instead of a pop
// and a push: the geometric instance of 10^6 torus samples (bench_setcover --geometric
// --samples 1000000 --rho 0.03 --shape 0, written and read back), 4 interleaved runs,
// std::priority_queue 1.19-1.37 s, binary heap with replacement 1.10-1.12 s, 4-ary
// 1.01-1.08 s, the same cover; with multipliers no change (2.07-2.31 s: there the sums of
// rescoring took the time).
//
// With multipliers: lagrangian_greedy.
//
// With equal costs and no multipliers (the pipeline's instances, OR-Library's unicost runs)
// the score order is the order of μ, and the queue is a bucket per μ: no 16-byte candidates
// sifted through a 13 MB heap, whose cache misses took about a third of the greedy's time.
// The same columns in the same order. 10^6-sample torus level, 3 interleaved pairs: greedy
// stage (the first greedy beside the first coordinate ascent) 0.62 / 0.62 / 0.64 s ->
// 0.47 / 0.40 / 0.48 s, set cover 4.04 / 3.87 / 3.74 s -> 3.77 / 3.50 / 3.46 s, the same
// output hash.
std::vector<std::int32_t> greedy_cover(const Instance& inst, std::span<const double> u,
                                       std::span<const char> allowed,
                                       std::span<const std::int32_t> start) {
  if (!u.empty()) {
    return lagrangian_greedy(inst, u, allowed, start,
                             std::max<std::size_t>(256, static_cast<std::size_t>(inst.num_cols()) / 16));
  }
  std::vector<char> covered(static_cast<std::size_t>(inst.num_rows()), 0);
  std::vector<std::int32_t> mu(static_cast<std::size_t>(inst.num_cols()));
  for (std::int32_t j = 0; j < inst.num_cols(); ++j) {
    mu[j] = static_cast<std::int32_t>(inst.column(j).size());
  }
  std::int32_t uncovered = inst.num_rows();
  std::vector<std::int32_t> chosen;
  // Takes column j; `falls(k)` sees each column k whose count is about to fall by one.
  const auto take_and = [&](std::int32_t j, auto&& falls) {
    chosen.push_back(j);
    for (std::int32_t i : inst.column(j)) {
      if (!covered[i]) {
        covered[i] = 1;
        --uncovered;
        for (std::int32_t k : inst.row(i)) {
          falls(k);
          --mu[k];
        }
      }
    }
  };
  const auto take = [&](std::int32_t j) { take_and(j, [](std::int32_t) {}); };
  for (std::int32_t j : start) take(j);
  std::int32_t top = largest_count_if_equal_costs(inst, allowed, mu);
  const auto words = static_cast<std::size_t>((inst.num_cols() + 63) / 64);
  if (top >= 0 && (static_cast<std::size_t>(top) + 1) * words * 8 <=
                      4 * sizeof(std::int32_t) * static_cast<std::size_t>(inst.num_entries())) {
    // The same order with a bitset of columns per count μ, kept exact as the counts fall
    // (a column moves to its new count's set at once), instead of heaps whose stale
    // columns move when they come up: the first column of the largest count is the first
    // set bit of its set, found from a word below which that set has none. Both run one
    // after the other on the same instance (instrumented, not committed), the sets first:
    // 10^6 torus samples (2.2 million pops and 1.4 million moves of the heaps) 0.287 s
    // against 0.355 s, 5·10^5 samples 0.071 s against 0.114 s, the same columns.
    // Where the sets would take more than four times the matrix's memory, the heaps.
    std::vector<std::uint64_t> bits((static_cast<std::size_t>(top) + 1) * words, 0);
    std::vector<std::int32_t> count(static_cast<std::size_t>(top) + 1, 0);
    std::vector<std::size_t> cursor(static_cast<std::size_t>(top) + 1, words);
    std::vector<char> queued(static_cast<std::size_t>(inst.num_cols()), 0);
    const auto insert = [&](std::int32_t b, std::int32_t j) {
      const auto w = static_cast<std::size_t>(j) / 64;
      bits[static_cast<std::size_t>(b) * words + w] |= std::uint64_t{1} << (j % 64);
      ++count[b];
      cursor[b] = std::min(cursor[b], w);
    };
    const auto erase = [&](std::int32_t b, std::int32_t j) {
      bits[static_cast<std::size_t>(b) * words + static_cast<std::size_t>(j) / 64] &=
          ~(std::uint64_t{1} << (j % 64));
      --count[b];
    };
    for (std::int32_t j = 0; j < inst.num_cols(); ++j) {
      if ((allowed.empty() || allowed[j]) && mu[j] > 0) {
        insert(mu[j], j);
        queued[j] = 1;
      }
    }
    while (uncovered > 0) {
      while (top > 0 && count[top] == 0) --top;
      RSTRUCT_ASSERT_MSG(top > 0, "greedy: allowed columns do not cover every row");
      const std::uint64_t* set = bits.data() + static_cast<std::size_t>(top) * words;
      std::size_t w = cursor[top];
      while (set[w] == 0) ++w;
      cursor[top] = w;
      const auto j = static_cast<std::int32_t>(w * 64 + static_cast<std::size_t>(__builtin_ctzll(set[w])));
      erase(top, j);
      queued[j] = 0;
      take_and(j, [&](std::int32_t k) {
        if (!queued[k]) return;
        erase(mu[k], k);
        if (mu[k] > 1) {
          insert(mu[k] - 1, k);
        } else {
          queued[k] = 0;
        }
      });
    }
    remove_redundant(inst, chosen);
    return chosen;
  }
  if (top >= 0) {
    // The first column in (score, index) order is then the one with the most uncovered
    // rows, the smallest index among those: a bucket per count μ, each a min-heap of
    // column indices. A column whose μ fell since it was queued is moved to its bucket
    // when it comes up (μ only falls, so the largest non-empty bucket only falls too).
    std::vector<std::vector<std::int32_t>> bucket(static_cast<std::size_t>(top) + 1);
    for (std::int32_t j = 0; j < inst.num_cols(); ++j) {
      // Increasing indices: every bucket is a min-heap as it is filled.
      if ((allowed.empty() || allowed[j]) && mu[j] > 0) bucket[mu[j]].push_back(j);
    }
    const std::greater<std::int32_t> later;
    while (uncovered > 0) {
      while (top > 0 && bucket[top].empty()) --top;
      RSTRUCT_ASSERT_MSG(top > 0, "greedy: allowed columns do not cover every row");
      std::vector<std::int32_t>& b = bucket[top];
      std::pop_heap(b.begin(), b.end(), later);
      const std::int32_t j = b.back();
      b.pop_back();
      if (mu[j] == top) {
        take(j);
      } else if (mu[j] > 0) {
        bucket[mu[j]].push_back(j);
        std::push_heap(bucket[mu[j]].begin(), bucket[mu[j]].end(), later);
      }
    }
    remove_redundant(inst, chosen);
    return chosen;
  }
  auto score = [&](std::int32_t j) {
    if (mu[j] == 0) return Candidate{0.0, -1, 0};
    return Candidate{inst.cost(j) / mu[j], j, mu[j]};
  };
  // One batch: every candidate queued at once.
  take_in_score_order(
      inst.num_cols(), allowed, std::numeric_limits<std::size_t>::max(),
      [&](std::int32_t j) { return mu[j]; }, score, take, [&] { return uncovered; });
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
