// Re-derives every error constant of the predicates' floating-point filters
// (include/rstruct/predicates/detail/filter_constants.hpp) and checks that the coded constant is at least
// the derived bound. Each claim prints its enclosure, the margin and HOLDS/FAILS; the
// program exits non-zero if one fails.
//
// Method: a priori forward error analysis carried out mechanically. The filters evaluate
// the templates of include/rstruct/predicates/detail/polynomials.hpp with T = double; here the same templates
// run with T = Tracked, a number that carries, in outward-rounded intervals (MPFI), an
// upper bound `mag` on the exact value's magnitude and `err` on the accumulated error,
// with every input column normalised to maximum 1 (filter_constants.hpp states the
// model). For x̃ = fl(ã ∘ b̃):
//   ±:  mag = m_a + m_b,      err = e_a + e_b + u·(m_a + e_a + m_b + e_b)
//   ×:  mag = m_a·m_b,        err = m_a e_b + m_b e_a + e_a e_b + u·(m_a+e_a)(m_b+e_b) + η·2^(b·deg)
// where the last term bounds, relative to the normalising product, the absolute error
// η = 2⁻¹⁰⁷⁵ of an underflowing product of degree deg when every column maximum is at
// least 2^-b (the filter guard). A leaf difference t̃ = fl(p − q) normalised by its column
// maximum has |t| ≤ 1/(1 − u) and |t̃ − t| ≤ u/(1 − u); an input used directly (a weight,
// a radius) has magnitude ≤ 1 and no error.
//
// Every monomial of each polynomial (and of its error bound, which follows the same
// tree) is a product of one factor per column of the normalising product S (e.g.
// m_x·m_y·m_z·m_j·m_k for insphere), so the bound at the actual maxima is at most the
// bound at all maxima 1 times S. The filter computes S·K in floating point with r
// roundings towards zero at worst, so the claim is K·(1 − u)^r ≥ err(1, ..., 1).
// Nothing uses that m is the *largest* magnitude of its column, only that it bounds every
// computed magnitude there and is at least the guard's 2^-b: the almost-static filters
// (include/rstruct/predicates/almost_static_filter.hpp) use the box extents
// W_i = fl(hi_i − lo_i) ≥ |fl(p_i − q_i)| (monotone rounding) with the same K, the same
// expression for K·S and the guard applied to W, so they need no constant of their own.
#include <boost/multiprecision/mpfi.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <functional>
#include <string>
#include <vector>

#include "rstruct/predicates/detail/filter_constants.hpp"
#include "rstruct/predicates/detail/polynomials.hpp"

namespace {

using Interval = boost::multiprecision::mpfi_float_100;
namespace pd = rstruct::predicates::detail;
namespace fc = rstruct::predicates::detail::filter;

Interval unit_roundoff() { return boost::multiprecision::ldexp(Interval(1), -53); }
Interval underflow_error() { return boost::multiprecision::ldexp(Interval(1), -1075); }

int g_guard_exponent = 0;  // b of the filter being derived: column maxima >= 2^-b

struct Tracked {
  Interval mag;
  Interval err;
  int deg = 0;
};

Tracked operator+(const Tracked& a, const Tracked& b) {
  if (a.deg != b.deg) throw std::logic_error("inhomogeneous sum");
  const Interval u = unit_roundoff();
  return {a.mag + b.mag, a.err + b.err + u * (a.mag + a.err + b.mag + b.err), a.deg};
}
Tracked operator-(const Tracked& a, const Tracked& b) { return a + b; }
Tracked operator*(const Tracked& a, const Tracked& b) {
  const Interval u = unit_roundoff();
  const int deg = a.deg + b.deg;
  const Interval underflow =
      underflow_error() * boost::multiprecision::ldexp(Interval(1), g_guard_exponent * deg);
  return {a.mag * b.mag,
          a.mag * b.err + b.mag * a.err + a.err * b.err +
              u * (a.mag + a.err) * (b.mag + b.err) + underflow,
          deg};
}

Tracked difference_leaf(int deg = 1) {
  const Interval u = unit_roundoff();
  return {1 / (1 - u), u / (1 - u), deg};
}
Tracked exact_leaf(int deg) { return {Interval(1), Interval(0), deg}; }

struct Claim {
  std::string name;
  double coded;
  int bound_roundings;
  double guard_min;
  std::function<Tracked()> evaluate;
};

int exponent_of(double power_of_two) {
  int e = 0;
  std::frexp(power_of_two, &e);
  return -(e - 1);
}

bool check(const Claim& c) {
  g_guard_exponent = exponent_of(c.guard_min);
  const Tracked t = c.evaluate();
  const Interval u = unit_roundoff();
  Interval shrink = 1;
  for (int i = 0; i < c.bound_roundings; ++i) shrink *= 1 - u;
  const Interval needed = t.err / shrink;  // K must be >= this
  const Interval margin = Interval(c.coded) / needed;
  const bool holds = lower(Interval(c.coded)) > upper(needed);
  std::printf("%-28s claim: coded K = %.17g >= err/(1-u)^%d\n", c.name.c_str(), c.coded,
              c.bound_roundings);
  std::printf("%-28s enclosure of err/(1-u)^r: [%.17g, %.17g] (= %.4f u)\n", "",
              static_cast<double>(lower(needed)), static_cast<double>(upper(needed)),
              static_cast<double>(upper(Interval(needed / u))));
  std::printf("%-28s margin K/bound >= %.6f  (guard 2^-%d)  %s\n", "",
              static_cast<double>(lower(margin)), g_guard_exponent, holds ? "HOLDS" : "FAILS");
  return holds;
}

Tracked orient3d_error() {
  const Tracked t = difference_leaf();
  return pd::det3(t, t, t, t, t, t, t, t, t);
}
Tracked orient2d_error() {
  const Tracked t = difference_leaf();
  return pd::minor2(t, t, t, t);
}
Tracked lifted4_error(bool weighted) {
  const Tracked t = difference_leaf();
  const Tracked w = weighted ? difference_leaf(2) : Tracked{Interval(0), Interval(0), 2};
  const Tracked l = pd::lifted_height(t, t, t, w);
  return pd::lifted_det4_negated(pd::LiftedRows<Tracked>{t, t, t, l, t, t, t, l, t, t, t, l,
                                                          t, t, t, l});
}
Tracked coplanar_error() {
  const Tracked t = difference_leaf();
  const Tracked l = pd::lifted_height(t, t, t, difference_leaf(2));
  return pd::lifted_det3(t, t, l, t, t, l, t, t, l);
}
Tracked collinear_error() {
  const Tracked t = difference_leaf();
  const Tracked l = pd::lifted_height(t, t, t, difference_leaf(2));
  return pd::lifted_det2(t, l, t, l);
}
Tracked squared_distance_error() {
  const Tracked t = difference_leaf();
  return pd::squared_distance_difference(t, t, t, t, t, t);
}
Tracked power_difference_error() {
  const Tracked t = difference_leaf();
  const Tracked w = exact_leaf(2);
  return pd::power_difference(t, t, t, w, t, t, t, w);
}
Tracked power_value_error() {
  const Tracked t = difference_leaf();
  return pd::power_value(t, t, t, exact_leaf(2));
}
Tracked ball_side_error() {
  const Tracked t = difference_leaf();
  return pd::ball_side_value(t, t, t, exact_leaf(1));
}

// Dynamic filters (include/rstruct/predicates/detail/dynamic_filter.hpp): |D̃ − D| ≤ K·P̃
// with P̃ the computed permanent of the same tree. Two mechanical passes over the same
// templates:
//  1. Roundings: the largest number n of roundings that any term of the expanded tree
//     carries, leaves' differences included (a leaf t̃ = fl(p − q) = t(1 + δ): 1; a sum
//     or difference: max(n_a, n_b) + 1; a product: n_a + n_b + 1). In the absence of
//     underflow the computed value is the sum of the terms, each times a product of at most
//     n factors (1 + δ): |D̃ − D| ≤ γ_n·P, and the permanent, evaluated on |t̃| by the same
//     tree, P̃ = Σ|term|·(1 + θ) ≥ (1 − γ_n)·P.
//  2. Underflow: a product that underflows adds η, |η| ≤ 2⁻¹⁰⁷⁵ (sums are then exact),
//     which later operations scale. Under the guard (|t̃| ≤ 2^100, |w̃| ≤ 2^200) each node
//     carries a bound M on its computed magnitude and E on the part of its value that
//     comes from some η: for ±, M = (M_a + M_b)(1 + u), E = (E_a + E_b)(1 + u); for ×,
//     M = M_a·M_b·(1 + u) + η, E = ((M_a + E_a)·E_b + E_a·(M_b + E_b) + E_a·E_b)(1 + u) + η.
//     The same E bounds the permanent's share, as the permanent runs the same tree on
//     magnitudes with the same bounds.
// The filter decides when |D̃| > B = fl(K·P̃) and B ≥ 2^-700, so K·P̃ ≥ 2^-700/(1 + u), and
// B ≥ K·P̃·(1 − u). It is right if B ≥ γ_n·P + E, which holds when
//   (K(1 − u) − γ_n/(1 − γ_n))·P̃ ≥ γ_n·E/(1 − γ_n) + E   for P̃ = 2^-700/(K(1 + u)),
// the left side growing with P̃. The root's M must also stay finite (no overflow).
struct Roundings {
  int n = 0;
};
Roundings operator+(const Roundings& a, const Roundings& b) { return {std::max(a.n, b.n) + 1}; }
Roundings operator-(const Roundings& a, const Roundings& b) { return a + b; }
Roundings operator*(const Roundings& a, const Roundings& b) { return {a.n + b.n + 1}; }

struct Underflow {
  Interval m;
  Interval e;
};
Underflow operator+(const Underflow& a, const Underflow& b) {
  const Interval grow = 1 + unit_roundoff();
  return {(a.m + b.m) * grow, (a.e + b.e) * grow};
}
Underflow operator-(const Underflow& a, const Underflow& b) { return a + b; }
Underflow operator*(const Underflow& a, const Underflow& b) {
  const Interval grow = 1 + unit_roundoff();
  return {a.m * b.m * grow + underflow_error(),
          ((a.m + a.e) * b.e + a.e * (b.m + b.e) + a.e * b.e) * grow + underflow_error()};
}

template <class T>
T lifted4_tree(const T& t, const T& w) {
  const T l = pd::lifted_height(t, t, t, w);
  return pd::lifted_det4_negated(pd::LiftedRows<T>{t, t, t, l, t, t, t, l, t, t, t, l, t, t, t, l});
}

bool check_dynamic(const char* name, double coded, bool weighted) {
  const fc::DynamicGuard& g = fc::kGuardDynamic;
  // Unweighted, the height subtracts the weight difference 0 all the same: counted as a
  // rounding (it is exact, so this only overestimates).
  const int n = lifted4_tree(Roundings{1}, Roundings{weighted ? 1 : 0}).n;
  const Underflow leaf{Interval(g.max_difference), Interval(0)};
  const Underflow weight{Interval(weighted ? g.max_weight_difference : 0.0), Interval(0)};
  const Underflow root = lifted4_tree(leaf, weight);
  const Interval u = unit_roundoff();
  const Interval gamma = n * u / (1 - n * u);
  const Interval k(coded);
  const Interval slope = k * (1 - u) - gamma / (1 - gamma);
  const Interval smallest_permanent = Interval(g.min_bound) / (k * (1 + u));
  const Interval left = slope * smallest_permanent;
  const Interval right = gamma * root.e / (1 - gamma) + root.e;
  const bool no_overflow = upper(root.m) < 0x1p1000;
  const bool holds = lower(slope) > 0 && lower(left) > upper(right) && no_overflow;
  std::printf("%-28s claim: K(1-u) - g_n/(1-g_n) > 0 with n = %d roundings per term, and the\n",
              name, n);
  std::printf("%-28s slack at the guard's smallest permanent exceeds the underflow share\n", "");
  std::printf("%-28s K = %.17g = %.4f u, needed %.4f u; slack [%.6g, %.6g] vs underflow <= %.6g;"
              " |D| <= %.3g  %s\n",
              "", coded, static_cast<double>(lower(Interval(k / u))),
              static_cast<double>(upper(Interval(gamma / (1 - gamma) / (1 - u) / u))),
              static_cast<double>(lower(left)), static_cast<double>(upper(left)),
              static_cast<double>(upper(right)), static_cast<double>(upper(root.m)),
              holds ? "HOLDS" : "FAILS");
  return holds;
}

}  // namespace

int main() {
  const double g3 = fc::kGuardDegree3.min_magnitude;
  const double g5 = fc::kGuardDegree5.min_magnitude;
  const double g2 = fc::kGuardDegree2.min_magnitude;
  const std::vector<Claim> claims = {
      {"orient3d", fc::kOrient3d, 3, g3, orient3d_error},
      {"orient2d", fc::kOrient2d, 2, g3, orient2d_error},
      {"insphere", fc::kInsphere, 5, g5, [] { return lifted4_error(false); }},
      {"power_test", fc::kPowerTest, 5, g5, [] { return lifted4_error(true); }},
      {"coplanar_power_test", fc::kCoplanarPower, 4, g5, coplanar_error},
      {"collinear_power_test", fc::kCollinearPower, 3, g5, collinear_error},
      {"compare_squared_distance", fc::kSquaredDistanceDifference, 2, g2,
       squared_distance_error},
      {"compare_power_distance", fc::kPowerDifference, 2, g2, power_difference_error},
      {"power_sign", fc::kPowerValue, 2, g2, power_value_error},
      {"side_of_ball", fc::kBallSide, 2, g2, ball_side_error},
  };
  int failed = 0;
  for (const Claim& c : claims) failed += check(c) ? 0 : 1;
  failed += check_dynamic("insphere (dynamic)", fc::kInsphereDynamic, false) ? 0 : 1;
  failed += check_dynamic("power_test (dynamic)", fc::kPowerTestDynamic, true) ? 0 : 1;
  std::printf("%zu claims, %d failed\n", claims.size() + 2, failed);
  return failed == 0 ? 0 : 1;
}
