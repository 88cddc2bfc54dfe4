// Poles from a tetrahedron soup (hand-made configurations) and the circumsphere construction.

#include "rstruct/poles/pole_set.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <gmpxx.h>
#include <random>
#include <string>
#include <vector>

#include "poles/circumsphere.hpp"
#include "rstruct/core/error.hpp"

using rstruct::Point3;
using rstruct::poles::compute_poles;
using rstruct::poles::kNoPole;
using rstruct::poles::PoleSet;
using rstruct::poles::TetrahedronSoup;
using Tet = std::array<std::uint32_t, 4>;

namespace {

/// Sample 0 at the origin; vertex k·i (i = 1..3) at ±k times a unit vector. The tetrahedron
/// (0, k·e1, k·e2, k·e3) has circumcentre (k/2)(1, 1, 1).
struct Star {
  std::vector<Point3> vertices{{0, 0, 0}};
  std::vector<Tet> tets;
  std::uint32_t add(const Point3& p) {
    vertices.push_back(p);
    return static_cast<std::uint32_t>(vertices.size() - 1);
  }
  void add_corner_tet(double k) {
    const auto a = add({k, 0, 0}), b = add({0, k, 0}), c = add({0, 0, k});
    tets.push_back({0, a, b, c});
  }
};

/// 300 random vertices in a cube and 3000 random tetrahedra over them (four distinct
/// vertices; their ids listed increasing if `sorted`).
std::vector<Tet> random_tetrahedra(std::mt19937_64& rng, std::vector<Point3>& vertices,
                                   bool sorted) {
  std::uniform_real_distribution<double> coordinate(-1, 1);
  std::uniform_int_distribution<std::uint32_t> vertex(0, 299);
  vertices.resize(300);
  for (Point3& p : vertices) p = {coordinate(rng), coordinate(rng), coordinate(rng)};
  std::vector<Tet> tets;
  while (tets.size() < 3000) {
    Tet t{vertex(rng), vertex(rng), vertex(rng), vertex(rng)};
    Tet s = t;
    std::sort(s.begin(), s.end());
    if (s[0] != s[1] && s[1] != s[2] && s[2] != s[3]) tets.push_back(sorted ? s : t);
  }
  return tets;
}

/// Every field of two pole sets.
void check_same_poles(const PoleSet& many, const PoleSet& one) {
  CHECK(many.tet == one.tet);
  CHECK(many.owner == one.owner);
  CHECK(many.sites == one.sites);
  CHECK(many.sample_poles == one.sample_poles);
  CHECK(many.representative == one.representative);
  CHECK(many.centre == one.centre);
  CHECK(many.radius == one.radius);
  CHECK(many.label == one.label);
}

}  // namespace

TEST_CASE("first pole is the largest incident circumball, second the largest opposite one") {
  Star star;
  star.add_corner_tet(2);   // centre (1, 1, 1)
  star.add_corner_tet(-2);  // centre (−1, −1, −1)
  star.add_corner_tet(4);   // centre (2, 2, 2): the farthest, p⁺
  star.add_corner_tet(-1);  // centre (−.5, −.5, −.5): opposite but nearer
  const TetrahedronSoup soup{star.vertices, 1, star.tets, {}};
  const PoleSet poles = compute_poles(soup);
  REQUIRE(poles.is_valid());
  REQUIRE(poles.size() == 2);  // only tetrahedra that are somebody's pole become poles
  const auto [first, second] = poles.sample_poles[0];
  REQUIRE(first != kNoPole);
  REQUIRE(second != kNoPole);
  CHECK(poles.tet[first] == 2);
  CHECK(poles.tet[second] == 1);
  CHECK(poles.centre[first] == Point3{2, 2, 2});
  CHECK(poles.centre[second] == Point3{-1, -1, -1});
  CHECK(poles.radius[first] == Approx(std::sqrt(12.0)).epsilon(1e-15));
  CHECK(poles.owner[first] == 0);
  CHECK(poles.is_box_pole(first));  // its other vertices are extra sites (index >= 1)
}

TEST_CASE("a sample with no vertex beyond its first pole has no second pole") {
  Star star;
  star.add_corner_tet(2);
  star.add_corner_tet(3);
  const PoleSet poles = compute_poles({star.vertices, 1, star.tets, {}});
  REQUIRE(poles.is_valid());
  CHECK(poles.sample_poles[0][0] != kNoPole);
  CHECK(poles.sample_poles[0][1] == kNoPole);
}

TEST_CASE("a pole shared by several samples is stored once; duplicates share poles") {
  // Four samples forming one tetrahedron; each sample's only incident cell is that one.
  const std::vector<Point3> vertices = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0, 0, 2}, {0, 0, 0}};
  const std::vector<Tet> tets = {{0, 1, 2, 3}};
  const std::vector<std::uint32_t> representative = {0, 1, 2, 3, 0};
  const PoleSet poles = compute_poles({vertices, 5, tets, representative});
  REQUIRE(poles.is_valid());
  REQUIRE(poles.size() == 1);
  for (std::uint32_t s = 0; s < 5; ++s) CHECK(poles.sample_poles[s][0] == 0);
  CHECK(poles.sample_poles[4] == poles.sample_poles[0]);
  CHECK(poles.owner[0] == 0);
  CHECK(poles.representative[4] == 0);
}

TEST_CASE("box sites get no poles, and poles touching them are box poles") {
  const std::vector<Point3> vertices = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0, 0, 2}};
  const std::vector<Tet> tets = {{0, 1, 2, 3}};
  const PoleSet poles = compute_poles({vertices, 2, tets, {}});  // vertices 2, 3 are sites
  REQUIRE(poles.is_valid());
  CHECK(poles.sample_poles.size() == 2);
  CHECK(poles.is_box_pole(0));
}

TEST_CASE("soup errors") {
  const std::vector<Point3> vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const std::vector<Tet> bad = {{0, 1, 2, 7}};
  CHECK_THROWS_AS(compute_poles({vertices, 4, bad, {}}), rstruct::InvalidInput);
  const std::vector<Tet> good = {{0, 1, 2, 3}};
  CHECK_THROWS_AS(compute_poles({vertices, 5, good, {}}), rstruct::InvalidInput);
  const std::vector<std::uint32_t> rep = {1, 2, 2, 3};  // 0 → 1, but 1 is not its own
  CHECK_THROWS_AS(compute_poles({vertices, 4, good, rep}), rstruct::InvalidInput);
  const std::vector<Point3> flat = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  CHECK_THROWS_AS(compute_poles({flat, 4, good, {}}), rstruct::InternalError);
}

TEST_CASE("circumsphere centres are equidistant from the four vertices, slivers included") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 2000; ++trial) {
    const double offset = trial % 2 == 0 ? 0.0 : 1e6;
    Point3 p[4];
    for (auto& q : p) q = {offset + u(rng), offset + u(rng), u(rng)};
    if (trial % 4 >= 2) p[3].z = p[0].z + 1e-13 * u(rng);  // nearly flat: exact path
    if (trial % 4 >= 2) { p[1].z = p[0].z; p[2].z = p[0].z; }
    if (p[3].z == p[0].z) continue;  // exactly flat
    const auto cs = rstruct::poles::detail::circumsphere(p[0], p[1], p[2], p[3]);
    // Measure |c − p_i|² − |c − p_0|² exactly for the rounded centre c = p0 + offset.
    mpq_class c[3];
    for (int i = 0; i < 3; ++i) c[i] = mpq_class(p[0][i]) + mpq_class(cs.offset[i]);
    auto d2 = [&](const Point3& q) {
      mpq_class s = 0;
      for (int i = 0; i < 3; ++i) s += (c[i] - q[i]) * (c[i] - q[i]);
      return s;
    };
    const mpq_class r2 = d2(p[0]);
    for (int i = 1; i < 4; ++i) {
      const double rel = std::fabs(mpq_class(d2(p[i]) - r2).get_d()) / r2.get_d();
      INFO("trial " << trial << " vertex " << i);
      // Rounding the centre to doubles moves each distance by about ulp(|c|)·R.
      const double ulp_c = std::ldexp(1.0, std::ilogb(std::fabs(offset) + std::sqrt(r2.get_d())) - 52);
      CHECK(rel <= 1e-6 + 8 * ulp_c / std::sqrt(r2.get_d()));
    }
  }
}

TEST_CASE("the poles do not depend on the threads choosing them") {
  // Random (non-Delaunay, non-flat) tetrahedra over 300 vertices, 200 of them samples.
  std::mt19937_64 rng(17);
  std::vector<Point3> vertices;
  const std::vector<Tet> tets = random_tetrahedra(rng, vertices, false);
  const TetrahedronSoup soup{vertices, 200, tets, {}};
  const PoleSet one = compute_poles(soup, 1);
  REQUIRE(one.is_valid());
  REQUIRE(one.size() > 100);
  for (const unsigned threads : {2u, 3u}) {
    // One range of tetrahedra per thread.
    check_same_poles(compute_poles(soup, threads, 1), one);
  }
}

TEST_CASE("large soups: the same poles on one thread and on several; the first bad tetrahedron") {
  // Large enough that the checks and the per-sample loops run in several chunks.
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> coordinate(-1, 1);
  std::uniform_int_distribution<std::uint32_t> vertex(0, 39'999);
  std::vector<Point3> vertices(40'000);
  for (Point3& p : vertices) p = {coordinate(rng), coordinate(rng), coordinate(rng)};
  std::vector<Tet> tets;
  while (tets.size() < 200'000) {
    Tet t{vertex(rng), vertex(rng), vertex(rng), vertex(rng)};
    Tet sorted_ids = t;
    std::sort(sorted_ids.begin(), sorted_ids.end());
    if (std::adjacent_find(sorted_ids.begin(), sorted_ids.end()) == sorted_ids.end()) {
      tets.push_back(t);
    }
  }
  const TetrahedronSoup soup{vertices, 35'000, tets, {}};
  const PoleSet one = compute_poles(soup, 1);
  REQUIRE(one.is_valid());
  for (const unsigned threads : {2u, 4u}) {
    check_same_poles(compute_poles(soup, threads), one);
  }
  // Two tetrahedra with a vertex out of range, in different chunks: the first is named.
  std::vector<Tet> bad = tets;
  bad[150'000][2] = 40'000;
  bad[70'000][1] = 40'001;
  for (const unsigned threads : {1u, 2u, 4u}) {
    try {
      (void)compute_poles({vertices, 35'000, bad, {}}, threads);
      FAIL("no error for a vertex out of range");
    } catch (const rstruct::InvalidInput& e) {
      CHECK(std::string(e.what()).find("tetrahedron 70000 has vertex 40001 out of range") !=
            std::string::npos);
    }
  }
}

TEST_CASE("a tetrahedron that is one sample's p⁺ and a smaller sample's p⁻ is one pole") {
  // Random tetrahedra: poles chosen by several samples in different roles happen.
  std::size_t crossed = 0;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    std::mt19937_64 rng(seed);
    std::vector<Point3> vertices;
    const std::vector<Tet> tets = random_tetrahedra(rng, vertices, seed % 2 == 0);
    const TetrahedronSoup soup{vertices, 300, tets, {}};
    for (const unsigned threads : {1u, 2u}) {
      const PoleSet poles = compute_poles(soup, threads, 1);
      REQUIRE(poles.is_valid());  // among others: no tetrahedron twice
      // Every pole is the choice of its owner, in the same role or the other.
      std::vector<int> first_of(poles.size(), 0), second_of(poles.size(), 0);
      for (std::uint32_t s = 0; s < 300; ++s) {
        const auto [a, b] = poles.sample_poles[s];
        if (a != kNoPole) ++first_of[a];
        if (b != kNoPole) ++second_of[b];
      }
      for (std::size_t p = 0; p < poles.size(); ++p) {
        CHECK(first_of[p] + second_of[p] > 0);
        if (first_of[p] > 0 && second_of[p] > 0) ++crossed;
      }
    }
  }
  CHECK(crossed > 0);
}

TEST_CASE("the poles do not depend on the order of the soup; ties go to the smallest ids") {
  // A parallel Delaunay triangulation numbers its cells by timing: the same tetrahedra in
  // another order must give the same poles, with the same numbers.
  std::mt19937_64 rng(23);
  std::vector<Point3> vertices;
  std::vector<Tet> tets = random_tetrahedra(rng, vertices, true);
  // Exact ties: the same four vertices listed twice (the second copy wins no tie).
  for (int i = 0; i < 50; ++i) tets.push_back(tets[static_cast<std::size_t>(i)]);
  const TetrahedronSoup soup{vertices, 200, tets, {}};
  const PoleSet one = compute_poles(soup, 1);
  REQUIRE(one.is_valid());
  REQUIRE(one.size() > 100);
  for (std::size_t p = 0; p < one.size(); ++p) CHECK(one.tet[p] < 3000);  // first copies
  for (const unsigned threads : {2u, 3u}) {  // the copies in a later range than the originals
    const PoleSet many = compute_poles(soup, threads, 1);
    CHECK(many.tet == one.tet);
    CHECK(many.sample_poles == one.sample_poles);
  }
  for (std::size_t p = 1; p < one.size(); ++p) CHECK(one.owner[p - 1] <= one.owner[p]);
  for (int round = 0; round < 3; ++round) {
    std::vector<Tet> shuffled = tets;
    std::shuffle(shuffled.begin(), shuffled.end(), rng);
    const TetrahedronSoup other{vertices, 200, shuffled, {}};
    const PoleSet many = compute_poles(other, 2, 1);  // two ranges of tetrahedra
    REQUIRE(many.size() == one.size());
    CHECK(many.owner == one.owner);
    CHECK(many.sites == one.sites);
    CHECK(many.sample_poles == one.sample_poles);
    CHECK(many.centre == one.centre);
    CHECK(many.radius == one.radius);
  }
}

TEST_CASE("a tie in the circumradius goes to the tetrahedron with the smaller sorted ids") {
  // Sample 0 at the origin and two mirrored corner tetrahedra: equal circumradii (exactly:
  // the offsets are (±1/2, ±1/2, ±1/2)), listed in either order.
  Star star;
  star.add_corner_tet(1);   // vertices 1, 2, 3
  star.add_corner_tet(-1);  // vertices 4, 5, 6
  const Tet low = star.tets[0];
  const Tet high = star.tets[1];
  for (const std::vector<Tet>& tets : {std::vector<Tet>{low, high}, std::vector<Tet>{high, low}}) {
    const TetrahedronSoup soup{star.vertices, 1, tets, {}};
    const PoleSet poles = compute_poles(soup, 1);
    REQUIRE(poles.sample_poles[0][0] != kNoPole);
    CHECK(poles.sites[poles.sample_poles[0][0]] == low);
    REQUIRE(poles.sample_poles[0][1] != kNoPole);
    CHECK(poles.sites[poles.sample_poles[0][1]] == high);
  }
}
