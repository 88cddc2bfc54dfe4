#include "rstruct/sampling/ellipse_projection.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace rstruct::sampling {

namespace {

/// Root of a strictly decreasing convex function on [lo, hi] with f(lo) ≥ 0 ≥ f(hi).
/// Newton's method from lo: by convexity each iterate stays at or below the root, so the
/// sequence increases monotonically; it stops when an iterate no longer increases (full
/// precision) or, as a safeguard against rounding, leaves the bracket, in which case
/// bisection finishes the job.
template <typename F, typename DF>
double solve_convex_decreasing(F f, DF df, double lo, double hi) {
  double s = lo;
  for (int i = 0; i < 200; ++i) {
    const double value = f(s);
    if (value <= 0.0) return s;
    const double slope = df(s);
    if (!(slope < 0.0)) break;
    const double next = s - value / slope;
    if (!(next > s) || next > hi) break;
    s = next;
  }
  lo = s;
  for (int i = 0; i < 2200 && lo < hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    (f(mid) > 0.0 ? lo : hi) = mid;
  }
  return f(hi) == 0.0 ? hi : lo;
}

/// Closest point on the n-dimensional ellipsoid with sorted axes e[0] ≥ … ≥ e[n−1] > 0 to
/// y with y[i] ≥ 0 (see the header for the method). Writes x[0..n).
void closest_sorted(const double* e, const double* y, double* x, int n) {
  if (n == 1) {
    x[0] = e[0];
    return;
  }
  const int last = n - 1;
  const double el2 = e[last] * e[last];
  std::array<double, 3> shift{};  // e_i² − e_last², ≥ 0
  for (int i = 0; i < n; ++i) shift[static_cast<std::size_t>(i)] = e[i] * e[i] - el2;
  // Among axes equal to the smallest, put any positive component last (symmetry).
  if (y[last] == 0.0) {
    for (int i = 0; i < last; ++i) {
      if (shift[static_cast<std::size_t>(i)] == 0.0 && y[i] > 0.0) {
        std::array<double, 3> yy{}, xx{};
        std::copy(y, y + n, yy.begin());
        std::swap(yy[static_cast<std::size_t>(i)], yy[static_cast<std::size_t>(last)]);
        closest_sorted(e, yy.data(), xx.data(), n);
        std::swap(xx[static_cast<std::size_t>(i)], xx[static_cast<std::size_t>(last)]);
        std::copy(xx.begin(), xx.begin() + n, x);
        return;
      }
    }
  }
  if (y[last] > 0.0) {
    auto F = [&](double s) {
      double sum = -1.0;
      for (int i = 0; i < n; ++i) {
        const double t = e[i] * y[i] / (s + shift[static_cast<std::size_t>(i)]);
        sum += t * t;
      }
      return sum;
    };
    auto dF = [&](double s) {
      double sum = 0.0;
      for (int i = 0; i < n; ++i) {
        const double den = s + shift[static_cast<std::size_t>(i)];
        const double t = e[i] * y[i] / den;
        sum -= 2.0 * t * t / den;
      }
      return sum;
    };
    double hi = 0.0;
    for (int i = 0; i < n; ++i) hi = std::hypot(hi, e[i] * y[i]);
    const double s = solve_convex_decreasing(F, dF, e[last] * y[last], hi);
    for (int i = 0; i < n; ++i) {
      x[i] = e[i] * e[i] * y[i] / (s + shift[static_cast<std::size_t>(i)]);
    }
    return;
  }
  // y[last] == 0 and every component along an axis equal to e[last] is 0.
  double sum = 0.0;
  for (int i = 0; i < last; ++i) {
    if (shift[static_cast<std::size_t>(i)] > 0.0) {
      const double t = e[i] * y[i] / shift[static_cast<std::size_t>(i)];
      sum += t * t;
    }
  }
  if (sum < 1.0) {
    // Query inside the focal region: the closest point leaves the hyperplane x_last = 0.
    double rest = 1.0;
    for (int i = 0; i < last; ++i) {
      const double si = shift[static_cast<std::size_t>(i)];
      x[i] = si > 0.0 ? e[i] * e[i] * y[i] / si : 0.0;
      rest -= (x[i] / e[i]) * (x[i] / e[i]);
    }
    x[last] = e[last] * std::sqrt(std::max(0.0, rest));
    return;
  }
  closest_sorted(e, y, x, last);
  x[last] = 0.0;
}

}  // namespace

std::array<double, 3> closest_point_on_ellipsoid(const std::array<double, 3>& axes,
                                                 const std::array<double, 3>& y) {
  std::array<int, 3> order{0, 1, 2};
  std::stable_sort(order.begin(), order.end(), [&](int i, int j) {
    return axes[static_cast<std::size_t>(i)] > axes[static_cast<std::size_t>(j)];
  });
  std::array<double, 3> e{}, ya{}, x{};
  for (std::size_t k = 0; k < 3; ++k) {
    const auto i = static_cast<std::size_t>(order[k]);
    e[k] = axes[i];
    ya[k] = std::fabs(y[i]);
  }
  closest_sorted(e.data(), ya.data(), x.data(), 3);
  std::array<double, 3> result{};
  for (std::size_t k = 0; k < 3; ++k) {
    const auto i = static_cast<std::size_t>(order[k]);
    result[i] = std::copysign(x[k], y[i]);
  }
  return result;
}

std::array<double, 2> closest_point_on_filled_ellipse(double alpha, double beta, double p,
                                                      double q) {
  const double ap = std::fabs(p);
  const double aq = std::fabs(q);
  if (alpha == 0.0) return {0.0, 0.0};
  if (beta == 0.0) return {std::copysign(std::min(ap, alpha), p), 0.0};
  const double tp = ap / alpha;
  const double tq = aq / beta;
  if (tp * tp + tq * tq <= 1.0) return {p, q};
  const double a2 = alpha * alpha;
  const double b2 = beta * beta;
  // Outside: x = (α² p / (s + α²), β² q / (s + β²)) with s > 0 the root of the strictly
  // decreasing G(s) = (α p / (s + α²))² + (β q / (s + β²))² − 1; G(0) > 0 here and
  // G(|(αp, βq)|) ≤ 0.
  auto G = [&](double s) {
    const double u = alpha * ap / (s + a2);
    const double w = beta * aq / (s + b2);
    return u * u + w * w - 1.0;
  };
  auto dG = [&](double s) {
    const double u = alpha * ap / (s + a2);
    const double w = beta * aq / (s + b2);
    return -2.0 * (u * u / (s + a2) + w * w / (s + b2));
  };
  const double s = solve_convex_decreasing(G, dG, 0.0, std::hypot(alpha * ap, beta * aq));
  return {std::copysign(a2 * ap / (s + a2), p), std::copysign(b2 * aq / (s + b2), q)};
}

}  // namespace rstruct::sampling
