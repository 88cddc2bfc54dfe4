#include "rstruct/setcover/solver.hpp"

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>
#include <algorithm>
#include <random>
#include <sstream>

#include "rstruct/core/error.hpp"
#include "rstruct/setcover/verifier.hpp"
#include "small_instances.hpp"

using namespace rstruct::setcover;
using rstruct::setcover::testing::brute_force_optimum;
using rstruct::setcover::testing::gen_small_instance;
using rstruct::setcover::testing::SmallInstance;

namespace {

SolverOptions small_options(std::uint64_t seed = 1) {
  SolverOptions o;
  o.time_limit = 30.0;  // a safety net: the work limits end the search first
  o.seed = seed;
  o.max_local_search_iterations = 20'000;
  return o;
}

Verdict verify(const SmallInstance& s, const Certificate& cert) {
  std::istringstream in(certificate_text(cert));
  return verify_certificate(s.rows, s.columns, s.costs, in);
}

}  // namespace

TEST_CASE("small instances: optimal cost, bound <= optimum, certificate valid") {
  rc::prop("solver matches brute force", [] {
    const SmallInstance s = *gen_small_instance();
    const Instance inst = s.build();
    const double opt = brute_force_optimum(inst);
    for (bool domination : {true, false}) {
      SolverOptions o = small_options();
      o.use_domination = domination;
      const Solution sol = solve(inst, o);
      RC_ASSERT(inst.is_cover(sol.columns));
      RC_ASSERT(sol.cost == opt);
      RC_ASSERT(sol.lower_bound <= opt);
      RC_ASSERT(sol.proven_optimal);
      RC_ASSERT(sol.optimal == (sol.lower_bound == sol.cost));
      const Verdict v = verify(s, sol.certificate);
      RC_LOG() << v.summary() << "\n" << certificate_text(sol.certificate);
      RC_ASSERT(v.valid);
      RC_ASSERT(v.bound_value == sol.lower_bound);
      RC_ASSERT(v.cost_value == sol.cost);
    }
  });
}

TEST_CASE("the result does not depend on the order of the columns (metamorphic)") {
  rc::prop("reversed columns give the same optimal cost", [] {
    SmallInstance s = *gen_small_instance();
    const double a = solve(s.build(), small_options()).cost;
    std::reverse(s.columns.begin(), s.columns.end());
    std::reverse(s.costs.begin(), s.costs.end());
    RC_ASSERT(solve(s.build(), small_options()).cost == a);
  });
}

TEST_CASE("an uncoverable row is a clear error") {
  const Instance inst = Instance::from_columns(3, {{0}, {2}});
  CHECK_THROWS_AS(solve(inst), rstruct::ComputationFailed);
  CHECK_THROWS_WITH(solve(inst), Catch::Contains("row 1"));
}

TEST_CASE("trivial instances") {
  const Instance empty = Instance::from_columns(0, {});
  const Solution e = solve(empty);
  CHECK(e.cost == 0.0);
  CHECK(e.optimal);
  const Instance zero = Instance::from_columns(2, {{0, 1}, {0}}, {0.0, 1.0});
  const Solution z = solve(zero);
  CHECK(z.cost == 0.0);
  CHECK(z.columns == std::vector<std::int32_t>{0});
}

TEST_CASE("non-integer costs: exact certificate, no ceiling") {
  SmallInstance s;
  s.rows = 3;
  s.columns = {{0, 1}, {1, 2}, {0, 2}, {0}, {1}, {2}};
  s.costs = {0.7, 0.7, 0.7, 0.3, 0.3, 0.3};
  const Instance inst = s.build();
  const Solution sol = solve(inst, small_options());
  CHECK(sol.cost == Approx(0.9));
  // LP optimum is 0.9 as well (u = 0.3 each), so the bound is close but never above the cost.
  CHECK(sol.lower_bound <= sol.cost);
  CHECK(sol.lower_bound > 0.89);
  const Verdict v = verify(s, sol.certificate);
  CHECK(v.valid);
  CHECK_FALSE(v.integer_costs);
}

TEST_CASE("geometric-style instance: cover, bound and certificate") {
  // Points on a circle, each column covers its point and 3 neighbours on each side.
  const std::int32_t n = 3000;
  std::vector<std::vector<std::int32_t>> cols(n);
  for (std::int32_t j = 0; j < n; ++j) {
    for (std::int32_t d = -3; d <= 3; ++d) cols[j].push_back((j + d + n) % n);
  }
  const Instance inst = Instance::from_columns(n, cols);
  const Solution sol = solve(inst, small_options());
  CHECK(inst.is_cover(sol.columns));
  CHECK(sol.cost == 429);  // ⌈3000 / 7⌉
  CHECK(sol.lower_bound <= 429);
  CHECK(sol.lower_bound >= 420);  // LP optimum 3000/7 = 428.57…
  std::istringstream in(certificate_text(sol.certificate));
  CHECK(verify_certificate(n, cols, {}, in).valid);
}

TEST_CASE("local-search streams: deterministic under an iteration limit, never worse than one") {
  // A random unicost instance too large for the exact search, so the local search decides.
  std::mt19937_64 rng(0x5eed5c);
  const std::int32_t rows = 300;
  std::vector<std::vector<std::int32_t>> cols(1500);
  for (auto& c : cols) {
    for (std::int32_t i = 0; i < rows; ++i) {
      if (rng() % 50 == 0) c.push_back(i);
    }
  }
  for (std::int32_t i = 0; i < rows; ++i) cols[static_cast<std::size_t>(i) % cols.size()].push_back(i);
  for (auto& c : cols) {
    std::sort(c.begin(), c.end());
    c.erase(std::unique(c.begin(), c.end()), c.end());
  }
  const Instance inst = Instance::from_columns(rows, cols);
  SolverOptions one = small_options(7);
  one.local_search_streams = 1;
  SolverOptions two = small_options(7);
  two.local_search_streams = 2;
  two.threads = 2;
  SolverOptions two_sequential = two;
  two_sequential.threads = 1;
  const Solution a = solve(inst, one);
  const Solution b = solve(inst, two);
  const Solution c = solve(inst, two);
  const Solution d = solve(inst, two_sequential);
  REQUIRE(inst.is_cover(b.columns));
  REQUIRE(b.stats.local_search_iterations > a.stats.local_search_iterations);  // both streams ran
  // Stream 0 repeats the single-stream search, so two streams can only do better.
  CHECK(b.cost <= a.cost);
  // Same seed and work limits: the same cover, on two threads or one after another.
  CHECK(b.columns == c.columns);
  CHECK(b.columns == d.columns);
  // Each stream ran its budget in full (or reached the bound); the report says so.
  CHECK(b.stats.local_search_iterations <= 2 * two.max_local_search_iterations);
  CHECK(b.stats.local_search_iterations == d.stats.local_search_iterations);
  CHECK(b.stats.stopped_by == SearchLimit::kIterations);
  CHECK(d.stats.stopped_by == SearchLimit::kIterations);
}

TEST_CASE("work limits: counts within the budget over several components, and the limit named") {
  // Three random unicost blocks on disjoint rows (three components after reduction), each
  // too large for the exact search, so that the local search runs in every component.
  std::mt19937_64 rng(0xb0d6e7);
  const std::int32_t sizes[] = {100, 200, 300};
  std::int32_t rows = 0;
  std::vector<std::vector<std::int32_t>> cols;
  for (const std::int32_t n : sizes) {
    std::vector<std::vector<std::int32_t>> block(static_cast<std::size_t>(5 * n));
    for (auto& c : block) {
      for (std::int32_t i = 0; i < n; ++i) {
        if (rng() % 25 == 0) c.push_back(rows + i);
      }
    }
    for (std::int32_t i = 0; i < n; ++i) block[static_cast<std::size_t>(i)].push_back(rows + i);
    for (auto& c : block) {
      std::sort(c.begin(), c.end());
      c.erase(std::unique(c.begin(), c.end()), c.end());
      cols.push_back(c);
    }
    rows += n;
  }
  const Instance inst = Instance::from_columns(rows, cols);
  for (const std::int64_t budget : {std::int64_t{1}, std::int64_t{1000}, std::int64_t{9999}}) {
    SolverOptions o = small_options(3);
    o.max_local_search_iterations = budget;
    o.max_subgradient_iterations = 50;
    const Solution s = solve(inst, o);
    INFO("budget " << budget << ": " << s.stats.components << " components, "
                   << s.stats.local_search_iterations << " local-search and "
                   << s.stats.subgradient_iterations << " subgradient iterations");
    REQUIRE(inst.is_cover(s.columns));
    CHECK(s.stats.components >= 3);
    CHECK(s.stats.local_search_iterations <= budget * o.local_search_streams);
    CHECK(s.stats.subgradient_iterations <= 50 * s.stats.components);
    CHECK(s.stats.stopped_by != SearchLimit::kTime);
    if (budget > 1) CHECK(s.stats.local_search_iterations > 0);
  }
  // No time at all: the time limit is named as what ended the search.
  SolverOptions none = small_options(3);
  none.time_limit = 0.0;
  const Solution t = solve(inst, none);
  CHECK(inst.is_cover(t.columns));
  CHECK(t.stats.stopped_by == SearchLimit::kTime);
  CHECK(std::string(to_string(SearchLimit::kIterations)) == "iterations");
}

TEST_CASE("domination work limit: deterministic cut, valid cover, the limit named") {
  // Columns and many of their subsets (dominated columns) over random rows: the domination
  // passes have real work to do. A small limit must cut them (fewer dominated columns found,
  // less work), leave a valid cover and certificate, and be reported as a work limit; the
  // default limit must not cut them here (their unlimited work is far below 64 per entry).
  std::mt19937_64 rng(0xd0111a7e);
  const std::int32_t rows = 400;
  std::vector<std::vector<std::int32_t>> cols;
  for (int j = 0; j < 300; ++j) {
    std::vector<std::int32_t> c;
    for (std::int32_t i = 0; i < rows; ++i) {
      if (rng() % 20 == 0) c.push_back(i);
    }
    if (c.empty()) c.push_back(static_cast<std::int32_t>(rng() % rows));
    cols.push_back(c);
    std::vector<std::int32_t> sub;
    for (const std::int32_t i : c) {
      if (rng() % 2 == 0) sub.push_back(i);
    }
    if (!sub.empty()) cols.push_back(sub);
  }
  for (std::int32_t i = 0; i < rows; ++i) cols.push_back({i});
  const Instance inst = Instance::from_columns(rows, cols);
  SolverOptions full = small_options();
  full.max_local_search_iterations = 2000;
  full.domination_work_per_entry = 0;  // no work limit
  full.max_domination_work = 0;
  SolverOptions cut = full;
  cut.domination_work_per_entry = 0.5;
  SolverOptions standard = full;
  standard.domination_work_per_entry = 64;
  standard.max_domination_work = 1'000'000'000;
  SolverOptions capped = full;  // the absolute cap alone, set low
  capped.max_domination_work = 100;
  const Solution a = solve(inst, full);
  const Solution b = solve(inst, cut);
  const Solution b2 = solve(inst, cut);
  const Solution c = solve(inst, standard);
  INFO("work per entry: unlimited " << a.stats.reduction_work / double(inst.num_entries())
                                    << ", cut " << b.stats.reduction_work / double(inst.num_entries()));
  REQUIRE(inst.is_cover(a.columns));
  REQUIRE(inst.is_cover(b.columns));
  CHECK(a.stats.dominated_columns > 0);
  CHECK(b.stats.dominated_columns < a.stats.dominated_columns);
  CHECK(b.stats.reduction_work < a.stats.reduction_work);
  CHECK(b.stats.stopped_by == SearchLimit::kIterations);
  CHECK(b.columns == b2.columns);
  CHECK(b.stats.reduction_work == b2.stats.reduction_work);
  CHECK(b.lower_bound <= a.cost);
  CHECK(a.lower_bound <= b.cost);
  // The default limit leaves this instance's reduction as without one.
  CHECK(a.stats.reduction_work < 64 * inst.num_entries());
  CHECK(c.stats.reduction_work == a.stats.reduction_work);
  CHECK(c.stats.dominated_columns == a.stats.dominated_columns);
  CHECK(c.columns == a.columns);
  const Solution d = solve(inst, capped);
  REQUIRE(inst.is_cover(d.columns));
  CHECK(d.stats.reduction_work < a.stats.reduction_work);
  CHECK(d.stats.stopped_by == SearchLimit::kIterations);
}
