// Metamorphic checks: exact translations, power-of-two scalings and reflections leave the
// combinatorics (finite cells, hidden and merged points) unchanged.
#include <rapidcheck/catch.h>

#include <catch2/catch.hpp>
#include <cmath>

#include "generators.hpp"
#include "rstruct/core/error.hpp"
#include "rstruct/triangulation/regular_triangulation_3.hpp"

namespace {

using rstruct::Point3;
using rstruct::triangulation::RegularTriangulation3;

struct Outcome {
  std::set<rstruct::test::CellKey> cells;
  std::set<std::uint32_t> hidden;
  std::set<std::uint32_t> merged;
  friend bool operator==(const Outcome&, const Outcome&) = default;
};

Outcome outcome(const std::vector<Point3>& p, const std::vector<double>& w) {
  const RegularTriangulation3 t = w.empty() ? RegularTriangulation3(p)
                                            : RegularTriangulation3(p, w);
  Outcome o{rstruct::test::cell_set(t), {}, {}};
  for (const auto& h : t.hidden_points()) o.hidden.insert(h.point);
  for (const auto& d : t.duplicate_points()) o.merged.insert(d.point);
  return o;
}

void draw(int kind, std::uint64_t seed, std::size_t n, std::vector<Point3>& p,
          std::vector<double>& w) {
  using namespace rstruct::test;
  switch (kind) {
    case 0: p = uniform_points(n, seed); w.clear(); break;
    case 1: p = uniform_points(n, seed); w = hiding_weights(n, 0.25, seed + 3); break;
    case 2: p = grid_points(3, 4, 5); w.clear(); break;
    case 3: p = sphere_points(26); w.clear(); break;
    default: p = duplicate_points(n, 15, seed); w = hiding_weights(n, 1.0, seed + 9); break;
  }
}

}  // namespace

TEST_CASE("translation, scaling by powers of two and reflection keep the combinatorics") {
  rc::prop("metamorphic", [] {
    const int kind = *rc::gen::inRange(0, 5);
    const auto seed = *rc::gen::arbitrary<std::uint64_t>();
    const auto n = static_cast<std::size_t>(*rc::gen::inRange(8, 150));
    std::vector<Point3> p;
    std::vector<double> w;
    draw(kind, seed, n, p, w);
    Outcome base;
    try {
      base = outcome(p, w);
    } catch (const rstruct::InvalidInput&) {
      RC_SUCCEED("flat draw");
    }
    // Integer translations below 2^20 are exact on these dyadic coordinates.
    const Point3 shift{double(*rc::gen::inRange(-(1 << 20), 1 << 20)),
                       double(*rc::gen::inRange(-(1 << 20), 1 << 20)),
                       double(*rc::gen::inRange(-(1 << 20), 1 << 20))};
    std::vector<Point3> moved = p;
    for (Point3& q : moved) q += shift;
    RC_ASSERT(outcome(moved, w) == base);
    // Scaling by 2^k multiplies weights by 4^k, exactly.
    const int k = *rc::gen::inRange(-300, 300);
    std::vector<Point3> scaled = p;
    for (Point3& q : scaled) q = {std::ldexp(q.x, k), std::ldexp(q.y, k), std::ldexp(q.z, k)};
    std::vector<double> sw = w;
    for (double& x : sw) x = std::ldexp(x, 2 * k);
    RC_ASSERT(outcome(scaled, sw) == base);
    // A reflection reverses orientations but keeps the cells as vertex sets.
    std::vector<Point3> mirrored = p;
    for (Point3& q : mirrored) q.y = -q.y;
    RC_ASSERT(outcome(mirrored, w) == base);
  });
}
