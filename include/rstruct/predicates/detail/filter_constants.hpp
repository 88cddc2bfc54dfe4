#pragma once
/// \file
/// Every error constant of the predicates' floating-point filters, in one place.
/// Each constant is re-derived and checked by proofs/filter_bounds.cpp (run it with
/// `meson test --suite proofs`), which instantiates the very templates of
/// polynomials.hpp with an outward-rounded error-tracking number type (MPFI).
///
/// Error model (IEEE binary64, round to nearest, -ffp-contract=off): fl(x ± y) =
/// (x ± y)(1 + δ), fl(x · y) = xy(1 + δ) + η with |δ| ≤ u = 2⁻⁵³ and |η| ≤ 2⁻¹⁰⁷⁵ (η ≠ 0
/// only on underflow; sums that underflow are exact). The leaves are the computed
/// differences t̃ = fl(p − q) of inputs (|t − t̃| ≤ u|t|), normalised by the largest
/// computed |t̃| of their column (m_x, m_y, m_z; m_w for weight differences).
///
/// Semi-static filter: with D̃ the computed value and D the exact one, |D̃ − D| ≤ K · S
/// where S is the product of column maxima named beside each constant, computed in
/// floating point as written in filters.hpp with `bound_roundings` roundings (each may
/// lose a factor 1 − u, which K absorbs). The filter decides only when |D̃| > K·S, D̃ is
/// finite and every column maximum is at least the guard's min_magnitude 2^-b. Below it
/// underflow could dominate: the proof adds, for each product of degree d, the share
/// 2⁻¹⁰⁷⁵·2^(b·d) of its absolute underflow error relative to the normalising product, and
/// the guard also keeps K·S a normal number. Overflow needs no guard: with no divisions,
/// an overflow anywhere leaves D̃ = ±inf or NaN (rejected), and an overflowing K·S = +inf
/// never decides.
///
/// The almost-static filters (almost_static_filter.hpp) reuse kOrient3d and kInsphere with
/// the extents of a box holding every input as the column maxima: any upper bounds of the
/// computed column magnitudes satisfy the derivation (see proofs/filter_bounds.cpp).

namespace rstruct::predicates::detail::filter {

/// Guard of one filter: where its constant holds.
struct Guard {
  double min_magnitude;  ///< smallest allowed column maximum m_x, m_y, m_z (> 0)
};

/// 2^k as a constant expression.
constexpr double pow2(int k) {
  double r = 1;
  for (; k > 0; --k) r *= 2;
  for (; k < 0; ++k) r /= 2;
  return r;
}

/// Degree ≤ 3 predicates (orient3d, orient2d): column maxima ≥ 2^-300.
inline constexpr Guard kGuardDegree3{pow2(-300)};
/// Degree 4 and 5 predicates (in-sphere, power tests): column maxima ≥ 2^-180.
inline constexpr Guard kGuardDegree5{pow2(-180)};
/// Degree 2 predicates (distance and power comparisons): maxima ≥ 2^-400.
inline constexpr Guard kGuardDegree2{pow2(-400)};

/// orient3d: S = m_x·m_y·m_z, 3 roundings in the bound.
inline constexpr double kOrient3d = 5.1071e-15;
/// orient2d in a coordinate plane: S = m_u·m_v, 2 roundings.
inline constexpr double kOrient2d = 8.8818e-16;
/// insphere: S = m_x·m_y·m_z·M², M = max(m_x, m_y, m_z), 5 roundings.
inline constexpr double kInsphere = 1.3057e-13;
/// power_test: S = m_x·m_y·m_z·max(M², m_w), 5 roundings.
inline constexpr double kPowerTest = 1.6432e-13;
/// coplanar power test (projected lifted 3×3): S = m_u·m_v·max(M², m_w), 4 roundings.
inline constexpr double kCoplanarPower = 3.0421e-14;
/// collinear power test (projected lifted 2×2): S = m_q·max(M², m_w), 3 roundings.
inline constexpr double kCollinearPower = 6.8834e-15;
/// compare_squared_distance: S = M², 2 roundings.
inline constexpr double kSquaredDistanceDifference = 3.7748e-15;
/// compare_power_distance: S = max(M², |w_p|, |w_q|), 2 roundings.
inline constexpr double kPowerDifference = 4.8850e-15;
/// power_sign: S = max(M², |w|), 2 roundings.
inline constexpr double kPowerValue = 1.9985e-15;
/// side_of_ball: S = max(M, |r|)², 2 roundings.
inline constexpr double kBallSide = 2.1095e-15;

/// Dynamic filters (dynamic_filter.hpp), tried after the semi-static one fails and before
/// the exact stage: |D̃ − D| ≤ K·P̃ where P̃ is the "permanent" of the same expression tree
/// (every leaf replaced by its absolute value, every subtraction by an addition) computed
/// in floating point. Per-term error analysis: every term of the expanded tree carries at
/// most n roundings (its leaves' differences included), so |D̃ − D| ≤ γ_n·P and
/// P̃ ≥ (1 − γ_n)·P with γ_n = nu/(1 − nu); K·(1 − u) ≥ γ_n/(1 − γ_n) then covers the
/// rounding of K·P̃ as well. proofs/filter_bounds.cpp counts n on the templates themselves
/// (17 for both tests: the in-sphere test's heights subtract a zero weight difference,
/// counted as a rounding too) and checks K, with the underflow margin the guard leaves.
inline constexpr double kInsphereDynamic = 18 * pow2(-53);
inline constexpr double kPowerTestDynamic = 18 * pow2(-53);
/// Guard of the dynamic filters: every computed coordinate difference at most 2^100 in
/// magnitude, every weight difference at most 2^200, and K·P̃ at least 2^-700 (normal, and
/// far above the at most 2^-766 that underflowing products can add to the error then).
struct DynamicGuard {
  double max_difference;
  double max_weight_difference;
  double min_bound;
};
inline constexpr DynamicGuard kGuardDynamic{pow2(100), pow2(200), pow2(-700)};

}  // namespace rstruct::predicates::detail::filter
