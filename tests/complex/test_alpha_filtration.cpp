#include "rstruct/complex/alpha_filtration.hpp"

#include <rapidcheck/catch.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "complex/rational_geometry.hpp"
#include "rstruct/complex/dual_complex.hpp"
#include "rstruct/complex/homology.hpp"
#include "rstruct/complex/orthosphere_predicates.hpp"
#include "rstruct/core/error.hpp"
#include "rstruct/triangulation/regular_triangulation_3.hpp"

using namespace rstruct;
using namespace rstruct::complex;
using testing::BallSet;
using testing::triangulate;
using testing::Q;

namespace {

/// |value − exact| ≤ 2^-28 |exact|, and the same sign (checked in rationals).
bool close_with_sign(double value, const Q& exact) {
  if (sgn(Q(value)) != sgn(exact)) return false;
  const Q error = abs(Q(value) - exact);
  return error <= abs(exact) / Q(mpz_class(1) << 28);
}

std::vector<VertexId> vertices_of(const SimplicialComplex& r, int d, SimplexIndex i) {
  switch (d) {
    case 0: return {r.vertices()[i]};
    case 1: return {r.edges()[i].begin(), r.edges()[i].end()};
    case 2: return {r.triangles()[i].begin(), r.triangles()[i].end()};
    default: return {r.tetrahedra()[i].begin(), r.tetrahedra()[i].end()};
  }
}

/// x rounded to a multiple of 2^-20.
double on_grid(double x) { return std::ldexp(std::round(std::ldexp(x, 20)), -20); }

/// Thresholds t (multiples of 2^-20, |t| < 2^30) between the distinct values and beyond
/// them, each further than a relative 10^-6 from every value, so that the values' rounding
/// cannot move one across it. With weights on the same grid, every w + t is exact: the
/// grown balls have exactly the power diagram of the given ones.
std::vector<double> thresholds(const AlphaFiltration& f) {
  std::vector<double> values;
  for (int d = 0; d < 4; ++d) values.insert(values.end(), f.alpha[d].begin(), f.alpha[d].end());
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  std::vector<double> candidates = {on_grid(values.front() - 1.0), on_grid(values.back() + 1.0)};
  for (std::size_t i = 0; i + 1 < values.size(); ++i) {
    candidates.push_back(on_grid(values[i] + (values[i + 1] - values[i]) / 2));
  }
  std::vector<double> out;
  for (const double t : candidates) {
    if (!(std::fabs(t) < 0x1p30)) continue;
    const auto next = std::lower_bound(values.begin(), values.end(), t);
    const bool clear_above = next == values.end() || *next - t > 1e-6 * std::max(1.0, std::fabs(*next));
    const bool clear_below =
        next == values.begin() || t - *(next - 1) > 1e-6 * std::max(1.0, std::fabs(*(next - 1)));
    if (clear_above && clear_below) out.push_back(t);
  }
  return out;
}

}  // namespace

TEST_CASE("orthosphere_power_value: the exact value within 2^-28, with its sign") {
  rc::prop("random simplices of 1 to 4 weighted points", [] {
    const int k = *rc::gen::inRange(1, 5);
    const double scale = std::ldexp(1.0, *rc::gen::inRange(-30, 30));
    std::vector<WeightedPoint> s;
    for (int i = 0; i < k; ++i) {
      const auto coord = [&] { return *rc::gen::inRange(-1000000, 1000000) * scale / 1e6; };
      const double r = *rc::gen::inRange(0, 1000000) * scale / 1e6;
      s.push_back({{coord(), coord(), coord()}, r * r});
    }
    std::vector<testing::QPoint> q;
    for (const auto& p : s) q.push_back(testing::to_q(p));
    const auto z = testing::orthocenter(q);
    RC_PRE(z.has_value());
    RC_ASSERT(close_with_sign(orthosphere_power_value(s), testing::power(*z, q[0])));
  });
  SECTION("near tangency the value keeps its sign and is not flushed to zero") {
    // Balls of radius 1 at distance 2 + δ (two), and three or four balls with a third
    // and fourth tangent-ish one, at scales 2^-300 … 2^300 (weights scaled by its
    // square): values far smaller than the terms, decided by the exact stage.
    for (const int scale : {-300, -40, 0, 40, 300}) {
      const double f = std::ldexp(1.0, scale);
      for (int e = 1; e <= 60; ++e) {
        for (const double sign : {1.0, -1.0}) {
          const double delta = sign * std::ldexp(1.0, -e);
          const WeightedPoint a{{0, 0, 0}, f * f};
          const WeightedPoint b{{(2 + delta) * f, 0, 0}, f * f};
          const WeightedPoint c{{f, (1 + delta) * f, 0.25 * f}, 1.0625 * f * f};
          const WeightedPoint d{{f, 0.5 * f, (1 - delta) * f}, 1.25 * f * f};
          for (const std::vector<WeightedPoint>& s : {std::vector<WeightedPoint>{a, b},
                                                      std::vector<WeightedPoint>{a, b, c},
                                                      std::vector<WeightedPoint>{a, b, c, d}}) {
            std::vector<testing::QPoint> q;
            for (const auto& p : s) q.push_back(testing::to_q(p));
            const auto z = testing::orthocenter(q);
            if (!z) continue;
            CHECK(close_with_sign(orthosphere_power_value(s), testing::power(*z, q[0])));
          }
        }
      }
    }
    // Flat tetrahedra (height 2^-h: the filtered determinant is not accurate) with weights
    // whose lowest bits lie far below the coordinates' squares (they set the exact
    // stage's integer scale).
    for (int h = 20; h <= 50; h += 10) {
      for (const int t : {60, 90, 150, 250}) {
        const double tiny = std::ldexp(1.0, -t);
        const std::vector<WeightedPoint> s = {{{0, 0, 0}, 3 * tiny},
                                              {{1, 0, 0}, 5 * tiny},
                                              {{0, 1, 0}, 7 * tiny},
                                              {{1, 1, std::ldexp(1.0, -h)}, 11 * tiny}};
        std::vector<testing::QPoint> q;
        for (const auto& p : s) q.push_back(testing::to_q(p));
        CHECK(close_with_sign(orthosphere_power_value(s), testing::power(*testing::orthocenter(q), q[0])));
      }
    }
    const std::vector<WeightedPoint> touching = {{{0, 0, 0}, 1.0}, {{2, 0, 0}, 1.0}};
    CHECK(orthosphere_power_value(touching) == 0.0);
    // Four balls through one point (the origin): exactly 0.
    const std::vector<WeightedPoint> common = {
        {{1, 0, 0}, 1.0}, {{0, 2, 0}, 4.0}, {{0, 0, 3}, 9.0}, {{1, 1, 1}, 3.0}};
    CHECK(orthosphere_power_value(common) == 0.0);
  }
  SECTION("a single ball: −w") {
    CHECK(orthosphere_power_value(std::vector<WeightedPoint>{{{1, 2, 3}, 2.5}}) == -2.5);
  }
  SECTION("affinely dependent points are rejected") {
    const std::vector<WeightedPoint> flat = {
        {{0, 0, 0}, 1.0}, {{1, 0, 0}, 1.0}, {{0, 1, 0}, 1.0}, {{1, 1, 0}, 1.0}};
    CHECK_THROWS_AS(orthosphere_power_value(flat), InvalidInput);
  }
}

TEST_CASE("α filtration: every value is the minimum of the power over the dual face") {
  for (const int lo : {1, 500}) {
    rc::prop(lo == 1 ? "random balls" : "large overlapping balls", [lo] {
      BallSet set = testing::random_ball_set(lo);
      RC_PRE(triangulate(set));
      const AlphaFiltration f = alpha_filtration(set.points, set.cells);
      const SimplicialComplex& r = f.triangulation;
      bool some_attached = false;
      for (int d = 0; d < 4; ++d) {
        RC_ASSERT(f.alpha[d].size() == r.size(d));
        for (SimplexIndex i = 0; i < r.size(d); ++i) {
          const auto exact = testing::brute_force_alpha(set.exact, vertices_of(r, d, i));
          RC_ASSERT(exact.has_value());
          RC_ASSERT(close_with_sign(f.alpha[d][i], *exact));
          if (d < 3 && f.attached[d][i]) some_attached = true;
        }
      }
      RC_CLASSIFY(some_attached, "attached simplices");
    });
  }
}

TEST_CASE("α filtration: K at 0 exactly, K_t at thresholds between values, faces first") {
  for (const int lo : {1, 500}) {
    rc::prop(lo == 1 ? "random balls" : "large overlapping balls", [lo] {
      BallSet set = testing::random_ball_set(lo);
      for (auto& p : set.points) p.w = on_grid(p.w);
      RC_PRE(triangulate(set));
      const AlphaFiltration f = alpha_filtration(set.points, set.cells);
      RC_ASSERT(f.sublevel(0.0) == dual_complex(set.points, set.cells).in_k);
      const std::vector<double> ts = thresholds(f);
      RC_ASSERT(!ts.empty());
      RC_CLASSIFY(ts.size() > 10, "more than 10 thresholds");
      for (const double t : ts) {
        std::vector<WeightedPoint> grown = set.points;
        for (auto& p : grown) p.w += t;  // exact (see thresholds())
        // Growing every weight by t keeps the regular triangulation (same cells).
        RC_ASSERT(f.sublevel(t) == dual_complex(grown, set.cells).in_k);
      }
      // Faces never after cofaces, in values and in order().
      const SimplicialComplex& r = f.triangulation;
      const auto order = f.order();
      RC_ASSERT(order.size() == r.total_size());
      std::array<std::vector<std::size_t>, 4> position;
      for (int d = 0; d < 4; ++d) position[d].assign(r.size(d), 0);
      for (std::size_t k = 0; k < order.size(); ++k) position[order[k].first][order[k].second] = k;
      for (int d = 1; d < 4; ++d) {
        for (SimplexIndex i = 0; i < r.size(d); ++i) {
          for (const SimplexIndex face : r.faces(d, i)) {
            RC_ASSERT(f.alpha[d - 1][face] <= f.alpha[d][i]);
            RC_ASSERT(position[d - 1][face] < position[d][i]);
          }
        }
      }
    });
  }
}

TEST_CASE("α filtration of a ring of balls: points, a loop, then a disc") {
  // Eight balls of radius 1.7 on a circle of radius 4, alternating heights: at α = 0 a
  // loop (neighbours overlap); far below, only the empty set; far above, contractible.
  std::vector<Point3> centres;
  const double pi = std::acos(-1.0);
  for (int i = 0; i < 8; ++i) {
    const double a = 2 * pi * i / 8;
    centres.push_back({4 * std::cos(a), 4 * std::sin(a), (i % 2 ? 0.05 : -0.05) * (1 + 0.1 * i)});
  }
  const triangulation::RegularTriangulation3 rt(centres, std::vector<double>(8, 1.7 * 1.7));
  const AlphaFiltration f = alpha_filtration(rt);
  const auto complex_at = [&](double t) { return f.triangulation.subcomplex(f.sublevel(t)); };
  CHECK(complex_at(-1.7 * 1.7 - 1e-9).empty());
  // Every ball is unattached (its centre lies in its own power cell): it enters at −r².
  for (std::size_t v = 0; v < f.alpha[0].size(); ++v) {
    CHECK_FALSE(f.attached[0][v]);
    CHECK(f.alpha[0][v] == -1.7 * 1.7);
  }
  CHECK(betti_numbers(complex_at(-1.7 * 1.7)) == BettiNumbers{{8, 0, 0, 0}});
  CHECK(betti_numbers(complex_at(0.0)) == BettiNumbers{{1, 1, 0, 0}});
  CHECK(betti_numbers(complex_at(1e6)) == BettiNumbers{{1, 0, 0, 0}});
  CHECK(f.sublevel(0.0) == dual_complex(rt).in_k);
}

TEST_CASE("α filtration: the same values and flags on any number of threads") {
  // 3,000 random balls (about 10^5 simplices, many chunks per dimension), radii such that
  // K is neither empty nor everything.
  std::mt19937_64 rng(26);
  std::uniform_real_distribution<double> coord(-1.0, 1.0);
  std::uniform_real_distribution<double> radius(0.01, 0.08);
  std::vector<Point3> centres;
  std::vector<double> weights;
  for (int i = 0; i < 3000; ++i) {
    centres.push_back({coord(rng), coord(rng), coord(rng)});
    const double r = radius(rng);
    weights.push_back(r * r);
  }
  const triangulation::RegularTriangulation3 rt(centres, weights);
  const AlphaFiltration one = alpha_filtration(rt, 1);
  REQUIRE(one.triangulation.total_size() > 50000);
  for (const unsigned threads : {2u, 3u}) {
    const AlphaFiltration many = alpha_filtration(rt, threads);
    CHECK(many.alpha == one.alpha);  // bit for bit
    CHECK(many.attached == one.attached);
  }
  const auto k = one.sublevel(0.0);
  const auto counts = dual_complex(rt).counts();
  for (int d = 0; d < 4; ++d) {
    CHECK(static_cast<std::size_t>(std::count(k[d].begin(), k[d].end(), true)) == counts[d]);
  }
  CHECK(counts[1] > 0);
  CHECK(counts[1] < one.triangulation.size(1));
}

TEST_CASE("α filtration: cells naming missing points are rejected") {
  const std::vector<WeightedPoint> pts = {{{0, 0, 0}, 1.0}, {{1, 0, 0}, 1.0}, {{0, 1, 0}, 1.0}};
  const std::vector<Tetrahedron> cells = {{0, 1, 2, 3}};
  CHECK_THROWS_AS(alpha_filtration(pts, cells), InvalidInput);
}
