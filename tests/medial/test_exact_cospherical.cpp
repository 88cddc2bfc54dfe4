// exactly_coplanar and exactly_cospherical against the exact double predicates, on unions
// whose boundary vertices happen to be exact doubles (every h a rational square, so every
// root is eliminated to a rational), and on twins whose roots are equal (one shared root).

#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

#include "medial/exact_cospherical.hpp"
#include "rstruct/medial/boundary_vertices.hpp"
#include "rstruct/predicates/predicates.hpp"

using namespace rstruct;
using namespace rstruct::medial;

TEST_CASE("exact coplanar and cospherical tests agree with the double predicates on exact points",
          "[medial]") {
  // Balls of radius 3 on a grid of spacing 4: three spheres around a right angle meet in
  // points like (2, 2, ±1), exact doubles, on many common planes and spheres.
  std::vector<Ball> balls;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      for (int k = 0; k < 2; ++k) balls.push_back({{4.0 * i, 4.0 * j, 4.0 * k}, 3.0});
    }
  }
  const auto bv = boundary_vertices_of_union(balls);
  REQUIRE(bv.size() > 20);
  std::mt19937_64 rng(11);
  int coplanar = 0, cospherical = 0;
  for (int trial = 0; trial < 400; ++trial) {
    std::array<const BoundaryVertex*, 5> v{};
    std::array<Point3, 5> p{};
    for (int i = 0; i < 5; ++i) {
      v[i] = &bv[rng() % bv.size()];
      p[i] = v[i]->point;
    }
    const bool plane = predicates::orient3d(p[0], p[1], p[2], p[3]) == Sign::zero;
    CHECK(exactly_coplanar({v[0], v[1], v[2], v[3]}, balls) == plane);
    const bool sphere = predicates::insphere(p[0], p[1], p[2], p[3], p[4]) == Sign::zero;
    CHECK(exactly_cospherical(v, balls) == sphere);
    if (sphere) CHECK(maybe_cospherical(p));
    coplanar += plane ? 1 : 0;
    cospherical += sphere ? 1 : 0;
  }
  // Both outcomes occur, or the test would not test.
  CHECK(coplanar > 10);
  CHECK(coplanar < 390);
  CHECK(cospherical > 10);
  CHECK(cospherical < 390);
}

TEST_CASE("exact cospherical test on irrational points of one sphere", "[medial]") {
  // A ball of radius 2 at the origin and sixteen of radius 1.4 around it: the points of ∂U on
  // the big sphere have irrational coordinates (square roots), the twins of a singular
  // facet share one root. Any five of them are cospherical (the big sphere); a point on
  // small spheres only, put in their place, is generically not.
  std::vector<Ball> balls{{{0, 0, 0}, 2}};
  std::mt19937_64 rng(3);
  std::normal_distribution<double> g(0.0, 1.0);
  for (int i = 0; i < 16; ++i) {
    Vec3 d{g(rng), g(rng), g(rng)};
    d = (2.6 / std::sqrt(dot(d, d))) * d;
    balls.push_back({Point3{0, 0, 0} + d, 1.4});
  }
  const auto bv = boundary_vertices_of_union(balls);
  std::vector<const BoundaryVertex*> on0, off0;
  for (const auto& v : bv) (v.balls[0] == 0 ? on0 : off0).push_back(&v);
  REQUIRE(on0.size() >= 8);
  REQUIRE(!off0.empty());
  // Four points of the big sphere that all lie on another sphere are concyclic (coplanar,
  // and cospherical with anything): skip those quadruples.
  auto share_another = [&](std::size_t i) {
    for (auto x : on0[i]->balls) {
      if (x != 0 && has_ball(*on0[i + 1], x) && has_ball(*on0[i + 2], x) &&
          has_ball(*on0[i + 3], x)) {
        return true;
      }
    }
    return false;
  };
  int checked = 0;
  for (std::size_t i = 0; i + 4 < on0.size(); ++i) {
    if (share_another(i)) continue;
    CHECK(exactly_cospherical({on0[i], on0[i + 1], on0[i + 2], on0[i + 3], on0[i + 4]}, balls));
    CHECK_FALSE(
        exactly_cospherical({on0[i], on0[i + 1], on0[i + 2], on0[i + 3], off0[i % off0.size()]},
                            balls));
    // Four points of a sphere are coplanar only if concyclic: not here.
    CHECK_FALSE(exactly_coplanar({on0[i], on0[i + 1], on0[i + 2], on0[i + 3]}, balls));
    ++checked;
  }
  CHECK(checked >= 4);
}
