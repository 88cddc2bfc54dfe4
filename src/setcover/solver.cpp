#include "rstruct/setcover/solver.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <limits>
#include <optional>
#include <thread>

#include "branch_and_bound.hpp"
#include "greedy.hpp"
#include "local_search.hpp"
#include "reduction.hpp"
#include "rstruct/core/assert.hpp"
#include "rstruct/core/error.hpp"
#include "rstruct/core/parallel.hpp"
#include "rstruct/core/stopwatch.hpp"
#include "subgradient.hpp"

namespace rstruct::setcover {

namespace {

using detail::Component;

struct ComponentResult {
  std::vector<std::int32_t> cover;  ///< component columns
  double cost = 0.0;
  std::vector<double> u;            ///< component rows
  double greedy_cost = 0.0;
  double seconds_to_best = 0.0;
  std::int64_t subgradient_iterations = 0;
  std::int64_t local_search_iterations = 0;
  double greedy_seconds = 0.0;
  double subgradient_seconds = 0.0;
  double local_search_seconds = 0.0;
  bool proven = false;  ///< no cheaper cover exists (bound, reduced-cost fixing or search)
  std::int64_t exact_nodes = 0;
  bool timed_out = false;       ///< the deadline ended or skipped some stage
  bool hit_work_limit = false;  ///< an iteration or node limit ended some stage
};

/// Components whose surviving columns number at most this get an exact search first.
constexpr std::int32_t kExactColumns = 60;
constexpr std::int64_t kExactNodes = 300'000;
/// Instances with at least this many entries run the domination checks in parallel.
constexpr std::int64_t kParallelReductionEntries = 100'000;
/// Components with at least this many entries run their greedy beside the first ascent.
constexpr std::int64_t kGreedyBesideEntries = 1'000'000;

struct Budget {
  double deadline = 0.0;              ///< seconds on the solver clock
  std::int64_t local_search_iterations = -1;  ///< per stream; negative: unlimited
  std::int32_t subgradient_iterations = 0;
  std::uint64_t seed = 1;
  std::int32_t streams = 1;
  unsigned threads = 1;
};

/// Columns j that may still be in a cover cheaper than `ub`: bound + reduced_j must stay
/// below it (any cover containing j costs at least L(u) + max(0, r_j)).
std::vector<char> reduced_cost_filter(const Instance& inst, const detail::LagrangianState& st,
                                      std::vector<double>& reduced, unsigned threads) {
  detail::lagrangian_bound(inst, st.u, &reduced, threads);
  const double slack = 1e-9 * std::max(1.0, std::abs(st.cover_cost));
  const double limit = inst.has_integer_costs() ? st.cover_cost - 1.0 + slack : st.cover_cost - slack;
  std::vector<char> allowed(static_cast<std::size_t>(inst.num_cols()), 0);
  for (std::int32_t j = 0; j < inst.num_cols(); ++j) {
    allowed[j] = st.bound + std::max(0.0, reduced[j]) <= limit;
  }
  return allowed;
}

/// Local search on the columns that survive reduced-cost fixing.
void improve_by_local_search(const Instance& inst, detail::LagrangianState& st,
                             const Budget& budget, const Stopwatch& clock, ComponentResult& out) {
  std::vector<double> reduced;
  const std::vector<char> allowed = reduced_cost_filter(inst, st, reduced, budget.threads);
  // The surviving columns as an instance of their own, `map` giving each one's number in
  // `inst`; unless every column survives (the pipeline's instances, whose gap leaves every
  // reduced cost below it): then `inst` itself, not a copy of it (10^6 torus samples: 2·10^7
  // entries copied and transposed on one thread, 0.13 s).
  const bool all_survive = std::find(allowed.begin(), allowed.end(), 0) == allowed.end();
  std::optional<Instance> copy;
  std::vector<std::int32_t> map;
  if (!all_survive) {
    std::vector<std::int64_t> start{0};
    std::vector<std::int32_t> entries;
    std::vector<double> costs;
    std::vector<char> row_ok(static_cast<std::size_t>(inst.num_rows()), 0);
    // Sized exactly: on large instances (10^8 entries) growth by doubling would hold up to
    // twice the entries, on top of the instance and of the copy made from them.
    std::int64_t kept_entries = 0;
    for (std::int32_t j = 0; j < inst.num_cols(); ++j) {
      if (allowed[j]) kept_entries += static_cast<std::int64_t>(inst.column(j).size());
    }
    entries.reserve(static_cast<std::size_t>(kept_entries));
    for (std::int32_t j = 0; j < inst.num_cols(); ++j) {
      if (!allowed[j]) continue;
      map.push_back(j);
      for (std::int32_t i : inst.column(j)) {
        entries.push_back(i);
        row_ok[i] = 1;
      }
      start.push_back(static_cast<std::int64_t>(entries.size()));
      costs.push_back(inst.cost(j));
    }
    // A row no surviving column covers: no cover is cheaper than the incumbent.
    if (std::find(row_ok.begin(), row_ok.end(), 0) != row_ok.end()) {
      out.proven = true;
      return;
    }
    copy = Instance::from_csr(inst.num_rows(), std::move(start), std::move(entries),
                              std::move(costs), budget.threads);
  }
  const Instance& sub = all_survive ? inst : *copy;
  const auto original = [&](std::int32_t k) { return all_survive ? k : map[k]; };
  if (sub.num_cols() <= kExactColumns) {
    const auto bb = detail::branch_and_bound(sub, st.cover_cost, kExactNodes, budget.deadline, clock);
    out.exact_nodes = bb.nodes;
    out.timed_out = out.timed_out || bb.timed_out;
    out.hit_work_limit = out.hit_work_limit || (!bb.finished && !bb.timed_out);
    if (!bb.best.empty() && bb.best_cost < st.cover_cost) {
      st.cover.clear();
      for (std::int32_t k : bb.best) st.cover.push_back(original(k));
      st.cover_cost = inst.cost_of(st.cover);
      out.seconds_to_best = clock.seconds();
    }
    if (bb.finished) {
      out.proven = true;
      return;
    }
  }
  std::vector<std::int32_t> seed_cols;
  if (all_survive) {
    seed_cols = st.cover;
  } else {
    std::vector<std::int32_t> local_of(static_cast<std::size_t>(inst.num_cols()), -1);
    for (std::size_t k = 0; k < map.size(); ++k) local_of[map[k]] = static_cast<std::int32_t>(k);
    for (std::int32_t j : st.cover) {
      if (local_of[j] >= 0) seed_cols.push_back(local_of[j]);
    }
  }
  const auto streams = static_cast<std::size_t>(std::max(1, budget.streams));
  const bool limited = budget.local_search_iterations >= 0;
  std::atomic<bool> stop{false};
  std::vector<detail::LocalSearchResult> results(streams);
  auto run_stream = [&](std::size_t s, double deadline) {
    detail::LocalSearchOptions lso;
    lso.deadline = deadline;
    lso.seed = budget.seed + 0x632BE59BD9B4E019ULL * s;
    lso.max_iterations = limited ? budget.local_search_iterations : INT64_MAX;
    lso.target = inst.has_integer_costs() ? std::ceil(st.bound - 1e-9) : st.bound;
    // With an iteration limit every stream runs to its end (a deterministic result);
    // otherwise the first stream to reach the bound stops the others.
    lso.stop = limited ? nullptr : &stop;
    results[s] = detail::row_weighting_search(sub, seed_cols, st.cover_cost, lso, clock);
  };
  const unsigned threads = std::max(1u, std::min<unsigned>(budget.threads, static_cast<unsigned>(streams)));
  if (threads >= streams) {
    std::vector<std::jthread> pool;
    for (std::size_t s = 1; s < streams; ++s) pool.emplace_back(run_stream, s, budget.deadline);
    run_stream(0, budget.deadline);
  } else {
    for (std::size_t s = 0; s < streams; ++s) {
      const double now = clock.seconds();
      const double left = std::max(0.0, budget.deadline - now);
      run_stream(s, now + left / static_cast<double>(streams - s));
    }
  }
  std::size_t winner = 0;
  for (std::size_t s = 0; s < streams; ++s) {
    out.local_search_iterations += results[s].iterations;
    out.timed_out = out.timed_out || results[s].timed_out;
    out.hit_work_limit = out.hit_work_limit || results[s].hit_iteration_limit;
    const auto& r = results[s];
    const auto& w = results[winner];
    if (!r.best.empty() && (w.best.empty() || r.best_cost < w.best_cost)) winner = s;
  }
  const detail::LocalSearchResult& ls = results[winner];
  if (!ls.best.empty() && ls.best_cost < st.cover_cost) {
    st.cover.clear();
    for (std::int32_t k : ls.best) st.cover.push_back(original(k));
    detail::remove_redundant(inst, st.cover);
    st.cover_cost = inst.cost_of(st.cover);
    out.seconds_to_best = ls.seconds_to_best;
  }
}

ComponentResult solve_component(const Instance& inst, const Budget& budget, const Stopwatch& clock) {
  ComponentResult out;
  const double t0 = clock.seconds();
  detail::LagrangianState st;
  // The greedy cover and the first multipliers do not depend on each other: on a large
  // component with two threads or more the greedy runs on its own thread meanwhile.
  const unsigned threads = std::max(1u, budget.threads);
  const bool beside = threads > 1 && inst.num_entries() >= kGreedyBesideEntries;
  std::exception_ptr greedy_error;
  {
    const auto greedy = [&] {
      try {
        st.cover = detail::greedy_cover(inst);
        st.cover_cost = inst.cost_of(st.cover);
        out.seconds_to_best = clock.seconds();
      } catch (...) {
        greedy_error = std::current_exception();
      }
    };
    std::jthread greedy_thread;
    if (beside) {
      greedy_thread = std::jthread(greedy);
    } else {
      greedy();
    }
    const unsigned ascent_threads = beside ? threads - 1 : threads;
    st.u = detail::initial_multipliers(inst);
    st.bound = detail::lagrangian_bound(inst, st.u, nullptr, ascent_threads);
    // Coordinate ascent first: a few O(entries) sweeps give a good bound on large sparse
    // instances, where each subgradient iteration is as expensive as a sweep.
    if (clock.seconds() < budget.deadline) {
      detail::coordinate_ascent(inst, st, 5, t0 + 0.2 * std::max(0.0, budget.deadline - t0),
                                clock, ascent_threads);
    } else {
      out.timed_out = true;
    }
  }  // joins the greedy
  if (greedy_error) std::rethrow_exception(greedy_error);
  out.greedy_cost = st.cover_cost;
  const double now = clock.seconds();
  out.greedy_seconds = now - t0;
  detail::SubgradientOptions so;
  so.max_iterations = budget.subgradient_iterations;
  so.deadline = now + 0.3 * std::max(0.0, budget.deadline - now);
  so.threads = threads;
  const double before = st.cover_cost;
  // Past the deadline only the mandatory work (a cover, multipliers) is done.
  if (clock.seconds() < so.deadline) {
    detail::subgradient(inst, st, so, clock);
    // The last iteration's greedy may still run (state.pending): one thread fewer here.
    detail::coordinate_ascent(inst, st, 20, so.deadline, clock,
                              st.pending && threads > 1 ? threads - 1 : threads);
    detail::finish_heuristic(inst, st);
  } else {
    out.timed_out = true;
  }
  if (st.cover_cost < before) out.seconds_to_best = clock.seconds();
  out.subgradient_iterations = st.iterations;
  out.timed_out = out.timed_out || st.timed_out;
  out.hit_work_limit = out.hit_work_limit || st.hit_iteration_limit;
  const double t1 = clock.seconds();
  out.subgradient_seconds = t1 - now;
  if (detail::bound_closes_gap(inst, st.bound, st.cover_cost)) {
    out.proven = true;
  } else if (inst.num_cols() <= kExactColumns || clock.seconds() < budget.deadline) {
    improve_by_local_search(inst, st, budget, clock, out);
  } else {
    out.timed_out = true;
  }
  out.local_search_seconds = clock.seconds() - t1;
  out.cover = st.cover;
  out.cost = st.cover_cost;
  out.u = st.u;
  return out;
}

/// Fills the certificate (rounded multipliers, exact claims) and the certified figures.
void attach_certificate(const Instance& inst, const std::vector<double>& u, Solution& sol) {
  Certificate& cert = sol.certificate;
  cert.num_rows = inst.num_rows();
  cert.num_cols = inst.num_cols();
  cert.unicost = inst.is_unicost();
  cert.cover = sol.columns;
  cert.multipliers = to_fixed_point(u, cert.scale);
  sol.lower_bound = certified_lower_bound(inst, cert);
  double claim = sol.lower_bound;
  if (!cert.unicost && !inst.has_integer_costs()) {
    // Costs read from decimal text are within 2^-53 relative of their doubles, which moves L
    // by at most 2^-53 Σ c_j: claim that much less so the verifier's exact reading agrees.
    double total = 0.0;
    for (double c : inst.costs()) total += c;
    claim = std::nextafter(claim - std::ldexp(total, -50), -INFINITY);
  }
  cert.bound_claim = exact_rational_text(claim);
  cert.cost_claim = exact_cost_text(inst, sol.columns, cert.unicost);
  sol.gap = sol.cost > 0 ? (sol.cost - sol.lower_bound) / sol.cost : 0.0;
  sol.optimal = sol.lower_bound >= sol.cost;
}

/// Local-search iterations of component k: the shares of `total` in proportion to the
/// components' weights, as differences of rounded-down cumulative shares, so that they add
/// up to `total` exactly (and never exceed it).
std::int64_t local_search_share(std::int64_t total, std::int64_t weight_before,
                                std::int64_t weight_through, std::int64_t weight_all) {
  const auto upto = [&](std::int64_t w) {
    return static_cast<std::int64_t>(std::floor(
        static_cast<double>(total) * (static_cast<double>(w) / static_cast<double>(weight_all))));
  };
  return upto(weight_through) - upto(weight_before);
}

/// Entries the domination passes may scan (0: no limit): the smaller of the per-entry and
/// the absolute limit of `options`, each 0 when off.
std::int64_t domination_work_limit(const SolverOptions& options, std::int64_t entries) {
  std::int64_t limit = options.max_domination_work;
  if (options.domination_work_per_entry > 0) {
    const double per_entry = std::min(
        options.domination_work_per_entry * static_cast<double>(std::max<std::int64_t>(entries, 1)),
        9.0e18);
    const auto scaled = std::max<std::int64_t>(static_cast<std::int64_t>(per_entry), 1);
    limit = limit > 0 ? std::min(limit, scaled) : scaled;
  }
  return limit;
}

}  // namespace

const char* to_string(SearchLimit limit) {
  switch (limit) {
    case SearchLimit::kNone:
      return "none";
    case SearchLimit::kIterations:
      return "iterations";
    case SearchLimit::kTime:
      return "time";
  }
  return "?";
}

Solution solve(const Instance& inst, const SolverOptions& options) {
  Stopwatch clock;
  if (const std::int32_t row = inst.first_uncoverable_row(); row >= 0) {
    throw ComputationFailed("set cover: row " + std::to_string(row) +
                            " (0-based) is covered by no column; no cover exists");
  }
  Solution sol;
  const detail::Reduction red =
      detail::reduce(inst, options.use_domination, 0.5 * options.time_limit, clock,
                     domination_work_limit(options, inst.num_entries()),
                     inst.num_entries() >= kParallelReductionEntries ? options.threads : 1);
  sol.stats.reduction_work = red.work;
  sol.stats.forced_columns = red.forced_cols;
  sol.stats.dominated_rows = red.dominated_rows;
  sol.stats.dominated_columns = red.dominated_cols;
  sol.stats.components = static_cast<std::int64_t>(red.components.size());
  sol.stats.reduction_seconds = clock.seconds();
  std::vector<double> u(static_cast<std::size_t>(inst.num_rows()), 0.0);
  for (const auto& [row, value] : red.forced_multipliers) u[row] = value;
  std::vector<std::int32_t> cover = red.fixed_cols;
  double greedy_cost = inst.cost_of(red.fixed_cols);
  bool all_proven = true;
  bool timed_out = red.timed_out;
  bool hit_work_limit = red.work_limited;
  std::int64_t remaining_nnz = 0;
  for (const Component& c : red.components) remaining_nnz += c.instance.num_entries() + 1;
  const std::int64_t total_nnz = remaining_nnz;
  for (std::size_t k = 0; k < red.components.size(); ++k) {
    const Component& c = red.components[k];
    const std::int64_t weight = c.instance.num_entries() + 1;
    const double share = static_cast<double>(weight) / static_cast<double>(remaining_nnz);
    const std::int64_t nnz_before = total_nnz - remaining_nnz;
    remaining_nnz -= weight;
    Budget budget;
    const double now = clock.seconds();
    budget.deadline = now + share * std::max(0.0, options.time_limit - now);
    budget.seed = options.seed * 0x9E3779B97F4A7C15ULL + k;
    budget.streams = options.local_search_streams;
    // All of them for the pricing passes; the local search uses at most one per stream.
    budget.threads = thread_count(options.threads, std::numeric_limits<std::size_t>::max());
    budget.subgradient_iterations = options.max_subgradient_iterations;
    if (options.max_local_search_iterations > 0) {
      budget.local_search_iterations =
          local_search_share(options.max_local_search_iterations, nnz_before, nnz_before + weight,
                             total_nnz);
    }
    const ComponentResult r = solve_component(c.instance, budget, clock);
    for (std::int32_t j : r.cover) cover.push_back(c.cols[j]);
    for (std::size_t i = 0; i < c.rows.size(); ++i) u[c.rows[i]] = r.u[i];
    greedy_cost += r.greedy_cost;
    sol.stats.seconds_to_best = std::max(sol.stats.seconds_to_best, r.seconds_to_best);
    sol.stats.subgradient_iterations += r.subgradient_iterations;
    sol.stats.local_search_iterations += r.local_search_iterations;
    sol.stats.greedy_seconds += r.greedy_seconds;
    sol.stats.subgradient_seconds += r.subgradient_seconds;
    sol.stats.local_search_seconds += r.local_search_seconds;
    sol.stats.exact_nodes += r.exact_nodes;
    all_proven = all_proven && r.proven;
    timed_out = timed_out || r.timed_out;
    hit_work_limit = hit_work_limit || r.hit_work_limit;
  }
  sol.stats.stopped_by = timed_out        ? SearchLimit::kTime
                         : hit_work_limit ? SearchLimit::kIterations
                                          : SearchLimit::kNone;
  std::sort(cover.begin(), cover.end());
  RSTRUCT_ASSERT_MSG(inst.is_cover(cover), "set cover: solver produced a non-cover");
  sol.columns = cover;
  sol.cost = inst.cost_of(cover);
  sol.stats.greedy_cost = greedy_cost;
  const double t_cert = clock.seconds();
  attach_certificate(inst, u, sol);
  sol.proven_optimal = sol.optimal || all_proven;
  sol.stats.certificate_seconds = clock.seconds() - t_cert;
  sol.stats.seconds = clock.seconds();
  return sol;
}

}  // namespace rstruct::setcover
