// The exact stage. Inputs are scaled to integers at one common binary unit (exact), then
// the polynomial of polynomials.hpp is evaluated in FastInt (inline limbs, no heap) when
// a bound on the bit length of the result fits, and in GMP otherwise (inputs spanning
// hundreds of binary orders of magnitude). The bit bounds: differences of scaled
// coordinates have at most Bc bits, lifting heights at most L bits
// (ScaleFinder::lifted_height_bits); a sum of k products of such factors needs
// log2(k) more bits than one product.
#include "predicates/exact_stage.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <bit>
#include <climits>
#include <cmath>
#include <initializer_list>
#include <string>

#include "rstruct/predicates/detail/polynomials.hpp"
#include "predicates/scaled_integer.hpp"
#include "rstruct/core/error.hpp"

namespace rstruct::predicates::detail {
namespace {

template <std::size_t N>
using PointRefs = std::array<const WeightedPoint*, N>;

template <class Z, std::size_t N>
struct Scaled {
  std::array<std::array<Z, 3>, N> c;  // coordinates / 2^s
  std::array<Z, N> w;                 // weights / 2^(2s)
};

template <std::size_t N>
ScaleFinder find_scale(const PointRefs<N>& pts, bool weighted) {
  ScaleFinder finder;
  for (const WeightedPoint* p : pts) {
    for (std::size_t i = 0; i < 3; ++i) finder.add_coordinate(p->c[i]);
    if (weighted) finder.add_weight(p->w);
  }
  return finder;
}

template <class Z, std::size_t N>
Scaled<Z, N> convert(const PointRefs<N>& pts, bool weighted, int s) {
  Scaled<Z, N> out;
  for (std::size_t j = 0; j < N; ++j) {
    for (std::size_t i = 0; i < 3; ++i) set_scaled(out.c[j][i], pts[j]->c[i], s);
    if (weighted) set_scaled(out.w[j], pts[j]->w, 2 * s);
  }
  return out;
}

/// Calls eval with a FastInt tag if `bits` fit in FastInt, with an mpz_class tag otherwise.
template <class Eval>
int dispatch(int bits, const Eval& eval) {
  if (bits <= FastInt::bit_capacity()) return eval(FastInt());
  return eval(mpz_class());
}

template <std::size_t N>
void require_finite_points(const char* where, const PointRefs<N>& pts) {
  for (const WeightedPoint* p : pts) require_finite(where, {p->c.x, p->c.y, p->c.z, p->w});
}

__extension__ typedef __int128 Int128;

Int128 mul64(std::int64_t a, std::int64_t b) { return static_cast<Int128>(a) * b; }

/// Σ coef_k · m_k exactly, for |coef_k| < 2^62 and |m_k| < 2^126, as high·2^64 + low with
/// 0 ≤ low < 2^64 (|high| < 2^126).
struct Int192 {
  Int128 high = 0;
  std::uint64_t low = 0;
};
Int192 sum_of_products(const std::int64_t (&coef)[3], const Int128 (&m)[3]) {
  Int128 high = 0;
  Int128 low = 0;  // sum of three values in [0, 2^64)
  for (int k = 0; k < 3; ++k) {
    const auto lo = static_cast<std::uint64_t>(m[k]);  // m = hi·2^64 + lo, 0 ≤ lo < 2^64
    const auto hi = static_cast<std::int64_t>((m[k] - static_cast<Int128>(lo)) >> 64);
    const Int128 b = static_cast<Int128>(coef[k]) * static_cast<Int128>(lo);  // |b| < 2^126
    high += mul64(coef[k], hi) + (b >> 64);  // >> is floor division by 2^64
    low += static_cast<Int128>(static_cast<std::uint64_t>(b));
  }
  high += low >> 64;
  return {high, static_cast<std::uint64_t>(low)};
}

int sign_of(const Int192& v) {
  if (v.high != 0) return v.high > 0 ? 1 : -1;
  return v.low != 0 ? 1 : 0;
}

/// det[p; q; r] from the rows' z and the 2×2 minors of their (x, y), as in
/// polynomials.hpp: pz·m(q, r) − qz·m(p, r) + rz·m(p, q).
Int192 det3_int(std::int64_t pz, std::int64_t qz, std::int64_t rz, Int128 m_qr, Int128 m_pr,
                Int128 m_pq) {
  return sum_of_products({pz, -qz, rz}, {m_qr, m_pr, m_pq});
}

/// A signed integer of 320 bits in two's complement (five 64-bit limbs, least significant
/// first): the last sum of the lifted determinant, Σ ±lift·det with |lift| < 2^127 and
/// |det| < 2^190, so every partial sum stays below 2^319 in magnitude.
class Sum320 {
 public:
  /// *this += (subtract ? −1 : 1)·l·d.
  void add_product(Int128 l, const Int192& d, bool subtract) {
    const bool l_negative = l < 0;
    const auto lm = static_cast<numeric::UInt128>(l_negative ? -l : l);
    // |d| as three limbs: d = high·2^64 + low in two's complement, negated if negative.
    std::uint64_t dm[3] = {d.low, static_cast<std::uint64_t>(d.high),
                           static_cast<std::uint64_t>(d.high >> 64)};
    const bool d_negative = d.high < 0;
    if (d_negative) {
      numeric::UInt128 carry = 1;
      for (std::uint64_t& limb : dm) {
        carry += static_cast<std::uint64_t>(~limb);
        limb = static_cast<std::uint64_t>(carry);
        carry >>= 64;
      }
    }
    const std::uint64_t lw[2] = {static_cast<std::uint64_t>(lm),
                                 static_cast<std::uint64_t>(lm >> 64)};
    std::uint64_t p[5] = {};
    for (int i = 0; i < 2; ++i) {
      numeric::UInt128 carry = 0;
      for (int j = 0; j < 3; ++j) {
        carry += static_cast<numeric::UInt128>(lw[i]) * dm[j] + p[i + j];
        p[i + j] = static_cast<std::uint64_t>(carry);
        carry >>= 64;
      }
      p[i + 3] = static_cast<std::uint64_t>(carry);
    }
    if ((l_negative != d_negative) != subtract) {  // add the two's complement −p
      numeric::UInt128 carry = 1;
      for (int k = 0; k < 5; ++k) {
        carry += static_cast<numeric::UInt128>(limb_[k]) + static_cast<std::uint64_t>(~p[k]);
        limb_[k] = static_cast<std::uint64_t>(carry);
        carry >>= 64;
      }
    } else {
      numeric::UInt128 carry = 0;
      for (int k = 0; k < 5; ++k) {
        carry += static_cast<numeric::UInt128>(limb_[k]) + p[k];
        limb_[k] = static_cast<std::uint64_t>(carry);
        carry >>= 64;
      }
    }
  }
  int sign() const {
    if ((limb_[4] >> 63) != 0) return -1;
    return (limb_[0] | limb_[1] | limb_[2] | limb_[3] | limb_[4]) != 0 ? 1 : 0;
  }

 private:
  std::uint64_t limb_[5] = {};
};

/// The inputs of one call split once (split_double): the finiteness check, the common
/// unit s (ScaleFinder's, for coordinates only) and the bit bound from one pass, so that
/// the usual case (nearby inputs, differences below 2^62) needs no second conversion.
template <std::size_t N>
struct SplitCoordinates {
  std::array<DyadicParts, N> part{};
  int unit = INT_MAX;  // smallest exponent of a non-zero value
  int top = INT_MIN;   // largest exponent just above a non-zero value's top bit
  bool finite = true;

  explicit SplitCoordinates(const std::array<double, N>& x) {
    for (std::size_t i = 0; i < N; ++i) {
      finite &= ((std::bit_cast<std::uint64_t>(x[i]) >> 52) & 0x7ff) != 0x7ff;
      part[i] = split_double(x[i]);
      if (part[i].mantissa != 0) {
        unit = std::min(unit, part[i].exponent);
        top = std::max(top, top_exponent(part[i]));
      }
    }
  }
  /// True iff all inputs are finite, not all zero, and every difference of two scaled
  /// values has at most `bits` bits.
  bool fits(int bits) const { return finite && unit != INT_MAX && top - unit + 1 <= bits; }
  /// Input i / 2^unit. \pre fits(62).
  std::int64_t scaled(std::size_t i) const {
    if (part[i].mantissa == 0) return 0;
    return part[i].mantissa * (std::int64_t{1} << (part[i].exponent - unit));
  }
};

/// orient3d when the scaled differences fit in 62 bits (nearby inputs, the usual case):
/// 2×2 minors are below 2^125 in Int128, the final sum is an Int192.
/// \pre s.fits(62); s holds a, b, c, d's coordinates in order.
int orient3d_int64(const SplitCoordinates<12>& s) {
  std::int64_t t[3][3];
  for (std::size_t j = 0; j < 3; ++j) {
    for (std::size_t i = 0; i < 3; ++i) t[j][i] = s.scaled(3 * (j + 1) + i) - s.scaled(i);
  }
  const Int128 m_qr = mul64(t[1][0], t[2][1]) - mul64(t[2][0], t[1][1]);
  const Int128 m_pr = mul64(t[0][0], t[2][1]) - mul64(t[2][0], t[0][1]);
  const Int128 m_pq = mul64(t[0][0], t[1][1]) - mul64(t[1][0], t[0][1]);
  return sign_of(det3_int(t[0][2], t[1][2], t[2][2], m_qr, m_pr, m_pq));
}

/// The lifted 4×4 determinant when coordinate differences fit in 62 bits and scaled
/// weights in 124 bits: minors and lifting heights (< 2^127) in Int128, the 3×3 minors
/// in Int192, the last four products and sums in FastInt (< 2^318).
/// \pre c.fits(62) and w's scaled differences (at unit 2·c.unit) below 2^125; c holds the
/// coordinates of a, b, c, d, e in order, w their weights (nullptr: all weights zero).
int lifted4_int64(const SplitCoordinates<15>& c, const SplitCoordinates<5>* w) {
  std::int64_t t[4][3];
  Int128 lift[4];
  const auto weight = [&](std::size_t j) -> Int128 {
    const DyadicParts& p = w->part[j];
    if (p.mantissa == 0) return 0;
    return static_cast<Int128>(p.mantissa) * (static_cast<Int128>(1) << (p.exponent - 2 * c.unit));
  };
  for (std::size_t j = 0; j < 4; ++j) {
    for (std::size_t i = 0; i < 3; ++i) t[j][i] = c.scaled(3 * j + i) - c.scaled(12 + i);
    const Int128 tw = w != nullptr ? weight(j) - weight(4) : 0;
    lift[j] = (mul64(t[j][0], t[j][0]) + mul64(t[j][1], t[j][1])) + mul64(t[j][2], t[j][2]) - tw;
  }
  auto m = [&](int p, int q) { return mul64(t[p][0], t[q][1]) - mul64(t[q][0], t[p][1]); };
  const Int128 m_ab = m(0, 1), m_ac = m(0, 2), m_ad = m(0, 3), m_bc = m(1, 2), m_bd = m(1, 3),
               m_cd = m(2, 3);
  Sum320 value;
  value.add_product(lift[0], det3_int(t[1][2], t[2][2], t[3][2], m_cd, m_bd, m_bc), false);
  value.add_product(lift[1], det3_int(t[0][2], t[2][2], t[3][2], m_cd, m_ad, m_ac), true);
  value.add_product(lift[2], det3_int(t[0][2], t[1][2], t[3][2], m_bd, m_ad, m_ab), false);
  value.add_product(lift[3], det3_int(t[0][2], t[1][2], t[2][2], m_bc, m_ac, m_ab), true);
  return value.sign();
}

/// orient3d with each column scaled by its own unit 2^s_i. det[t] = 2^(s_x+s_y+s_z)·det[t /
/// 2^s] with a positive factor, so the sign is unchanged, and the integers need
/// B_x + B_y + B_z + 3 bits (column spans B_i) rather than 3·max B_i + 3: one coordinate
/// near zero (a subnormal) widens only its own column.
template <class Z>
int orient3d_eval(const PointRefs<4>& pts, const std::array<int, 3>& unit) {
  std::array<std::array<Z, 3>, 4> v;
  for (std::size_t j = 0; j < 4; ++j) {
    for (std::size_t i = 0; i < 3; ++i) set_scaled(v[j][i], pts[j]->c[i], unit[i]);
  }
  std::array<std::array<Z, 3>, 3> t;
  for (std::size_t j = 0; j < 3; ++j) {
    for (std::size_t i = 0; i < 3; ++i) t[j][i] = v[j + 1][i] - v[0][i];
  }
  return sign_int(det3(t[0][0], t[0][1], t[0][2], t[1][0], t[1][1], t[1][2], t[2][0], t[2][1],
                       t[2][2]));
}

template <class Z>
int orient2d_eval(const PointRefs<3>& pts, int s, int k) {
  const auto v = convert<Z, 3>(pts, false, s);
  const auto u = static_cast<std::size_t>((k + 1) % 3), w = static_cast<std::size_t>((k + 2) % 3);
  const Z bu = v.c[1][u] - v.c[0][u], bv = v.c[1][w] - v.c[0][w];
  const Z cu = v.c[2][u] - v.c[0][u], cv = v.c[2][w] - v.c[0][w];
  return sign_int(minor2(bu, bv, cu, cv));
}

template <class Z>
int lifted4_eval(const PointRefs<5>& pts, int s) {
  const auto v = convert<Z, 5>(pts, true, s);
  std::array<std::array<Z, 4>, 4> r;  // rows (x, y, z, lifted height) relative to e
  for (std::size_t j = 0; j < 4; ++j) {
    for (std::size_t i = 0; i < 3; ++i) r[j][i] = v.c[j][i] - v.c[4][i];
    const Z tw = v.w[j] - v.w[4];
    r[j][3] = lifted_height(r[j][0], r[j][1], r[j][2], tw);
  }
  const LiftedRows<Z> rows{r[0][0], r[0][1], r[0][2], r[0][3], r[1][0], r[1][1], r[1][2], r[1][3],
                           r[2][0], r[2][1], r[2][2], r[2][3], r[3][0], r[3][1], r[3][2], r[3][3]};
  return sign_int(lifted_det4_negated(rows));
}

template <class Z>
int coplanar_eval(const PointRefs<4>& pts, int s, int k) {
  const auto v = convert<Z, 4>(pts, true, s);
  const auto u = static_cast<std::size_t>((k + 1) % 3), w = static_cast<std::size_t>((k + 2) % 3);
  std::array<std::array<Z, 3>, 3> r;  // rows (u, v, lifted height) relative to e
  for (std::size_t j = 0; j < 3; ++j) {
    const Z tx = v.c[j][0] - v.c[3][0], ty = v.c[j][1] - v.c[3][1], tz = v.c[j][2] - v.c[3][2];
    const Z tw = v.w[j] - v.w[3];
    r[j][0] = v.c[j][u] - v.c[3][u];
    r[j][1] = v.c[j][w] - v.c[3][w];
    r[j][2] = lifted_height(tx, ty, tz, tw);
  }
  return sign_int(lifted_det3(r[0][0], r[0][1], r[0][2], r[1][0], r[1][1], r[1][2], r[2][0],
                              r[2][1], r[2][2]));
}

template <class Z>
int collinear_eval(const PointRefs<3>& pts, int s, int k) {
  const auto v = convert<Z, 3>(pts, true, s);
  const auto q = static_cast<std::size_t>(k);
  std::array<Z, 2> tq, h;
  for (std::size_t j = 0; j < 2; ++j) {
    const Z tx = v.c[j][0] - v.c[2][0], ty = v.c[j][1] - v.c[2][1], tz = v.c[j][2] - v.c[2][2];
    const Z tw = v.w[j] - v.w[2];
    tq[j] = v.c[j][q] - v.c[2][q];
    h[j] = lifted_height(tx, ty, tz, tw);
  }
  return sign_int(lifted_det2(tq[0], h[0], tq[1], h[1]));
}

template <class Z>
int power_difference_eval(const PointRefs<3>& pts, int s) {
  const auto v = convert<Z, 3>(pts, true, s);
  std::array<std::array<Z, 3>, 2> t;
  for (std::size_t j = 0; j < 2; ++j) {
    for (std::size_t i = 0; i < 3; ++i) t[j][i] = v.c[0][i] - v.c[j + 1][i];
  }
  return sign_int(power_difference(t[0][0], t[0][1], t[0][2], v.w[1], t[1][0], t[1][1],
                                   t[1][2], v.w[2]));
}

template <class Z>
int power_value_eval(const PointRefs<2>& pts, int s) {
  const auto v = convert<Z, 2>(pts, true, s);
  std::array<Z, 3> t;
  for (std::size_t i = 0; i < 3; ++i) t[i] = v.c[0][i] - v.c[1][i];
  return sign_int(power_value(t[0], t[1], t[2], v.w[1]));
}

/// pts = {x, centre, (r, 0, 0)}: the radius is a length on the coordinates' scale.
template <class Z>
int ball_side_eval(const PointRefs<3>& pts, int s) {
  const auto v = convert<Z, 3>(pts, false, s);
  std::array<Z, 3> t;
  for (std::size_t i = 0; i < 3; ++i) t[i] = v.c[0][i] - v.c[1][i];
  return sign_int(ball_side_value(t[0], t[1], t[2], v.c[2][0]));
}

}  // namespace

void require_finite(const char* where, std::initializer_list<double> values) {
  for (const double v : values) {
    if (!std::isfinite(v)) {
      throw InvalidInput(std::string("predicates::") + where +
                         ": non-finite input coordinate or weight (" + std::to_string(v) + ")");
    }
  }
}

namespace {

/// orient3d_exact beyond 62-bit differences (or non-finite input); kept out of line so
/// that its large frame does not slow down the common path.
[[gnu::noinline]] int orient3d_exact_wide(const Point3& a, const Point3& b, const Point3& c,
                                          const Point3& d) {
  const WeightedPoint wa{a, 0}, wb{b, 0}, wc{c, 0}, wd{d, 0};
  const PointRefs<4> pts{&wa, &wb, &wc, &wd};
  require_finite_points("orient3d", pts);
  std::array<ScaleFinder, 3> column;
  for (const WeightedPoint* p : pts) {
    for (std::size_t i = 0; i < 3; ++i) column[i].add_coordinate(p->c[i]);
  }
  const std::array<int, 3> unit{column[0].unit(), column[1].unit(), column[2].unit()};
  const int bits = column[0].coordinate_difference_bits() +
                   column[1].coordinate_difference_bits() +
                   column[2].coordinate_difference_bits() + 3;
  if (bits <= FastInt::bit_capacity()) return orient3d_eval<FastInt>(pts, unit);
  if (bits <= WideInt::bit_capacity()) return orient3d_eval<WideInt>(pts, unit);
  return orient3d_eval<mpz_class>(pts, unit);
}

}  // namespace

int orient3d_exact(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  const SplitCoordinates<12> split({a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, d.x, d.y, d.z});
  if (split.fits(62)) [[likely]] return orient3d_int64(split);
  return orient3d_exact_wide(a, b, c, d);
}

int orient2d_exact(const Point3& a, const Point3& b, const Point3& c, int k) {
  const WeightedPoint wa{a, 0}, wb{b, 0}, wc{c, 0};
  const PointRefs<3> pts{&wa, &wb, &wc};
  require_finite_points("orient2d", pts);
  const ScaleFinder f = find_scale(pts, false);
  return dispatch(2 * f.coordinate_difference_bits() + 1, [&](auto tag) {
    return orient2d_eval<decltype(tag)>(pts, f.unit(), k);
  });
}

namespace {

/// lifted4_exact beyond the Int128 path (or non-finite input), out of line as for orient3d.
[[gnu::noinline]] int lifted4_exact_wide(const WeightedPoint& a, const WeightedPoint& b,
                                         const WeightedPoint& c, const WeightedPoint& d,
                                         const WeightedPoint& e) {
  const PointRefs<5> pts{&a, &b, &c, &d, &e};
  require_finite_points("power_test", pts);
  const ScaleFinder f = find_scale(pts, true);
  return dispatch(3 * f.coordinate_difference_bits() + f.lifted_height_bits() + 5,
                  [&](auto tag) { return lifted4_eval<decltype(tag)>(pts, f.unit()); });
}

}  // namespace

int lifted4_exact(const WeightedPoint& a, const WeightedPoint& b, const WeightedPoint& c,
                  const WeightedPoint& d, const WeightedPoint& e) {
  SplitCoordinates<15> coords({a.c.x, a.c.y, a.c.z, b.c.x, b.c.y, b.c.z, c.c.x, c.c.y, c.c.z,
                               d.c.x, d.c.y, d.c.z, e.c.x, e.c.y, e.c.z});
  const SplitCoordinates<5> weights({a.w, b.w, c.w, d.w, e.w});
  const bool weighted = weights.unit != INT_MAX;
  if (weighted) {
    // Weights live at scale 2^(2s) (ScaleFinder::add_weight): s ≤ ⌊exponent / 2⌋.
    const int half = weights.unit >= 0 ? weights.unit / 2 : -((-weights.unit + 1) / 2);
    coords.unit = std::min(coords.unit, half);
  }
  if (weights.finite && coords.fits(62) &&
      (!weighted || weights.top - 2 * coords.unit + 1 <= 125)) [[likely]] {
    return lifted4_int64(coords, weighted ? &weights : nullptr);
  }
  return lifted4_exact_wide(a, b, c, d, e);
}

int coplanar_power_exact(const WeightedPoint& a, const WeightedPoint& b,
                         const WeightedPoint& c, const WeightedPoint& e, int k) {
  const PointRefs<4> pts{&a, &b, &c, &e};
  require_finite_points("coplanar_power_test", pts);
  const ScaleFinder f = find_scale(pts, true);
  return dispatch(2 * f.coordinate_difference_bits() + f.lifted_height_bits() + 3,
                  [&](auto tag) { return coplanar_eval<decltype(tag)>(pts, f.unit(), k); });
}

int collinear_power_exact(const WeightedPoint& a, const WeightedPoint& b,
                          const WeightedPoint& e, int k) {
  const PointRefs<3> pts{&a, &b, &e};
  require_finite_points("collinear_power_test", pts);
  const ScaleFinder f = find_scale(pts, true);
  return dispatch(f.coordinate_difference_bits() + f.lifted_height_bits() + 1,
                  [&](auto tag) { return collinear_eval<decltype(tag)>(pts, f.unit(), k); });
}

int squared_distance_difference_exact(const Point3& x, const Point3& p, const Point3& q) {
  // Nearby inputs (the usual case): with every scaled coordinate below 2^60 in magnitude,
  // the differences are below 2^61, their squares below 2^122 and the signed sum of six
  // squares below 2^125, all exact in Int128.
  const SplitCoordinates<9> s({x.x, x.y, x.z, p.x, p.y, p.z, q.x, q.y, q.z});
  if (s.fits(60)) [[likely]] {
    Int128 sum = 0;
    for (std::size_t i = 0; i < 3; ++i) {
      const std::int64_t dp = s.scaled(i) - s.scaled(3 + i);
      const std::int64_t dq = s.scaled(i) - s.scaled(6 + i);
      sum += mul64(dp, dp) - mul64(dq, dq);
    }
    return (sum > 0) - (sum < 0);
  }
  return power_difference_exact(x, WeightedPoint{p, 0}, WeightedPoint{q, 0});
}

int power_difference_exact(const Point3& x, const WeightedPoint& p, const WeightedPoint& q) {
  const WeightedPoint wx{x, 0};
  const PointRefs<3> pts{&wx, &p, &q};
  require_finite_points("compare_power_distance", pts);
  const ScaleFinder f = find_scale(pts, true);
  return dispatch(f.lifted_height_bits() + 2,
                  [&](auto tag) { return power_difference_eval<decltype(tag)>(pts, f.unit()); });
}

int power_value_exact(const Point3& x, const WeightedPoint& p) {
  const WeightedPoint wx{x, 0};
  const PointRefs<2> pts{&wx, &p};
  require_finite_points("power_sign", pts);
  const ScaleFinder f = find_scale(pts, true);
  return dispatch(f.lifted_height_bits() + 1,
                  [&](auto tag) { return power_value_eval<decltype(tag)>(pts, f.unit()); });
}

int ball_side_exact(const Point3& x, const Point3& centre, double r) {
  require_finite("side_of_ball", {x.x, x.y, x.z, centre.x, centre.y, centre.z, r});
  const WeightedPoint wx{x, 0}, wc{centre, 0}, wr{{r, 0, 0}, 0};
  const PointRefs<3> pts{&wx, &wc, &wr};
  const ScaleFinder f = find_scale(pts, false);
  return dispatch(2 * f.coordinate_difference_bits() + 3,
                  [&](auto tag) { return ball_side_eval<decltype(tag)>(pts, f.unit()); });
}

}  // namespace rstruct::predicates::detail
