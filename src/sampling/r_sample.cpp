#include "rstruct/sampling/r_sample.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <unordered_map>
#include <vector>

#include "rstruct/core/error.hpp"
#include "rstruct/core/stopwatch.hpp"
#include "rstruct/sampling/random.hpp"
#include "sampling/point_index.hpp"

namespace rstruct::sampling {

namespace {

/// Relative allowance for the rounding of d, l and the bound's own arithmetic (each a few
/// ulps), and for lfs() being accurate to 1e-12 relative rather than exactly.
constexpr double kBoundSlack = 1e-12;

struct StackCell {
  ParamCell cell;
  int depth = 0;
};

void check_inputs(const Surface& surface, double r) {
  if (!surface.has_parametrization() || !surface.has_known_lfs()) {
    throw InvalidInput("r-sample of " + surface.name() +
                       ": needs a parametrized surface with known lfs (sphere, ellipsoid, "
                       "torus, or one of those moved rigidly)");
  }
  if (!std::isfinite(r) || r <= 0.0 || r > 1.0) {
    std::ostringstream msg;
    msg << "r-sample: r must be in (0, 1], got " << r;
    throw InvalidInput(msg.str());
  }
}

std::vector<StackCell> initial_cells(const Surface& surface, int per_side) {
  std::vector<StackCell> cells;
  for (int chart = 0; chart < surface.chart_count(); ++chart) {
    const ParamCell d = surface.chart_domain(chart);
    for (int i = 0; i < per_side; ++i) {
      for (int j = 0; j < per_side; ++j) {
        const double n = per_side;
        cells.push_back({{chart, d.u0 + (d.u1 - d.u0) * i / n, d.u0 + (d.u1 - d.u0) * (i + 1) / n,
                          d.v0 + (d.v1 - d.v0) * j / n, d.v0 + (d.v1 - d.v0) * (j + 1) / n},
                         0});
      }
    }
  }
  return cells;
}

/// Splits along the direction of larger reach and pushes both halves.
void split(const StackCell& c, const CellReach& reach, std::vector<StackCell>& stack) {
  ParamCell a = c.cell, b = c.cell;
  if (reach.u_reach >= reach.v_reach) {
    a.u1 = b.u0 = c.cell.u_mid();
  } else {
    a.v1 = b.v0 = c.cell.v_mid();
  }
  stack.push_back({a, c.depth + 1});
  stack.push_back({b, c.depth + 1});
}

/// A cell that could not be accepted because its centre g is too far from the samples.
struct Violation {
  StackCell cell;
  Point3 point;
  double ratio = 0;
  double lfs = 0;
};

/// One branch-and-bound pass over the cells of `stack` (see r_sample.hpp). Cells whose
/// centre ratio exceeds `fill` and that cannot be accepted at `threshold` are violations:
/// collected into `violations` if it is non-null, otherwise the pass stops at the first.
Certificate run_pass(const Surface& surface, const std::vector<Point3>& samples, double threshold,
                     double fill, const CertifyOptions& options, std::vector<StackCell> stack,
                     std::vector<Violation>* violations) {
  Stopwatch clock;
  const PointIndex index(samples);
  Certificate cert;
  cert.threshold = threshold;
  cert.certified = true;
  cert.min_leaf_reach_over_lfs = HUGE_VAL;
  while (!stack.empty()) {
    const StackCell c = stack.back();
    stack.pop_back();
    const CellReach reach = surface.cell_reach(c.cell);
    const double rho = reach.radius();
    const Point3 g = surface.point(c.cell.chart, c.cell.u_mid(), c.cell.v_mid());
    const double l = surface.lfs(g);
    const double d = samples.empty() ? HUGE_VAL : index.nearest(g).second;
    const double ratio = d / l;
    ++cert.grid_points;
    cert.grid_max = std::max(cert.grid_max, ratio);
    if (rho < l) {
      const double bound = (d + rho) / (l - rho) * (1.0 + kBoundSlack);
      if (bound <= threshold) {
        cert.upper_bound = std::max(cert.upper_bound, bound);
        ++cert.leaf_cells;
        cert.max_leaf_reach_over_lfs = std::max(cert.max_leaf_reach_over_lfs, rho / l);
        cert.min_leaf_reach_over_lfs = std::min(cert.min_leaf_reach_over_lfs, rho / l);
        continue;
      }
    }
    if (ratio > fill || c.depth >= options.max_depth) {
      cert.certified = false;
      if (!cert.violation || ratio > cert.violation_ratio) {
        cert.violation = g;
        cert.violation_ratio = ratio;
      }
      if (ratio <= fill) cert.undecided = true;
      if (violations == nullptr) break;
      if (ratio > fill) violations->push_back({c, g, ratio, l});
      continue;
    }
    split(c, reach, stack);
  }
  if (cert.leaf_cells == 0) cert.min_leaf_reach_over_lfs = 0;
  if (!cert.certified) cert.upper_bound = HUGE_VAL;
  cert.seconds = clock.seconds();
  return cert;
}

[[noreturn]] void too_many_points(std::size_t limit) {
  std::ostringstream msg;
  msg << "r-sample: more than " << limit << " points would be needed; choose a larger r";
  throw InvalidInput(msg.str());
}

/// Visits the leaves of the subdivision into cells of radius ≤ target·lfs (centre lfs),
/// calling leaf(cell) for each; stops with InvalidInput after `limit` leaves.
template <typename Leaf>
void for_each_leaf(const Surface& surface, double target, const RSampleOptions& options,
                   std::size_t limit, Leaf leaf) {
  std::size_t leaves = 0;
  std::vector<StackCell> stack = initial_cells(surface, options.certify.initial_cells_per_side);
  while (!stack.empty()) {
    const StackCell c = stack.back();
    stack.pop_back();
    const CellReach reach = surface.cell_reach(c.cell);
    const Point3 g = surface.point(c.cell.chart, c.cell.u_mid(), c.cell.v_mid());
    if (reach.radius() <= target * surface.lfs(g) || c.depth >= options.certify.max_depth) {
      if (++leaves > limit) too_many_points(options.max_points);
      leaf(c.cell);
      continue;
    }
    split(c, reach, stack);
  }
}

/// One uniformly placed point (in parameters) per cell of radius ≤ target·lfs. A cheap
/// pass with cells four times larger first predicts the count (leaves scale like
/// 1/target², so ×16), so that hopeless requests fail fast rather than after building
/// max_points points.
std::vector<Point3> jittered_sample(const Surface& surface, double target,
                                    const RSampleOptions& options) {
  for_each_leaf(surface, 4.0 * target, options, options.max_points / 8, [](const ParamCell&) {});
  Random random(derive_seed(options.seed, 7));
  std::vector<Point3> points;
  for_each_leaf(surface, target, options, options.max_points, [&](const ParamCell& cell) {
    points.push_back(surface.point(cell.chart, random.uniform(cell.u0, cell.u1),
                                   random.uniform(cell.v0, cell.v1)));
  });
  return points;
}

/// Keeps violations (largest ratio first) at least half_gap·lfs apart, with a hash grid.
std::vector<Point3> thin(std::vector<Violation> v, double half_gap) {
  std::sort(v.begin(), v.end(),
            [](const Violation& a, const Violation& b) { return a.ratio > b.ratio; });
  double lmin = HUGE_VAL;
  for (const Violation& x : v) lmin = std::min(lmin, x.lfs);
  const double h = half_gap * lmin;
  // Cell coordinates wrap modulo 2⁶⁴ (unsigned arithmetic): collisions only cost time.
  auto cell_of = [h](double c) {
    return static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(c / h)));
  };
  auto key = [](std::uint64_t i, std::uint64_t j, std::uint64_t k) {
    return (i * 73856093ull) ^ (j * 19349663ull) ^ (k * 83492791ull);
  };
  std::unordered_multimap<std::uint64_t, Point3> grid;
  std::vector<Point3> kept;
  for (const Violation& x : v) {
    const double radius = half_gap * x.lfs;
    const auto span = static_cast<std::uint64_t>(std::ceil(radius / h));
    const std::uint64_t ci = cell_of(x.point.x), cj = cell_of(x.point.y), ck = cell_of(x.point.z);
    bool free = true;
    for (std::uint64_t i = ci - span; i != ci + span + 1 && free; ++i) {
      for (std::uint64_t j = cj - span; j != cj + span + 1 && free; ++j) {
        for (std::uint64_t k = ck - span; k != ck + span + 1 && free; ++k) {
          const auto range = grid.equal_range(key(i, j, k));
          for (auto it = range.first; it != range.second && free; ++it) {
            if (distance(it->second, x.point) < radius) free = false;
          }
        }
      }
    }
    if (!free) continue;
    kept.push_back(x.point);
    grid.emplace(key(ci, cj, ck), x.point);
  }
  return kept;
}

void check_options(const RSampleOptions& o) {
  if (!(o.fill_fraction > 0.0 && o.fill_fraction < 1.0) || !(o.spacing > 0.0 && o.spacing <= 4.0) ||
      o.max_rounds < 1 || o.certify.initial_cells_per_side < 1 || o.certify.max_depth < 1) {
    throw InvalidInput(
        "r-sample options: need 0 < fill_fraction < 1, 0 < spacing <= 4, max_rounds >= 1, "
        "initial_cells_per_side >= 1, max_depth >= 1");
  }
}

/// Adds points until every cell is accepted at threshold r. Adding points only lowers
/// dist(·, S), so cells accepted in one round stay accepted: each round revisits only the
/// previous round's violating cells.
void fill_until_certified(const Surface& surface, double r, double fill,
                          const RSampleOptions& options, RSample& result) {
  std::vector<StackCell> stack = initial_cells(surface, options.certify.initial_cells_per_side);
  while (!stack.empty()) {
    if (result.rounds == options.max_rounds) {
      throw ComputationFailed("r-sample: not certified after " +
                              std::to_string(options.max_rounds) + " rounds");
    }
    ++result.rounds;
    std::vector<Violation> violations;
    const Certificate pass =
        run_pass(surface, result.points, r, fill, options.certify, std::move(stack), &violations);
    if (pass.undecided) {
      throw ComputationFailed("r-sample: a cell could not be decided within " +
                              std::to_string(options.certify.max_depth) + " subdivisions");
    }
    stack.clear();
    for (const Violation& v : violations) stack.push_back(v.cell);
    const std::vector<Point3> added = thin(std::move(violations), 0.5 * fill);
    result.points.insert(result.points.end(), added.begin(), added.end());
    result.added_points += added.size();
  }
}

}  // namespace

Certificate certify_r_sample(const Surface& surface, const std::vector<Point3>& samples, double r,
                             const CertifyOptions& options) {
  check_inputs(surface, r);
  for (std::size_t i = 0; i < samples.size(); ++i) {
    if (!is_finite(samples[i])) {
      std::ostringstream msg;
      msg << "r-sample certification: sample " << i << " is not finite";
      throw InvalidInput(msg.str());
    }
  }
  return run_pass(surface, samples, r, r, options,
                  initial_cells(surface, options.initial_cells_per_side), nullptr);
}

RSample generate_r_sample(const Surface& surface, double r, const RSampleOptions& options) {
  check_inputs(surface, r);
  check_options(options);
  Stopwatch clock;
  const double fill = options.fill_fraction * r;
  RSample result;
  result.requested_r = r;
  result.points = jittered_sample(surface, options.spacing * fill, options);
  result.initial_points = result.points.size();
  fill_until_certified(surface, r, fill, options, result);
  result.generation_seconds = clock.seconds();
  clock.reset();
  // A fresh certification of the final sample (independent of the generation rounds),
  // then attempts at thresholds just above the achieved grid maximum.
  result.certificate = certify_r_sample(surface, result.points, r, options.certify);
  if (!result.certificate.certified) {
    throw InternalError("r-sample: the final certification failed after generation succeeded");
  }
  if (options.tighten) {
    // The true supremum is at least the largest ratio seen at any cell centre; a failed
    // attempt reveals a larger one, and the next attempt starts from it.
    double seen = result.certificate.grid_max;
    for (int attempt = 0; attempt < 4; ++attempt) {
      const double tau = seen * 1.05;
      if (tau >= result.certificate.upper_bound) break;
      Certificate tight = certify_r_sample(surface, result.points, tau, options.certify);
      seen = std::max({seen, tight.grid_max, tight.violation_ratio});
      if (tight.certified) {
        tight.grid_max = seen;
        result.certificate = tight;
        break;
      }
    }
    result.certificate.grid_max = std::max(result.certificate.grid_max, seen);
  }
  result.certification_seconds = clock.seconds();
  return result;
}

}  // namespace rstruct::sampling
