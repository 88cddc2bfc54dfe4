#include "rstruct/complex/orthosphere_predicates.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>

#include "complex/filtered_number.hpp"
#include "complex/rounded_leaf_number.hpp"
#include "rstruct/core/assert.hpp"
#include "rstruct/core/error.hpp"

namespace rstruct::complex {
namespace {

using detail::FilteredNumber;
using detail::RoundedLeafNumber;

std::atomic<std::uint64_t> g_filtered{0};
std::atomic<std::uint64_t> g_exact{0};

/// Each thread counts in its own counters, added to the totals when the thread ends (the
/// pipeline's workers end before their caller reads the totals) or when its owner reads
/// or resets them. One shared atomic counter incremented for every test made the
/// threads of the dual complex take turns on its cache line.
struct ThreadCounts {
  std::uint64_t filtered = 0;
  std::uint64_t exact = 0;
  void flush() {
    if (filtered != 0) g_filtered.fetch_add(filtered, std::memory_order_relaxed);
    if (exact != 0) g_exact.fetch_add(exact, std::memory_order_relaxed);
    filtered = exact = 0;
  }
  ~ThreadCounts() { flush(); }
};
thread_local ThreadCounts t_counts;

template <class N>
using V3 = std::array<N, 3>;

/// a − b of two input doubles (the filter turns exact differences into exact leaves).
template <class N>
RSTRUCT_COMPLEX_INLINE N difference(double a, double b) {
  return N(a) - N(b);
}
template <>
FilteredNumber difference<FilteredNumber>(double a, double b) {
  return FilteredNumber::difference(a, b);
}
template <>
RSTRUCT_COMPLEX_INLINE RoundedLeafNumber difference<RoundedLeafNumber>(double a, double b) {
  return RoundedLeafNumber::difference(a, b);
}

template <class N>
RSTRUCT_COMPLEX_INLINE N dot(const V3<N>& x, const V3<N>& y) {
  N s = x[0] * y[0];
  s += x[1] * y[1];
  s += x[2] * y[2];
  return s;
}

template <class N>
RSTRUCT_COMPLEX_INLINE V3<N> cross(const V3<N>& x, const V3<N>& y) {
  return {x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
}

template <class N>
RSTRUCT_COMPLEX_INLINE V3<N> combine(const N& a, const V3<N>& x, const N& b, const V3<N>& y) {  // a x − b y
  return {a * x[0] - b * y[0], a * x[1] - b * y[1], a * x[2] - b * y[2]};
}

/// The quantities of a simplex relative to its first point c₀ (see the header), in number
/// type N (FilteredNumber for the filter, mpq_class for the exact stage). The Gram forms
/// of the header are evaluated through equivalent, better conditioned vector forms:
///   k = 1: bᵀ adj(G) b = b₁², D = |u₁|²;
///   k = 2: bᵀ adj(G) b = |a|², a = b₁u₂ − b₂u₁; D = |n|², n = u₁ × u₂;
///          adj(G) b = (a × n) in the basis sense: g_pᵀ adj(G) b = ⟨u_p, a × n⟩;
///   k = 3: bᵀ adj(G) b = |v|², v = b₁ u₂×u₃ + b₂ u₃×u₁ + b₃ u₁×u₂; D = det(u₁,u₂,u₃)².
/// (Cramer's rule for z − c₀ in aff(σ); the k = 2 identity is the vector triple product.)
/// KC ≥ 0 fixes k = KC at compile time (the filter's fast stage); KC = −1 reads it from
/// the simplex.
template <class N, int KC = -1>
struct OrthoSystem {
  int k = 0;
  std::array<V3<N>, 3> u;  // u_i = c_i − c₀
  std::array<N, 3> b;      // b_i = |u_i|² − w_i + w₀
  V3<N> origin;            // c₀
  N w0;
  WeightedPoint first;
  // Shared by degeneracy(), power() and attachment() (computed once; the same
  // expressions, so the same values, as when each computed its own):
  N uu;      // k = 1: |u₁|²
  V3<N> n;   // k = 2: u₁ × u₂
  N nn;      // k = 2: |n|²
  V3<N> a;   // k = 2: b₁u₂ − b₂u₁
  V3<N> axn; // k = 2: a × n
  bool safe_leaves = true;  // RoundedLeafNumber only: every leaf passed is_safe_leaf

  RSTRUCT_COMPLEX_INLINE int dim() const {
    if constexpr (KC >= 0) {
      return KC;
    } else {
      return k;
    }
  }

  RSTRUCT_COMPLEX_INLINE explicit OrthoSystem(std::span<const WeightedPoint> sigma)
      : k(KC >= 0 ? KC : static_cast<int>(sigma.size()) - 1), first(sigma[0]) {
    for (int j = 0; j < 3; ++j) origin[j] = N(sigma[0].c[j]);
    w0 = N(sigma[0].w);
    if constexpr (std::is_same_v<N, RoundedLeafNumber>) {
      safe_leaves = RoundedLeafNumber::is_safe_leaf(sigma[0].w);
    }
    for (int i = 0; i < dim(); ++i) {
      for (int j = 0; j < 3; ++j) u[i][j] = difference<N>(sigma[i + 1].c[j], sigma[0].c[j]);
      const N dw = difference<N>(sigma[i + 1].w, sigma[0].w);
      b[i] = dot(u[i], u[i]) - dw;
      if constexpr (std::is_same_v<N, RoundedLeafNumber>) {
        safe_leaves = safe_leaves && RoundedLeafNumber::is_safe_leaf(u[i][0].v) &&
                      RoundedLeafNumber::is_safe_leaf(u[i][1].v) &&
                      RoundedLeafNumber::is_safe_leaf(u[i][2].v) &&
                      RoundedLeafNumber::is_safe_leaf(dw.v);
      }
    }
    derive_shared();
  }

  /// The same system from exact leaves in N (leaves[i] = x, y, z, w of σ's point i, all in
  /// one scale): the exact integer stage of orthosphere_power_value. Serves degeneracy()
  /// and power() only (attachment() reads the doubles of σ's first point).
  OrthoSystem(std::span<const WeightedPoint> sigma, const std::array<std::array<N, 4>, 4>& leaves)
      : k(static_cast<int>(sigma.size()) - 1), first(sigma[0]) {
    static_assert(KC < 0);
    for (int j = 0; j < 3; ++j) origin[j] = leaves[0][j];
    w0 = leaves[0][3];
    for (int i = 0; i < dim(); ++i) {
      for (int j = 0; j < 3; ++j) u[i][j] = leaves[i + 1][j] - leaves[0][j];
      b[i] = dot(u[i], u[i]) - (leaves[i + 1][3] - leaves[0][3]);
    }
    derive_shared();
  }

  /// uu, n, nn, a and axn from u and b.
  RSTRUCT_COMPLEX_INLINE void derive_shared() {
    if (dim() == 1) uu = dot(u[0], u[0]);
    if (dim() == 2) {
      n = cross(u[0], u[1]);
      nn = dot(n, n);
      a = combine(b[0], u[1], b[1], u[0]);
      axn = cross(a, n);
    }
  }

  /// Zero iff the points are affinely dependent (|u₁|², |n|² or the determinant).
  RSTRUCT_COMPLEX_INLINE N degeneracy() const {
    if (dim() == 1) return uu;
    if (dim() == 2) return nn;
    return dot(u[0], cross(u[1], u[2]));
  }

  /// Of the sign of π_σ(z_σ): bᵀ adj(G) b − 4 D w₀.
  RSTRUCT_COMPLEX_INLINE N power() const {
    if (dim() == 1) return b[0] * b[0] - N(4.0) * uu * w0;
    if (dim() == 2) return dot(a, a) - N(4.0) * nn * w0;
    const V3<N> c0 = cross(u[1], u[2]);
    const V3<N> c1 = cross(u[2], u[0]);
    const V3<N> c2 = cross(u[0], u[1]);
    V3<N> v;
    for (int j = 0; j < 3; ++j) v[j] = b[0] * c0[j] + b[1] * c1[j] + b[2] * c2[j];
    const N det = dot(u[0], c0);
    return dot(v, v) - N(4.0) * det * det * w0;
  }

  /// Of the sign of π_p(z_σ) − π_σ(z_σ): D b_p − g_pᵀ adj(G) b (k = 1, 2). For
  /// RoundedLeafNumber, `safe` is cleared if one of p's leaves fails is_safe_leaf.
  RSTRUCT_COMPLEX_INLINE N attachment(const WeightedPoint& p, bool& safe) const {
    V3<N> up;
    for (int j = 0; j < 3; ++j) up[j] = difference<N>(p.c[j], first.c[j]);
    const N dw = difference<N>(p.w, first.w);
    if constexpr (std::is_same_v<N, RoundedLeafNumber>) {
      safe = RoundedLeafNumber::is_safe_leaf(up[0].v) &&
             RoundedLeafNumber::is_safe_leaf(up[1].v) &&
             RoundedLeafNumber::is_safe_leaf(up[2].v) && RoundedLeafNumber::is_safe_leaf(dw.v);
    }
    const N bp = dot(up, up) - dw;
    if (dim() == 1) return uu * bp - dot(u[0], up) * b[0];
    return nn * bp - dot(up, axn);
  }
  N attachment(const WeightedPoint& p) const {
    bool safe = true;
    return attachment(p, safe);
  }
};

void check_size(std::span<const WeightedPoint> sigma, std::size_t max) {
  if (sigma.empty() || sigma.size() > max) {
    throw InvalidInput("orthosphere predicate: " + std::to_string(sigma.size()) +
                       " points, expected 1 to " + std::to_string(max));
  }
}

Sign exact_sign(const mpq_class& x) { return static_cast<Sign>(sgn(x)); }

void require_independent(const mpq_class& degeneracy) {
  if (sgn(degeneracy) == 0) {
    throw InvalidInput("orthosphere predicate: the points of the simplex are affinely dependent");
  }
}

/// The fast stage of orthosphere_power_sign for |σ| = KC + 1: the sign, or 2.
template <int KC>
int fast_power_sign(std::span<const WeightedPoint> sigma) {
  const OrthoSystem<RoundedLeafNumber, KC> s(sigma);
  if (!s.safe_leaves) return 2;
  const int nondegenerate = s.degeneracy().certified_sign();
  if (nondegenerate != 1 && nondegenerate != -1) return 2;
  return s.power().certified_sign();
}

/// The fast stage of orthosphere_attachment_sign for |σ| = KC + 1 ≥ 2: the sign, or 2.
template <int KC>
int fast_attachment_sign(std::span<const WeightedPoint> sigma, const WeightedPoint& p) {
  const OrthoSystem<RoundedLeafNumber, KC> s(sigma);
  if (!s.safe_leaves || s.degeneracy().certified_sign() != 1) return 2;
  bool safe = true;
  const RoundedLeafNumber value = s.attachment(p, safe);
  return safe ? value.certified_sign() : 2;
}

}  // namespace

Sign orthosphere_power_sign_exact(std::span<const WeightedPoint> sigma) {
  check_size(sigma, 4);
  if (sigma.size() == 1) return -sign_of(sigma[0].w);
  const OrthoSystem<mpq_class> s(sigma);
  require_independent(s.degeneracy());
  return exact_sign(s.power());
}

Sign orthosphere_attachment_sign_exact(std::span<const WeightedPoint> sigma,
                                       const WeightedPoint& p) {
  check_size(sigma, 3);
  if (sigma.size() == 1) {
    // π_p(c₀) − π₀(c₀) = |c_p − c₀|² − w_p + w₀.
    const OrthoSystem<mpq_class> s(std::array<WeightedPoint, 2>{sigma[0], p});
    return exact_sign(s.b[0]);
  }
  const OrthoSystem<mpq_class> s(sigma);
  require_independent(s.degeneracy());
  return exact_sign(s.attachment(p));
}

Sign orthosphere_power_sign(std::span<const WeightedPoint> sigma) {
  check_size(sigma, 4);
  if (sigma.size() == 1) return -sign_of(sigma[0].w);
  const int fast = sigma.size() == 4   ? fast_power_sign<3>(sigma)
                   : sigma.size() == 3 ? fast_power_sign<2>(sigma)
                                       : fast_power_sign<1>(sigma);
  if (fast != 2) {
    ++t_counts.filtered;
    return static_cast<Sign>(fast);
  }
  const OrthoSystem<FilteredNumber> s(sigma);
  const int nondegenerate = s.degeneracy().certified_sign();
  if (nondegenerate == 1 || nondegenerate == -1) {
    const int sign = s.power().certified_sign();
    if (sign != 2) {
      ++t_counts.filtered;
      return static_cast<Sign>(sign);
    }
  }
  ++t_counts.exact;
  return orthosphere_power_sign_exact(sigma);
}

namespace {

/// 4D of the header: 4|u₁|², 4|n|² or 4 det², in number type N.
template <class N>
N orthosphere_denominator(const OrthoSystem<N>& s) {
  if (s.dim() == 1) return N(4.0) * s.uu;
  if (s.dim() == 2) return N(4.0) * s.nn;
  const N det = s.degeneracy();
  return N(4.0) * det * det;
}

/// Whether the filtered x is within a relative 2⁻³⁰ of its exact value and not zero (a
/// zero value needs the exact stage to tell 0 from tiny). (2⁻⁴⁶ sent about a quarter of
/// the simplices of a surface-ball triangulation to the exact stage: flat cells.)
bool accurate(const FilteredNumber& x) {
  const double e = x.error_bound();
  return x.v != 0 && e <= std::fabs(x.v) * 0x1p-30;
}

/// An input double as m·2^e with m an integer (|m| < 2⁵³).
struct Dyadic {
  double mantissa;
  int exponent;
};
Dyadic dyadic(double x) {
  int e = 0;
  const double f = std::frexp(x, &e);  // x = f·2^e, 0.5 ≤ |f| < 1 (or x = 0)
  return {std::ldexp(f, 53), e - 53};
}

/// m·2^shift as an integer. \pre shift ≥ 0 unless m = 0.
mpz_class scaled(const Dyadic& d, int shift) {
  if (d.mantissa == 0) return 0;
  RSTRUCT_ASSERT(shift >= 0);
  mpz_class z(d.mantissa);  // exact: an integer below 2⁵³
  mpz_mul_2exp(z.get_mpz_t(), z.get_mpz_t(), static_cast<mp_bitcnt_t>(shift));
  return z;
}

/// The exact π_σ(z_σ), rounded toward zero to a double, from integers: every coordinate
/// times 2^E and every weight times 2^2E (E makes them all integers), so that the header's
/// polynomials (OrthoSystem<mpz_class>) are evaluated without fractions (mpq_class would
/// take a gcd after every operation), and the quotient is scaled back by 2^−2E once.
double exact_power_value(std::span<const WeightedPoint> sigma) {
  std::array<std::array<Dyadic, 4>, 4> d{};  // x, y, z, w of each point
  int scale = std::numeric_limits<int>::min();
  for (std::size_t i = 0; i < sigma.size(); ++i) {
    for (int j = 0; j < 3; ++j) {
      d[i][j] = dyadic(sigma[i].c[j]);
      if (d[i][j].mantissa != 0) scale = std::max(scale, -d[i][j].exponent);
    }
    d[i][3] = dyadic(sigma[i].w);
    if (d[i][3].mantissa != 0) scale = std::max(scale, (1 - d[i][3].exponent) / 2);
  }
  if (scale == std::numeric_limits<int>::min()) scale = 0;  // every input is zero
  std::array<std::array<mpz_class, 4>, 4> leaves;
  for (std::size_t i = 0; i < sigma.size(); ++i) {
    for (int j = 0; j < 4; ++j) {
      leaves[i][j] = scaled(d[i][j], d[i][j].exponent + (j < 3 ? scale : 2 * scale));
    }
  }
  const OrthoSystem<mpz_class> s(sigma, leaves);
  const mpz_class den = orthosphere_denominator(s);
  if (sgn(den) == 0) {
    throw InvalidInput("orthosphere predicate: the points of the simplex are affinely dependent");
  }
  const mpz_class num = s.power();
  const int sign = sgn(num);
  if (sign == 0) return 0.0;
  // |num| / den to at least 64 bits: shift num left, divide, truncate.
  mpz_class q = abs(num);
  const auto bits = [](const mpz_class& x) {
    return static_cast<long>(mpz_sizeinbase(x.get_mpz_t(), 2));
  };
  const long shift = std::max(0L, 64 + bits(den) - bits(q));
  mpz_mul_2exp(q.get_mpz_t(), q.get_mpz_t(), static_cast<mp_bitcnt_t>(shift));
  mpz_tdiv_q(q.get_mpz_t(), q.get_mpz_t(), den.get_mpz_t());
  long exponent = 0;
  const double mantissa = mpz_get_d_2exp(&exponent, q.get_mpz_t());  // truncated, [0.5, 1)
  const long e2 = exponent - shift - 2L * scale;
  const double magnitude =
      std::ldexp(mantissa, static_cast<int>(std::clamp(e2, -2000L, 2000L)));
  if (magnitude == 0) return sign * std::numeric_limits<double>::denorm_min();
  return sign * magnitude;
}

}  // namespace

double orthosphere_power_value(std::span<const WeightedPoint> sigma) {
  check_size(sigma, 4);
  if (sigma.size() == 1) return -sigma[0].w;
  // Filtered: numerator and denominator each within a relative 2⁻³⁰, so their rounded
  // quotient is within (1 + 2⁻³⁰)² / (1 − 2⁻³⁰) · (1 + 2⁻⁵³) − 1 < 2⁻²⁸ of the exact one;
  // its sign is then certified too.
  const OrthoSystem<FilteredNumber> s(sigma);
  const FilteredNumber num = s.power();
  const FilteredNumber den = orthosphere_denominator(s);
  if (accurate(num) && accurate(den)) {
    const double q = num.v / den.v;
    if (std::isfinite(q) && std::fabs(q) >= 0x1p-1000) {  // normal: relative rounding
      ++t_counts.filtered;
      return q;
    }
  }
  ++t_counts.exact;
  return exact_power_value(sigma);
}

Sign orthosphere_attachment_sign(std::span<const WeightedPoint> sigma, const WeightedPoint& p) {
  check_size(sigma, 3);
  if (sigma.size() == 1) {
    const std::array<WeightedPoint, 2> pair{sigma[0], p};
    const OrthoSystem<RoundedLeafNumber, 1> fast(pair);
    int sign = fast.safe_leaves ? fast.b[0].certified_sign() : 2;
    if (sign == 2) sign = OrthoSystem<FilteredNumber>(pair).b[0].certified_sign();
    if (sign != 2) {
      ++t_counts.filtered;
      return static_cast<Sign>(sign);
    }
  } else {
    const int fast = sigma.size() == 3 ? fast_attachment_sign<2>(sigma, p)
                                       : fast_attachment_sign<1>(sigma, p);
    if (fast != 2) {
      ++t_counts.filtered;
      return static_cast<Sign>(fast);
    }
    const OrthoSystem<FilteredNumber> s(sigma);
    if (s.degeneracy().certified_sign() == 1) {
      const int sign = s.attachment(p).certified_sign();
      if (sign != 2) {
        ++t_counts.filtered;
        return static_cast<Sign>(sign);
      }
    }
  }
  ++t_counts.exact;
  return orthosphere_attachment_sign_exact(sigma, p);
}

namespace {

/// orthosphere_is_unattached_in_union for |σ| = KC + 1 ≥ 2. Stage 1: RoundedLeafNumber
/// (cheap); stage 2: FilteredNumber, built on first need; stage 3: exact.
template <int KC>
bool unattached_in_union(std::span<const WeightedPoint> sigma,
                         std::span<const WeightedPoint> opposite) {
  const OrthoSystem<RoundedLeafNumber, KC> fast(sigma);
  const bool fast_independent = fast.safe_leaves && fast.degeneracy().certified_sign() == 1;
  std::optional<OrthoSystem<FilteredNumber>> slow;
  bool slow_independent = false;
  const auto slow_system = [&]() -> const OrthoSystem<FilteredNumber>& {
    if (!slow) {
      slow.emplace(sigma);
      slow_independent = slow->degeneracy().certified_sign() == 1;
    }
    return *slow;
  };
  std::uint64_t filtered = 0;
  std::uint64_t exact = 0;
  bool result = true;
  int power = fast_independent ? fast.power().certified_sign() : 2;
  if (power == 2) {
    const OrthoSystem<FilteredNumber>& s = slow_system();
    power = slow_independent ? s.power().certified_sign() : 2;
  }
  if (power == 2) {
    ++exact;
    power = static_cast<int>(orthosphere_power_sign_exact(sigma));
  } else {
    ++filtered;
  }
  if (power == 1) result = false;
  for (std::size_t k = 0; result && k < opposite.size(); ++k) {
    int sign = 2;
    if (fast_independent) {
      bool safe = true;
      const RoundedLeafNumber value = fast.attachment(opposite[k], safe);
      if (safe) sign = value.certified_sign();
    }
    if (sign == 2) {
      const OrthoSystem<FilteredNumber>& s = slow_system();
      sign = slow_independent ? s.attachment(opposite[k]).certified_sign() : 2;
    }
    if (sign == 2) {
      ++exact;
      sign = static_cast<int>(orthosphere_attachment_sign_exact(sigma, opposite[k]));
    } else {
      ++filtered;
    }
    if (sign == -1) result = false;
  }
  t_counts.filtered += filtered;
  t_counts.exact += exact;
  return result;
}

}  // namespace

bool orthosphere_is_unattached_in_union(std::span<const WeightedPoint> sigma,
                                        std::span<const WeightedPoint> opposite) {
  check_size(sigma, 3);
  if (sigma.size() == 1) {
    if (orthosphere_power_sign(sigma) == Sign::positive) return false;
    for (const WeightedPoint& p : opposite) {
      if (orthosphere_attachment_sign(sigma, p) == Sign::negative) return false;
    }
    return true;
  }
  return sigma.size() == 2 ? unattached_in_union<1>(sigma, opposite)
                          : unattached_in_union<2>(sigma, opposite);
}

OrthospherePredicateCounters orthosphere_predicate_counters() {
  t_counts.flush();
  return {g_filtered.load(std::memory_order_relaxed), g_exact.load(std::memory_order_relaxed)};
}

void reset_orthosphere_predicate_counters() {
  t_counts = ThreadCounts{};
  g_filtered.store(0, std::memory_order_relaxed);
  g_exact.store(0, std::memory_order_relaxed);
}

}  // namespace rstruct::complex
