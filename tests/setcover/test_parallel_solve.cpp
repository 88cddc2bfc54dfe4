// The set-cover solver's threads (presolve domination checks, pricing passes, the greedy
// beside the ascent, the last Lagrangian greedy beside the final ascent) never change its
// result: on instances large enough for every parallel path, 1, 2 and 3 threads give the
// same presolve (removals, work, components), the same cover, bound and statistics.
#include "setcover/reduction.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <vector>

#include "rstruct/core/stopwatch.hpp"
#include "rstruct/setcover/solver.hpp"

using namespace rstruct::setcover;

namespace {

/// 100,000 rows; 50,000 columns of 20 rows near a random centre (costs 1–3), a random
/// subset of every other one (dominated when not cheaper), and a singleton of cost 4 per
/// row (coverage; dominated): about 1.4·10^6 entries, with dominated rows and columns
/// for the presolve to find over several rounds of checks.
Instance large_instance(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const std::int32_t rows = 100'000;
  std::vector<std::vector<std::int32_t>> cols;
  std::vector<double> costs;
  for (int j = 0; j < 50'000; ++j) {
    std::vector<std::int32_t> c;
    const auto centre = static_cast<std::int32_t>(rng() % rows);
    for (int t = 0; t < 20; ++t) {
      c.push_back(std::clamp<std::int32_t>(centre + static_cast<std::int32_t>(rng() % 200) - 100, 0, rows - 1));
    }
    cols.push_back(c);
    costs.push_back(static_cast<double>(1 + rng() % 3));
    if (j % 2 == 0) {
      std::vector<std::int32_t> sub;
      for (const std::int32_t i : c) {
        if (rng() % 2 == 0) sub.push_back(i);
      }
      if (sub.empty()) sub.push_back(c.front());
      cols.push_back(sub);
      costs.push_back(static_cast<double>(1 + rng() % 3));
    }
  }
  for (std::int32_t i = 0; i < rows; ++i) {
    cols.push_back({i});
    costs.push_back(4.0);
  }
  return Instance::from_columns(rows, cols, costs);
}

void check_same_reduction(const detail::Reduction& a, const detail::Reduction& b) {
  CHECK(a.fixed_cols == b.fixed_cols);
  CHECK(a.forced_multipliers == b.forced_multipliers);
  CHECK(a.dominated_rows == b.dominated_rows);
  CHECK(a.dominated_cols == b.dominated_cols);
  CHECK(a.forced_cols == b.forced_cols);
  CHECK(a.work == b.work);
  CHECK(a.work_limited == b.work_limited);
  REQUIRE(a.components.size() == b.components.size());
  for (std::size_t c = 0; c < a.components.size(); ++c) {
    const detail::Component& x = a.components[c];
    const detail::Component& y = b.components[c];
    CHECK(x.rows == y.rows);
    CHECK(x.cols == y.cols);
    REQUIRE(x.instance.num_cols() == y.instance.num_cols());
    bool same = x.instance.num_rows() == y.instance.num_rows();
    for (std::int32_t j = 0; same && j < x.instance.num_cols(); ++j) {
      const auto p = x.instance.column(j);
      const auto q = y.instance.column(j);
      same = std::equal(p.begin(), p.end(), q.begin(), q.end()) &&
             x.instance.cost(j) == y.instance.cost(j);
    }
    for (std::int32_t i = 0; same && i < x.instance.num_rows(); ++i) {
      const auto p = x.instance.row(i);
      const auto q = y.instance.row(i);
      same = std::equal(p.begin(), p.end(), q.begin(), q.end());
    }
    CHECK(same);
  }
}

/// Many components: 3,000 blocks of 40 rows and 12 columns (the presolve leaves hundreds of
/// them, each far smaller than a parallel chunk of columns), and one block of 30,000 rows
/// and 20,000 columns (larger than one): the components' copy takes both parallel paths.
Instance blocks_instance(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<std::vector<std::int32_t>> cols;
  std::int32_t rows = 0;
  const auto block = [&](std::int32_t height, std::int32_t width, int per_col) {
    for (std::int32_t j = 0; j < width; ++j) {
      std::vector<std::int32_t> c;
      for (int t = 0; t < per_col; ++t) c.push_back(rows + static_cast<std::int32_t>(rng() % height));
      cols.push_back(c);
    }
    for (std::int32_t i = 0; i < height; ++i) cols.push_back({rows + i});  // coverage
    rows += height;
  };
  for (int b = 0; b < 1500; ++b) block(40, 12, 8);
  block(30'000, 20'000, 12);
  for (int b = 0; b < 1500; ++b) block(40, 12, 8);
  return Instance::from_columns(rows, cols);
}

}  // namespace

TEST_CASE("presolve: many components, the same on 1, 2 and 3 threads") {
  const Instance inst = blocks_instance(0xb10c);
  const rstruct::Stopwatch clock;
  const detail::Reduction one = detail::reduce(inst, true, 1e9, clock, 0, 1);
  REQUIRE(one.components.size() > 500);  // the presolve empties some blocks
  std::size_t widest = 0;
  for (const detail::Component& c : one.components) widest = std::max(widest, c.cols.size());
  CHECK(widest > 16'384);
  for (const unsigned threads : {2u, 3u}) {
    INFO(threads << " threads");
    check_same_reduction(one, detail::reduce(inst, true, 1e9, clock, 0, threads));
  }
}

TEST_CASE("presolve: the same removals, work and components on 1, 2 and 3 threads") {
  const Instance inst = large_instance(0x5eed1);
  REQUIRE(inst.num_rows() > 65'536);  // more than one round of domination checks
  const rstruct::Stopwatch clock;
  const detail::Reduction full = detail::reduce(inst, true, 1e9, clock, 0, 1);
  CHECK(full.dominated_cols > 1000);
  CHECK(full.dominated_rows > 100);
  CHECK(!full.work_limited);
  // No limit, and limits that cut the passes part way (in the rows' or the columns' checks).
  for (const std::int64_t limit : {std::int64_t{0}, full.work / 2, full.work / 5}) {
    INFO("work limit " << limit);
    const detail::Reduction one = detail::reduce(inst, true, 1e9, clock, limit, 1);
    CHECK(one.work_limited == (limit > 0));
    if (limit > 0) CHECK(one.dominated_cols + one.dominated_rows < full.dominated_cols + full.dominated_rows);
    for (const unsigned threads : {2u, 3u}) {
      INFO(threads << " threads");
      check_same_reduction(one, detail::reduce(inst, true, 1e9, clock, limit, threads));
    }
  }
}

TEST_CASE("solver: the same cover, bound and statistics on 1, 2 and 3 threads") {
  const Instance inst = large_instance(0x5eed2);
  REQUIRE(inst.num_entries() >= 1'000'000);  // every parallel path is taken
  SolverOptions o;
  o.time_limit = 600.0;  // the work limits end every stage first
  o.max_local_search_iterations = 2'000;
  o.max_subgradient_iterations = 10;  // the last iteration runs a heuristic (as the pipeline)
  o.threads = 1;
  const Solution one = solve(inst, o);
  REQUIRE(inst.is_cover(one.columns));
  CHECK(one.stats.stopped_by == SearchLimit::kIterations);
  for (const unsigned threads : {2u, 3u}) {
    INFO(threads << " threads");
    o.threads = threads;
    const Solution s = solve(inst, o);
    CHECK(s.columns == one.columns);
    CHECK(s.cost == one.cost);
    CHECK(s.lower_bound == one.lower_bound);
    CHECK(s.stats.greedy_cost == one.stats.greedy_cost);
    CHECK(s.stats.dominated_rows == one.stats.dominated_rows);
    CHECK(s.stats.dominated_columns == one.stats.dominated_columns);
    CHECK(s.stats.reduction_work == one.stats.reduction_work);
    CHECK(s.stats.components == one.stats.components);
    CHECK(s.stats.subgradient_iterations == one.stats.subgradient_iterations);
    CHECK(s.stats.local_search_iterations == one.stats.local_search_iterations);
  }
}
