// The triangulation against its definition on small inputs: the finite cells are exactly
// the positively oriented quadruples whose perturbed orthosphere no other input point is in
// conflict with (n <= 25, random and degenerate, weighted and unweighted).
#include <rapidcheck/catch.h>

#include <catch2/catch.hpp>

#include "generators.hpp"
#include "rstruct/core/error.hpp"
#include "rstruct/predicates/predicates.hpp"
#include "rstruct/triangulation/regular_triangulation_3.hpp"

namespace {

using rstruct::Point3;
using rstruct::Sign;
using rstruct::WeightedPoint;
using rstruct::test::CellKey;
using rstruct::triangulation::RegularTriangulation3;
namespace pr = rstruct::predicates;

struct Input {
  std::vector<Point3> points;
  std::vector<double> weights;  // empty: unweighted
};

std::set<CellKey> brute_force_cells(const Input& in) {
  const auto n = static_cast<std::uint32_t>(in.points.size());
  const auto wp = [&](std::uint32_t i) {
    return WeightedPoint{in.points[i], in.weights.empty() ? 0.0 : in.weights[i]};
  };
  std::set<CellKey> cells;
  for (std::uint32_t a = 0; a < n; ++a) {
    for (std::uint32_t b = a + 1; b < n; ++b) {
      for (std::uint32_t c = b + 1; c < n; ++c) {
        for (std::uint32_t d = c + 1; d < n; ++d) {
          std::uint32_t v[4] = {a, b, c, d};
          const Sign o = pr::orient3d(in.points[a], in.points[b], in.points[c], in.points[d]);
          if (o == Sign::zero) continue;
          if (o == Sign::negative) std::swap(v[0], v[1]);
          bool empty = true;
          for (std::uint32_t e = 0; e < n && empty; ++e) {
            if (e == a || e == b || e == c || e == d) continue;
            empty = pr::power_test_sos(wp(v[0]), wp(v[1]), wp(v[2]), wp(v[3]), wp(e), v[0],
                                       v[1], v[2], v[3], e) == Sign::negative;
          }
          if (empty) cells.insert({a, b, c, d});
        }
      }
    }
  }
  return cells;
}

Input make_input(int kind, std::uint64_t seed, int n) {
  using namespace rstruct::test;
  const auto un = static_cast<std::size_t>(n);
  switch (kind) {
    case 0: return {uniform_points(un, seed), {}};
    case 1: return {uniform_points(un, seed), hiding_weights(un, 0.2, seed + 1)};
    case 2: return {grid_points(2, 3, 4), {}};
    case 3: return {sphere_points(5), {}};  // 24 cospherical points
    case 4: return {sphere_points(6), {}};  // 24 more
    case 5: return {few_plane_points(un, 3, seed), {}};
    case 6: return {duplicate_points(un, 8, seed), {}};
    case 7: {
      std::vector<Point3> p = duplicate_points(un, 8, seed);
      return {p, hiding_weights(un, 1.0, seed + 7)};
    }
    case 8: return {grid_points(2, 3, 4), std::vector<double>(24, 0.25)};
    default: {
      std::vector<Point3> p = sphere_points(6);
      return {p, hiding_weights(p.size(), 2.0, seed)};
    }
  }
}

void check_against_brute_force(const Input& in, bool sort) {
  rstruct::triangulation::TriangulationOptions options;
  options.spatial_sort = sort;
  const RegularTriangulation3 t =
      in.weights.empty() ? RegularTriangulation3(in.points, options)
                         : RegularTriangulation3(in.points, in.weights, options);
  const auto valid = t.is_valid();
  RC_ASSERT(valid.message == std::string());
  const std::set<CellKey> expected = brute_force_cells(in);
  RC_ASSERT(rstruct::test::cell_set(t) == expected);
  // Points in no brute-force cell are exactly the hidden and merged ones.
  std::set<std::uint32_t> absent;
  for (std::uint32_t i = 0; i < in.points.size(); ++i) absent.insert(i);
  for (const CellKey& k : expected) {
    for (const std::uint32_t v : k) absent.erase(v);
  }
  std::set<std::uint32_t> reported;
  for (const auto& h : t.hidden_points()) reported.insert(h.point);
  for (const auto& d : t.duplicate_points()) reported.insert(d.point);
  RC_ASSERT(absent == reported);
}

}  // namespace

TEST_CASE("finite cells equal the brute-force regular triangulation (n <= 25)") {
  // 40 cases per property: each brute force is O(n^4) predicate calls.
  rc::prop("random and degenerate inputs, BRIO order", [] {
    const int kind = *rc::gen::inRange(0, 10);
    const auto seed = *rc::gen::arbitrary<std::uint64_t>();
    const int n = *rc::gen::inRange(5, 26);
    RC_TAG(kind);
    const Input in = make_input(kind, seed, n);
    try {
      check_against_brute_force(in, true);
    } catch (const rstruct::InvalidInput&) {
      // Only when the drawn points do not span R^3 (few-plane, duplicates).
      RC_ASSERT(brute_force_cells(in).empty());
    }
  });
  rc::prop("random and degenerate inputs, input order", [] {
    const int kind = *rc::gen::inRange(0, 10);
    const auto seed = *rc::gen::arbitrary<std::uint64_t>();
    const int n = *rc::gen::inRange(5, 26);
    const Input in = make_input(kind, seed, n);
    try {
      check_against_brute_force(in, false);
    } catch (const rstruct::InvalidInput&) {
      RC_ASSERT(brute_force_cells(in).empty());
    }
  });
}

TEST_CASE("regression: the 8 corners of a cube (cospherical, one box)") {
  std::vector<Point3> p = rstruct::test::sphere_points(3);
  REQUIRE(p.size() == 8);
  const RegularTriangulation3 t(p);
  CHECK(t.is_valid().message == "");
  CHECK(t.number_of_finite_cells() >= 5);
  CHECK(rstruct::test::cell_set(t) == brute_force_cells({p, {}}));
}
