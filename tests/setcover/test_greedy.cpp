// The lazy greedy (src/setcover/greedy.cpp: heap, incremental uncovered counts, rescoring
// only when a column lost rows) against the plain definition: at every step score every
// allowed column and take the first in (score, index) order. γ_j is defined as the greedy
// computes it: c_j minus the multipliers of all its rows, then u_i added back as row i gets
// covered (in the order the rows are covered, over the instance's row lists), so the two
// agree to the last bit; the counts μ_j are recounted from scratch here.
#include "setcover/greedy.hpp"

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <limits>
#include <random>

#include "rstruct/core/error.hpp"
#include "small_instances.hpp"

using rstruct::setcover::Instance;
using rstruct::setcover::testing::gen_small_instance;

namespace {

std::vector<std::int32_t> naive_greedy(const Instance& inst, const std::vector<double>& u,
                                       const std::vector<char>& allowed,
                                       const std::vector<std::int32_t>& start) {
  std::vector<char> covered(static_cast<std::size_t>(inst.num_rows()), 0);
  std::vector<double> gamma(static_cast<std::size_t>(inst.num_cols()));
  for (std::int32_t j = 0; j < inst.num_cols(); ++j) {
    gamma[j] = inst.cost(j);
    if (!u.empty()) {
      for (const std::int32_t i : inst.column(j)) gamma[j] -= u[i];
    }
  }
  std::vector<std::int32_t> chosen;
  const auto take = [&](std::int32_t j) {
    chosen.push_back(j);
    for (const std::int32_t i : inst.column(j)) {
      if (covered[i]) continue;
      covered[i] = 1;
      if (u.empty()) continue;
      for (const std::int32_t k : inst.row(i)) gamma[k] += u[i];
    }
  };
  for (const std::int32_t j : start) take(j);
  for (;;) {
    if (std::all_of(covered.begin(), covered.end(), [](char c) { return c != 0; })) break;
    double best = std::numeric_limits<double>::infinity();
    std::int32_t best_col = -1;
    for (std::int32_t j = 0; j < inst.num_cols(); ++j) {
      if (!allowed.empty() && !allowed[j]) continue;
      std::int32_t mu = 0;
      for (const std::int32_t i : inst.column(j)) mu += covered[i] ? 0 : 1;
      if (mu == 0) continue;
      const double g = gamma[j];
      const double score = u.empty() ? g / mu : (g > 0 ? g / mu : g * mu);
      if (score < best) {  // ties: the smaller index, met first
        best = score;
        best_col = j;
      }
    }
    RC_ASSERT(best_col >= 0);
    take(best_col);
  }
  rstruct::setcover::detail::remove_redundant(inst, chosen);
  return chosen;
}

}  // namespace

TEST_CASE("lazy greedy takes the columns the plain greedy takes") {
  rc::prop("with and without multipliers, allowed columns and a start", [] {
    const auto s = *gen_small_instance();
    const Instance inst = s.build();
    std::vector<double> u;
    if (*rc::gen::arbitrary<bool>()) {
      // Multipliers on a grid of quarters: equal scores (ties) are frequent.
      for (std::int32_t i = 0; i < inst.num_rows(); ++i) {
        u.push_back(0.25 * *rc::gen::inRange(0, 12));
      }
    }
    std::vector<std::int32_t> start;
    if (inst.num_cols() > 1 && *rc::gen::arbitrary<bool>()) start.push_back(inst.num_cols() - 1);
    // Some columns barred (empty: every column), as long as the others and the start still
    // cover every row (the greedy's precondition).
    std::vector<char> allowed;
    if (*rc::gen::arbitrary<bool>()) {
      std::vector<char> covered(static_cast<std::size_t>(inst.num_rows()), 0);
      for (std::int32_t j = 0; j < inst.num_cols(); ++j) {
        allowed.push_back(*rc::gen::inRange(0, 4) != 0 ? 1 : 0);
        const bool in_start = std::find(start.begin(), start.end(), j) != start.end();
        if (allowed.back() || in_start) {
          for (const std::int32_t i : inst.column(j)) covered[i] = 1;
        }
      }
      RC_PRE(std::all_of(covered.begin(), covered.end(), [](char c) { return c != 0; }));
    }
    const auto lazy = rstruct::setcover::detail::greedy_cover(inst, u, allowed, start);
    const auto naive = naive_greedy(inst, u, allowed, start);
    RC_ASSERT(lazy == naive);
    if (!u.empty()) {
      // Columns queued a few at a time: the batches must not change the columns taken.
      const auto batch = static_cast<std::size_t>(*rc::gen::inRange(1, 4));
      RC_ASSERT(rstruct::setcover::detail::lagrangian_greedy(inst, u, allowed, start, batch) == naive);
    }
  });
}

TEST_CASE("lazy greedy takes the columns the plain greedy takes, on instances of hundreds of columns") {
  // Large enough for a deep heap, whose every level the re-queueing of stale columns walks;
  // small integer costs and multipliers on a grid of quarters give many equal scores.
  for (std::uint64_t seed = 1; seed <= 60; ++seed) {
    INFO("seed " << seed);
    std::mt19937_64 rng(seed);
    const auto rows = static_cast<std::int32_t>(300 + rng() % 500);
    const auto cols = static_cast<std::int32_t>(1000 + rng() % 1000);
    std::vector<std::vector<std::int32_t>> columns(static_cast<std::size_t>(cols));
    std::vector<double> costs;
    for (auto& c : columns) {
      const auto centre = static_cast<std::int32_t>(rng() % static_cast<std::uint64_t>(rows));
      const auto size = 1 + rng() % 12;
      for (std::uint64_t t = 0; t < size; ++t) {
        c.push_back(std::clamp<std::int32_t>(centre + static_cast<std::int32_t>(rng() % 21) - 10, 0, rows - 1));
      }
      // Unit, small integer and real costs (real: the scores rarely tie, and a stale
      // column's new score often falls between the next ones in the queue).
      const double real = 1.0 + static_cast<double>(rng() % 1000) / 1000.0;
      costs.push_back(seed % 3 == 0 ? 1.0 : seed % 3 == 1 ? static_cast<double>(1 + rng() % 4) : real);
    }
    for (std::int32_t i = 0; i < rows; ++i) columns[static_cast<std::size_t>(rng() % columns.size())].push_back(i);
    const Instance inst = Instance::from_columns(rows, columns, costs);
    // Multipliers on every other seed: then the columns are queued in batches of 256 or
    // more (lagrangian_greedy), several batches on these instances.
    std::vector<double> u;
    for (std::int32_t i = 0; seed % 2 == 0 && i < rows; ++i) u.push_back(0.25 * static_cast<double>(rng() % 8));
    const auto lazy = rstruct::setcover::detail::greedy_cover(inst, u, {}, {});
    const auto naive = naive_greedy(inst, u, {}, {});
    CHECK(lazy == naive);
    if (!u.empty()) {
      for (const std::size_t batch : {1, 7, 40}) {
        INFO("batches of " << batch);
        CHECK(rstruct::setcover::detail::lagrangian_greedy(inst, u, {}, {}, batch) == naive);
      }
    }
  }
}

TEST_CASE("unit-cost greedy: the bitset sets and the heaps both take the plain greedy's columns") {
  // Unit costs take one of two queues by count μ: a bitset of columns per count, or, where
  // those sets would take more than four times the matrix's memory (a few columns far
  // larger than the rest: many counts, many columns, few entries), a heap per count.
  // Instances of both kinds, with many equal counts (ties to the smallest index).
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    INFO("seed " << seed);
    std::mt19937_64 rng(seed);
    const bool wide = seed % 2 == 0;  // large columns: the heaps
    const auto rows = static_cast<std::int32_t>(2000 + rng() % 2000);
    std::vector<std::vector<std::int32_t>> columns;
    for (int k = 0; k < 3000; ++k) {
      std::vector<std::int32_t> c;
      const auto centre = static_cast<std::int32_t>(rng() % static_cast<std::uint64_t>(rows));
      for (std::uint64_t t = 0, size = 1 + rng() % 4; t < size; ++t) {
        c.push_back(std::clamp<std::int32_t>(centre + static_cast<std::int32_t>(rng() % 9) - 4, 0, rows - 1));
      }
      columns.push_back(c);
    }
    for (int k = 0; wide && k < 6; ++k) {  // overlapping stretches of 300 to 1,500 rows
      const auto first = static_cast<std::int32_t>(rng() % static_cast<std::uint64_t>(rows));
      const auto length = static_cast<std::int32_t>(300 + rng() % 1200);
      std::vector<std::int32_t> c;
      for (std::int32_t i = first; i < std::min(rows, first + length); ++i) c.push_back(i);
      columns.insert(columns.begin() + static_cast<std::ptrdiff_t>(rng() % columns.size()), c);
    }
    for (std::int32_t i = 0; i < rows; ++i) columns[static_cast<std::size_t>(rng() % columns.size())].push_back(i);
    const Instance inst = Instance::from_columns(rows, columns);
    std::int64_t top = 0;
    for (std::int32_t j = 0; j < inst.num_cols(); ++j) {
      top = std::max<std::int64_t>(top, static_cast<std::int64_t>(inst.column(j).size()));
    }
    const std::int64_t bitset_bytes = (top + 1) * ((inst.num_cols() + 63) / 64) * 8;
    CHECK((bitset_bytes > 16 * inst.num_entries()) == wide);  // the kind of queue intended
    CHECK(rstruct::setcover::detail::greedy_cover(inst, {}, {}, {}) == naive_greedy(inst, {}, {}, {}));
  }
}

TEST_CASE("greedy refuses a negative multiplier") {
  // γ would then fall as rows get covered, and the lazy queue could take a column that is
  // no longer first.
  const Instance inst = Instance::from_columns(2, {{0}, {1}, {0, 1}}, {1.0, 1.0, 1.5});
  const std::vector<double> negative{0.5, -0.25};
  const std::vector<double> positive{0.5, 0.25};
  CHECK_THROWS_AS(rstruct::setcover::detail::greedy_cover(inst, negative), rstruct::InternalError);
  CHECK(rstruct::setcover::detail::greedy_cover(inst, positive) == std::vector<std::int32_t>{2});
}
