// The exact stage's integer paths at their limits, against the rational oracle (an
// independent Gaussian elimination on GMP rationals): orient3d and the lifted 4×4
// determinant on inputs whose scaled differences have 50 to 64 bits (both sides of the
// 62-bit Int128 path), large weights (negative lifting heights, every sign combination in
// the 320-bit final sum), and orient3d with one column spanning the whole double range
// (subnormals next to ordinary values: the per-column scaled path).
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "predicates/cases.hpp"
#include "predicates/exact_stage.hpp"
#include "predicates/rational_oracle.hpp"

using namespace rstruct;
using namespace rstruct::testing;
namespace pd = rstruct::predicates::detail;
using oracle::Q;

namespace {

/// Sign of −det[(p − e, |p − e|² − (w_p − w_e))] for p = a, b, c, d, in rationals.
int oracle_lifted4(const std::array<WeightedPoint, 5>& p) {
  oracle::Matrix m;
  const oracle::QPoint e = oracle::qp(p[4].c);
  for (std::size_t j = 0; j < 4; ++j) {
    const oracle::QPoint t = oracle::qsub(oracle::qp(p[j].c), e);
    m.push_back({t[0], t[1], t[2], oracle::qdot(t, t) - (Q(p[j].w) - Q(p[4].w))});
  }
  return -sgn(oracle::determinant(m));
}

/// An integer-valued double m·2^e with a random 53-bit m (any sign) and e in [0, max_e]:
/// differences of such values span up to 53 + max_e + 1 bits.
template <class Rng>
double wide_integer(Rng& rng, int max_e) {
  std::uniform_int_distribution<std::int64_t> m(-(std::int64_t{1} << 53) + 1,
                                                (std::int64_t{1} << 53) - 1);
  std::uniform_int_distribution<int> e(0, max_e);
  return std::ldexp(static_cast<double>(m(rng)), e(rng));
}

}  // namespace

TEST_CASE("orient3d_exact on 50- to 64-bit integer differences, nearly coplanar or not") {
  const std::uint64_t seed = 0x5eed0101;
  INFO("seed " << seed);
  std::mt19937_64 rng(seed);
  for (int n = 0; n < 4000; ++n) {
    const int max_e = n % 12;
    std::array<Point3, 4> p;
    for (auto& q : p) {
      q = {wide_integer(rng, max_e), wide_integer(rng, max_e), wide_integer(rng, max_e)};
    }
    if (n % 2 == 0) {
      // d near the plane of a, b, c: a + (b − a) + (c − a) rounded, then moved by ulps.
      p[3] = p[1] + (p[2] - p[0]);
      if (n % 4 == 0) p[3] = perturb_point(rng, p[3], 2);
    }
    INFO(std::hexfloat << p[0].x << ' ' << p[0].y << ' ' << p[0].z << " / " << p[3].x << ' '
                       << p[3].y << ' ' << p[3].z);
    REQUIRE(pd::orient3d_exact(p[0], p[1], p[2], p[3]) == oracle::orient3d(p[0], p[1], p[2], p[3]));
  }
}

TEST_CASE("orient3d_exact with one column spanning subnormals to large values") {
  const std::uint64_t seed = 0x5eed0102;
  INFO("seed " << seed);
  std::mt19937_64 rng(seed);
  for (int f = 0; f < static_cast<int>(Family::count_); ++f) {
    const auto fam = static_cast<Family>(f);
    INFO("family " << family_name(fam));
    for (int n = 0; n < 400; ++n) {
      auto p = make_points<4>(rng, fam);
      // One column gets a subnormal, a zero or a huge value in one point: that column
      // alone spans hundreds of binary orders of magnitude.
      const auto col = static_cast<std::size_t>(n % 3);
      const auto row = static_cast<std::size_t>(n / 3 % 4);
      switch (n % 4) {
        case 0: p[row][col] = random_subnormal(rng); break;
        case 1: p[row][col] = std::nextafter(0.0, n % 8 == 1 ? 1.0 : -1.0); break;
        case 2: p[row][col] = random_magnitude(rng, 400, 900); break;
        default: p[row][col] = 0; break;
      }
      REQUIRE(pd::orient3d_exact(p[0], p[1], p[2], p[3]) ==
              oracle::orient3d(p[0], p[1], p[2], p[3]));
      // Scaling one column by a power of two multiplies the determinant by it.
      auto s = p;
      const int k = static_cast<int>(rng() % 200) - 100;
      bool exact = true;
      for (auto& q : s) {
        const double v = std::ldexp(q[col], k);
        exact &= std::ldexp(v, -k) == q[col] && std::isfinite(v);
        q[col] = v;
      }
      if (exact) {
        REQUIRE(pd::orient3d_exact(s[0], s[1], s[2], s[3]) ==
                pd::orient3d_exact(p[0], p[1], p[2], p[3]));
      }
    }
  }
}

TEST_CASE("lifted4_exact on 50- to 64-bit differences with large weights") {
  const std::uint64_t seed = 0x5eed0103;
  INFO("seed " << seed);
  std::mt19937_64 rng(seed);
  int zeros = 0;
  for (int n = 0; n < 3000; ++n) {
    const int max_e = n % 12;
    std::array<WeightedPoint, 5> p;
    for (auto& q : p) {
      q.c = {wide_integer(rng, max_e), wide_integer(rng, max_e), wide_integer(rng, max_e)};
      q.w = 0;
    }
    switch (n % 4) {
      case 0:  // unweighted
        break;
      case 1:  // weights of the size of the squared differences: lifting heights of any sign
        for (auto& q : p) {
          q.w = std::ldexp(wide_integer(rng, 0), 53 + 2 * max_e + static_cast<int>(rng() % 16));
        }
        break;
      case 2: {  // all weights equal (the power test reduces to insphere), one moved
        const double w = std::ldexp(wide_integer(rng, 0), 60 + 2 * max_e);
        for (auto& q : p) q.w = w;
        p[n % 5].w = std::nextafter(w, 0.0);
        break;
      }
      default: {  // exactly orthogonal to the sphere at 0 of weight 0: every height is 0
        for (auto& q : p) {
          q.c = {std::ldexp(wide_integer(rng, 0), -28), std::ldexp(wide_integer(rng, 0), -28),
                 std::ldexp(wide_integer(rng, 0), -28)};
          q.c = {std::round(q.c.x), std::round(q.c.y), std::round(q.c.z)};
          q.w = q.c.x * q.c.x + q.c.y * q.c.y + q.c.z * q.c.z;  // exact: < 2^53
        }
        break;
      }
    }
    const int expected = oracle_lifted4(p);
    zeros += expected == 0;
    INFO("case " << n);
    REQUIRE(pd::lifted4_exact(p[0], p[1], p[2], p[3], p[4]) == expected);
  }
  CHECK(zeros > 0);
}
