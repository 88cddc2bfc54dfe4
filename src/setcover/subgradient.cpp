#include "subgradient.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#include "greedy.hpp"
#include "rstruct/core/parallel.hpp"

namespace rstruct::setcover::detail {

namespace {

/// Instances with more entries than this run the subgradient on a core (CFT §3).
constexpr std::int64_t kCoreThreshold = 200'000;
constexpr std::size_t kCorePerRow = 5;
constexpr std::int32_t kPriceEvery = 10;
constexpr std::int32_t kStepWindow = 20;
/// Below this many entries the O(entries) passes stay on one thread.
constexpr std::int64_t kParallelEntries = 1'000'000;
constexpr std::size_t kRowChunk = 1 << 13;
constexpr std::size_t kColumnChunk = 1 << 13;

/// CFT's core: for every row its kCorePerRow columns of smallest reduced cost, plus every
/// column with reduced cost below a small threshold, plus the incumbent cover.
std::vector<std::int32_t> build_core(const Instance& inst, const std::vector<double>& reduced,
                                     std::span<const std::int32_t> cover, double threshold,
                                     unsigned threads) {
  std::vector<char> in(static_cast<std::size_t>(inst.num_cols()), 0);
  // Rows in parallel: the mask is a union, the same whatever the chunks.
  parallel_chunks(static_cast<std::size_t>(inst.num_rows()), threads, kRowChunk,
                  [&](std::size_t begin, std::size_t end, unsigned /*worker*/) {
    std::vector<std::pair<double, std::int32_t>> tmp;
    for (auto i = static_cast<std::int32_t>(begin); i < static_cast<std::int32_t>(end); ++i) {
      tmp.clear();
      for (std::int32_t j : inst.row(i)) tmp.emplace_back(reduced[j], j);
      const std::size_t k = std::min(kCorePerRow, tmp.size());
      std::partial_sort(tmp.begin(), tmp.begin() + static_cast<std::ptrdiff_t>(k), tmp.end());
      for (std::size_t t = 0; t < k; ++t) {
        std::atomic_ref<char>(in[tmp[t].second]).store(1, std::memory_order_relaxed);
      }
    }
  });
  for (std::int32_t j = 0; j < inst.num_cols(); ++j) {
    if (reduced[j] < threshold) in[j] = 1;
  }
  for (std::int32_t j : cover) in[j] = 1;
  std::vector<std::int32_t> core;
  for (std::int32_t j = 0; j < inst.num_cols(); ++j) {
    if (in[j]) core.push_back(j);
  }
  return core;
}

/// L on the core columns at u, and the subgradient s_i = 1 − #{core j ∋ i : r_j < 0}.
double core_value_and_subgradient(const Instance& inst, const std::vector<std::int32_t>& core,
                                  const std::vector<double>& u, std::vector<double>& s) {
  double value = 0.0;
  for (double x : u) value += x;
  std::fill(s.begin(), s.end(), 1.0);
  for (std::int32_t j : core) {
    double r = inst.cost(j);
    for (std::int32_t i : inst.column(j)) r -= u[i];
    if (r < 0) {
      value += r;
      for (std::int32_t i : inst.column(j)) s[i] -= 1.0;
    }
  }
  return value;
}

/// CFT's step-size rule over windows of kStepWindow iterations: halve λ when L oscillates by
/// more than 1 %, grow it by 1.5 when L moves by less than 0.1 %. Added: a window that does
/// not beat the previous window's maximum is stalling (often a two-cycle), so λ halves; a
/// window whose last value is its maximum is steady progress, so λ may grow.
class StepControl {
 public:
  double update(double value, double lambda) {
    window_max_ = std::max(window_max_, value);
    window_min_ = std::min(window_min_, value);
    if (++count_ % kStepWindow != 0) return lambda;
    const double spread = (window_max_ - window_min_) / std::max(1e-12, std::abs(window_max_));
    if (spread > 0.01 || window_max_ <= previous_max_) lambda /= 2.0;
    else if (spread < 0.001 || value >= window_max_) lambda *= 1.5;
    previous_max_ = window_max_;
    window_max_ = -std::numeric_limits<double>::infinity();
    window_min_ = std::numeric_limits<double>::infinity();
    return lambda;
  }

 private:
  std::int32_t count_ = 0;
  double window_max_ = -std::numeric_limits<double>::infinity();
  double window_min_ = std::numeric_limits<double>::infinity();
  double previous_max_ = -std::numeric_limits<double>::infinity();
};

}  // namespace

double lagrangian_bound(const Instance& inst, std::span<const double> u,
                        std::vector<double>* reduced, unsigned threads) {
  double bound = 0.0;
  for (double x : u) bound += x;
  const auto n = static_cast<std::size_t>(inst.num_cols());
  if (threads == 1 || inst.num_entries() < kParallelEntries) {
    if (reduced) reduced->resize(n);
    for (std::int32_t j = 0; j < inst.num_cols(); ++j) {
      double r = inst.cost(j);
      for (std::int32_t i : inst.column(j)) r -= u[i];
      if (r < 0) bound += r;
      if (reduced) (*reduced)[j] = r;
    }
    return bound;
  }
  // The reduced costs in parallel, then the same sum in the same order: the same double.
  std::vector<double> local;
  std::vector<double>& r = reduced != nullptr ? *reduced : local;
  r.resize(n);
  parallel_chunks(n, threads, kColumnChunk, [&](std::size_t begin, std::size_t end, unsigned) {
    for (auto j = static_cast<std::int32_t>(begin); j < static_cast<std::int32_t>(end); ++j) {
      double x = inst.cost(j);
      for (std::int32_t i : inst.column(j)) x -= u[i];
      r[j] = x;
    }
  });
  for (const double x : r) {
    if (x < 0) bound += x;
  }
  return bound;
}

std::vector<double> initial_multipliers(const Instance& inst) {
  std::vector<double> u(static_cast<std::size_t>(inst.num_rows()),
                        std::numeric_limits<double>::infinity());
  for (std::int32_t j = 0; j < inst.num_cols(); ++j) {
    const auto rows = inst.column(j);
    if (rows.empty()) continue;
    const double v = inst.cost(j) / static_cast<double>(rows.size());
    for (std::int32_t i : rows) u[i] = std::min(u[i], v);
  }
  for (double& x : u) {
    if (!std::isfinite(x)) x = 0.0;
  }
  return u;
}

bool bound_closes_gap(const Instance& inst, double bound, double cost) {
  // The floating bound may be slightly off; this only decides when to stop searching.
  const double slack = 1e-9 * std::max(1.0, std::abs(cost));
  if (inst.has_integer_costs()) return std::ceil(bound - slack) >= cost;
  return bound >= cost - slack;
}

void coordinate_ascent(const Instance& inst, LagrangianState& state, std::int32_t sweeps,
                       double deadline, const Stopwatch& clock, unsigned threads) {
  std::vector<double> u = state.u;
  std::vector<double> reduced;
  lagrangian_bound(inst, u, &reduced, threads);
  std::vector<std::int32_t> order(static_cast<std::size_t>(inst.num_rows()));
  for (std::int32_t i = 0; i < inst.num_rows(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::int32_t a, std::int32_t b) {
    return inst.row(a).size() < inst.row(b).size();
  });
  for (std::int32_t sweep = 0; sweep < sweeps; ++sweep) {
    if (clock.seconds() > deadline) {
      state.timed_out = true;
      break;
    }
    for (std::int32_t i : order) {
      double m1 = std::numeric_limits<double>::infinity();
      for (std::int32_t j : inst.row(i)) m1 = std::min(m1, reduced[j] + u[i]);
      const double next = std::max(0.0, m1);
      const double delta = next - u[i];
      if (delta == 0.0) continue;
      for (std::int32_t j : inst.row(i)) reduced[j] -= delta;
      u[i] = next;
    }
    // Recompute from scratch: the incremental reduced costs drift by rounding.
    const double value = lagrangian_bound(inst, u, &reduced, threads);
    if (value > state.bound) {
      state.bound = value;
      state.u = u;
    } else {
      break;
    }
  }
}

void subgradient(const Instance& inst, LagrangianState& state, const SubgradientOptions& options,
                 const Stopwatch& clock) {
  const std::size_t m = static_cast<std::size_t>(inst.num_rows());
  const bool use_core = inst.num_entries() > kCoreThreshold;
  double min_cost = std::numeric_limits<double>::infinity();
  for (double c : inst.costs()) min_cost = std::min(min_cost, c);
  std::vector<double> reduced;
  std::vector<double> u = state.u;
  std::vector<std::int32_t> core;
  std::vector<char> core_mask;
  // Prices every column at u (a bound valid for the whole instance) and, unless this is
  // the last pricing, rebuilds the core from the reduced costs.
  auto price = [&](bool last) {
    const unsigned threads =
        state.pending && options.threads > 1 ? options.threads - 1 : options.threads;
    const double full = lagrangian_bound(inst, u, &reduced, threads);
    if (full > state.bound) {
      state.bound = full;
      state.u = u;
    }
    if (use_core && !last) {
      core = build_core(inst, reduced, state.cover, 0.0, options.threads);
      core_mask.assign(static_cast<std::size_t>(inst.num_cols()), 0);
      for (std::int32_t j : core) core_mask[j] = 1;
    }
  };
  if (!use_core) {
    core.resize(static_cast<std::size_t>(inst.num_cols()));
    for (std::int32_t j = 0; j < inst.num_cols(); ++j) core[j] = j;
  }
  price(false);
  double lambda = 0.1;
  StepControl control;
  std::vector<double> s(m);
  const std::int32_t heuristic_every = std::max(10, options.max_iterations / 25);
  double last_best = state.bound;
  std::int32_t stall = 0;
  std::int32_t it = 1;
  for (; it <= options.max_iterations; ++it) {
    ++state.iterations;
    if (bound_closes_gap(inst, state.bound, state.cover_cost)) break;
    if ((it & 7) == 0 && clock.seconds() > options.deadline) {
      state.timed_out = true;
      break;
    }
    const double value = core_value_and_subgradient(inst, core, u, s);
    if (!use_core && value > state.bound) {
      state.bound = value;
      state.u = u;
    }
    double norm = 0.0;
    for (std::size_t i = 0; i < m; ++i) {
      if (u[i] <= 0.0 && s[i] < 0.0) s[i] = 0.0;  // projected subgradient
      norm += s[i] * s[i];
    }
    if (norm == 0.0) break;  // the Lagrangian solution is an optimal cover of the core
    lambda = control.update(value, lambda);
    const double target_gap = std::max(state.cover_cost - value, 1e-3 * std::max(1.0, state.cover_cost));
    const double step = lambda * target_gap / norm;
    for (std::size_t i = 0; i < m; ++i) u[i] = std::max(0.0, u[i] + step * s[i]);
    if (use_core && it % kPriceEvery == 0) price(false);
    if (options.run_heuristics && it % heuristic_every == 0) {
      ++state.heuristic_calls;
      if (it == options.max_iterations && options.threads != 1 &&
          inst.num_entries() >= kParallelEntries) {
        // Nothing after this iteration reads the cover until the caller is done with the
        // multipliers: the greedy runs beside them, on copies of u and of the core.
        auto job = std::make_unique<PendingHeuristic>();
        PendingHeuristic& h = *job;
        h.thread = std::jthread([&inst, &h, u_copy = u,
                                 mask = use_core ? core_mask : std::vector<char>{}] {
          try {
            h.cover = greedy_cover(inst, u_copy, mask);
          } catch (...) {
            h.error = std::current_exception();
          }
        });
        state.pending = std::move(job);
      } else {
        auto cover = greedy_cover(inst, u, use_core ? std::span<const char>(core_mask) : std::span<const char>{});
        const double cost = inst.cost_of(cover);
        if (cost < state.cover_cost) {
          state.cover = std::move(cover);
          state.cover_cost = cost;
        }
      }
    }
    if (it % 100 == 0) {
      stall = state.bound > last_best + 1e-4 * std::max(1.0, std::abs(last_best)) ? 0 : stall + 1;
      last_best = state.bound;
      if (stall >= 30 || lambda < 1e-6) break;
    }
  }
  if (it > options.max_iterations) state.hit_iteration_limit = true;
  if (use_core) price(true);
}

void finish_heuristic(const Instance& inst, LagrangianState& state) {
  if (!state.pending) return;
  state.pending->thread.join();
  const std::unique_ptr<PendingHeuristic> h = std::move(state.pending);
  if (h->error) std::rethrow_exception(h->error);
  const double cost = inst.cost_of(h->cover);
  if (cost < state.cover_cost) {
    state.cover = std::move(h->cover);
    state.cover_cost = cost;
  }
}

}  // namespace rstruct::setcover::detail
