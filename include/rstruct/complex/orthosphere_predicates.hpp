#pragma once
/// \file
/// Exact predicates on the smallest orthogonal sphere of a simplex of weighted points, the
/// two decisions of the dual complex (weighted α-shape at α = 0; Edelsbrunner, "The union
/// of balls and its dual shape", DCG 13 (1995); DESIGN.md §4).
///
/// For affinely independent weighted points σ = {(c₀, w₀), …, (c_k, w_k)}, k ≤ 3, let z_σ
/// be the point of aff(c₀, …, c_k) with equal power π_i(z) = |z − c_i|² − w_i to all of
/// them (the centre of the smallest sphere orthogonal to all of them). Writing
/// u_i = c_i − c₀, b_i = |u_i|² − w_i + w₀ (i = 1..k), G the Gram matrix of the u_i and
/// D = det G > 0:
///   π_σ(z_σ)            = (bᵀ adj(G) b − 4 D w₀) / (4 D),
///   π_p(z_σ) − π_σ(z_σ) = (D b_p − g_pᵀ adj(G) b) / D,  g_p = (⟨u_i, c_p − c₀⟩)_i,
///                         b_p = |c_p − c₀|² − w_p + w₀.
/// Both signs are decided exactly: floating-point evaluations with a certified error bound
/// first (a cheap one whose underflow guard is a test on the leaves, then one that tracks
/// underflow per operation; src/complex/rounded_leaf_number.hpp, filtered_number.hpp),
/// then exact rational (GMP) evaluation of the same polynomial. No perturbation:
/// the dual complex at α = 0 is a well-defined geometric object, ties included.
///
/// These live in the complex module because the shared filtered/exact facility of
/// `numeric/` had not landed when they were written.

#include <cstdint>
#include <span>

#include "rstruct/geometry/vec3.hpp"
#include "rstruct/predicates/sign.hpp"

namespace rstruct::complex {

/// Sign of π_σ(z_σ), the power of the smallest orthosphere's centre (minus its squared
/// radius): negative or zero iff that orthosphere has a real, non-negative radius.
/// For k = 0 it is the sign of −w₀.
/// \pre 1 ≤ sigma.size() ≤ 4, points affinely independent.
/// \throws InvalidInput if the points are affinely dependent (D = 0).
Sign orthosphere_power_sign(std::span<const WeightedPoint> sigma);

/// Sign of π_p(z_σ) − π_σ(z_σ): negative iff p is *closer in power* to z_σ than σ's
/// points, i.e. z_σ lies outside the half-space of σ's dual face towards p (p "attaches"
/// σ when σ ∪ {p} is a simplex of the regular triangulation).
/// \pre 1 ≤ sigma.size() ≤ 3, points affinely independent.
/// \throws InvalidInput if the points of sigma are affinely dependent.
Sign orthosphere_attachment_sign(std::span<const WeightedPoint> sigma, const WeightedPoint& p);

/// The lower-simplex rule of the dual complex when no coface of σ is in K: true iff
/// orthosphere_power_sign(sigma) is not positive and orthosphere_attachment_sign(sigma, p)
/// is not negative for every p in `opposite` (σ unattached, its orthocentre in the union).
/// The same decisions as those calls, sharing one filtered evaluation of σ's system;
/// every sign the filter cannot certify goes to the exact stage.
/// \pre 1 ≤ sigma.size() ≤ 3, points affinely independent.
/// \throws InvalidInput if the points of sigma are affinely dependent.
bool orthosphere_is_unattached_in_union(std::span<const WeightedPoint> sigma,
                                        std::span<const WeightedPoint> opposite);

/// π_σ(z_σ) itself, a floating-point construction (for the α filtration,
/// alpha_filtration.hpp): its sign is the exact sign of orthosphere_power_sign (0 exactly
/// when the exact value is 0), and where the exact value's magnitude lies in
/// [2⁻¹⁰⁰⁰, 2¹⁰²⁴) the result is within a relative 2⁻²⁸ of it. The filtered evaluation of
/// numerator and denominator is used when its certified error bound is within 2⁻³⁰ of
/// each, else the exact value from integer arithmetic, truncated to a double (a non-zero
/// value too small for a double becomes the smallest double of its sign; one too large,
/// ±infinity). For k = 0 it is −w₀.
/// \pre 1 ≤ sigma.size() ≤ 4, points affinely independent.
/// \throws InvalidInput if the points are affinely dependent.
double orthosphere_power_value(std::span<const WeightedPoint> sigma);

/// The same signs from exact rational arithmetic only (no filter): the oracle of the
/// filter tests.
Sign orthosphere_power_sign_exact(std::span<const WeightedPoint> sigma);
Sign orthosphere_attachment_sign_exact(std::span<const WeightedPoint> sigma,
                                       const WeightedPoint& p);

/// How often each stage decided (process-wide, relaxed atomics).
struct OrthospherePredicateCounters {
  std::uint64_t filtered = 0;
  std::uint64_t exact = 0;
};
OrthospherePredicateCounters orthosphere_predicate_counters();
void reset_orthosphere_predicate_counters();

}  // namespace rstruct::complex
