// The kd-tree of the pole distance and the covering sets (src/poles/point_tree.hpp).
// Nearest point: exactly the point a linear scan in index order returns, the smallest
// squared distance as rstruct::squared_distance computes it, the smallest index among equal
// ones. Candidates within r: every point the exact predicate puts in the closed ball, each
// once, and no point whose computed squared distance exceeds the inflated radius. Checked
// on random, clustered, duplicate-heavy and tie-heavy sets, at extreme scales, with every
// leaf size, both leaf scans and both kinds of bounds (boxes; boxes and capsules), from
// no start and from a given one, and points crowding a circle (as poles do a torus's
// core circle) queried from off it; trees built on one thread and on several.

#include <rapidcheck/catch.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <numeric>
#include <random>
#include <vector>

#include "poles/point_tree.hpp"
#include "rstruct/predicates/predicates.hpp"

using rstruct::Point3;
using rstruct::poles::detail::PointTree;

namespace {

/// The reference: a scan in index order, strict comparison (the first minimum wins).
std::uint32_t scan_nearest(std::span<const Point3> points, const Point3& q) {
  std::uint32_t best = 0;
  double best_d2 = rstruct::squared_distance(q, points[0]);
  for (std::uint32_t i = 1; i < points.size(); ++i) {
    const double d2 = rstruct::squared_distance(q, points[i]);
    if (d2 < best_d2) {
      best_d2 = d2;
      best = i;
    }
  }
  return best;
}

/// Every query against the scan, from no start and from a start drawn among the points.
void check_queries(std::span<const Point3> points, std::span<const Point3> queries,
                   std::uint32_t leaf, PointTree::Scan scan, PointTree::Bounds bounds,
                   std::mt19937_64& rng) {
  const PointTree tree(points, leaf, scan, 1, bounds);
  std::uniform_int_distribution<std::uint32_t> any(0,
                                                   static_cast<std::uint32_t>(points.size() - 1));
  for (const Point3& q : queries) {
    const std::uint32_t expected = scan_nearest(points, q);
    RC_ASSERT(tree.nearest(q) == expected);
    const std::uint32_t start = any(rng);
    RC_ASSERT(tree.nearest_from(q, start, rstruct::squared_distance(q, points[start])) == expected);
    // The answer itself as the start: kept.
    RC_ASSERT(tree.nearest_from(q, expected, rstruct::squared_distance(q, points[expected])) ==
              expected);
  }
}

/// The candidates within r of q, sorted, against the exact ball: each point once, every
/// point of the closed ball among them, none past the inflated radius.
void check_candidates(const PointTree& tree, std::span<const Point3> points, const Point3& q,
                      double r) {
  std::vector<std::uint32_t> found;
  tree.candidates_within(q, r, found);
  std::sort(found.begin(), found.end());
  RC_ASSERT(std::adjacent_find(found.begin(), found.end()) == found.end());
  const double limit = PointTree::inflated_squared_radius(r);
  std::size_t at = 0;
  for (std::uint32_t i = 0; i < points.size(); ++i) {
    const bool candidate = at < found.size() && found[at] == i;
    at += candidate ? 1 : 0;
    if (rstruct::predicates::side_of_ball(points[i], q, r) != rstruct::Sign::positive) {
      RC_ASSERT(candidate);
    }
    if (candidate) RC_ASSERT(rstruct::squared_distance(q, points[i]) <= limit);
  }
  RC_ASSERT(at == found.size());  // no index out of range
}

enum class Shape { uniform, clustered, grid, line, duplicates, circle };

std::vector<Point3> make_points(Shape shape, std::size_t n, double scale, double offset,
                                std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Point3> points;
  points.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    Point3 p;
    switch (shape) {
      case Shape::uniform:
        p = {u(rng), u(rng), u(rng)};
        break;
      case Shape::clustered: {
        // A few tight clusters far apart: many thin, empty-bordered cells.
        const double c = static_cast<double>(i % 5) * 10.0;
        p = {c + 1e-4 * u(rng), -c + 1e-4 * u(rng), 1e-4 * u(rng)};
        break;
      }
      case Shape::grid: {
        // Integer grid points in a random order: many exactly equal distances.
        std::uniform_int_distribution<int> g(-4, 4);
        p = {double(g(rng)), double(g(rng)), double(g(rng))};
        break;
      }
      case Shape::line:
        p = {u(rng), 0.0, 0.0};
        break;
      case Shape::duplicates: {
        std::uniform_int_distribution<int> g(0, 3);
        p = {double(g(rng)), 0.5 * double(g(rng)), 0.0};
        break;
      }
      case Shape::circle: {
        // As the inner poles of a torus crowd its core circle: a relative spread of 10^-9
        // (many near ties for a query off the circle), every third point exactly on it
        // (as exactly as rounding allows).
        const double angle = 3.14159265358979 * u(rng);
        const double spread = i % 3 == 0 ? 0.0 : 1e-9;
        const double radius = 1.0 + spread * u(rng);
        p = {radius * std::cos(angle), radius * std::sin(angle), spread * u(rng)};
        break;
      }
    }
    points.push_back({offset + scale * p.x, offset + scale * p.y, scale * p.z});
  }
  return points;
}

/// A drawn case: a point set of a drawn shape, scale and offset, a tree's leaf size and
/// scan, and queries: `query_count` new points of the same shape (grid: half-lattice
/// points, the centres of cells and edges, equidistant from several points), five points
/// of the set, 40 points next to points of the set and a point far outside.
struct DrawnCase {
  std::mt19937_64 rng;
  double scale = 1;
  std::vector<Point3> points;
  std::vector<Point3> queries;
  std::uint32_t leaf = 64;
  PointTree::Scan scan = PointTree::Scan::best;
  PointTree::Bounds bounds = PointTree::Bounds::capsules;
};

DrawnCase draw_case(std::size_t query_count) {
  const auto seed = *rc::gen::arbitrary<std::uint64_t>();
  const auto shape = *rc::gen::element(Shape::uniform, Shape::clustered, Shape::grid, Shape::line,
                                       Shape::duplicates, Shape::circle);
  const auto n = *rc::gen::inRange<std::size_t>(1, 700);
  DrawnCase c;
  c.rng.seed(seed);
  // Scales whose squares stay normal, reach the subnormals, or overflow to infinity.
  c.scale = *rc::gen::element(1.0, 1e-3, 250.0, 1e-160, 1e200);
  const double offset = *rc::gen::element(0.0, 1e6, -3.5e8);
  c.leaf = *rc::gen::element(1U, 2U, 5U, 64U);
  c.scan = *rc::gen::element(PointTree::Scan::best, PointTree::Scan::portable);
  c.bounds = *rc::gen::element(PointTree::Bounds::capsules, PointTree::Bounds::capsules,
                               PointTree::Bounds::boxes);
  RC_LOG() << "seed " << seed << "\n";
  c.points = make_points(shape, n, c.scale, offset, c.rng);
  c.queries = make_points(shape, query_count, c.scale, offset, c.rng);
  if (shape == Shape::grid) {
    for (Point3& q : c.queries) q = {q.x + 0.5 * c.scale, q.y + 0.5 * c.scale, q.z};
  }
  if (shape == Shape::circle) {
    // Off the circle, as samples of a torus lie off its core circle: a quarter on its
    // axis (every point of the circle nearly a tie), the rest at distance about 0.7.
    for (std::size_t k = 0; k < c.queries.size(); ++k) {
      Point3& q = c.queries[k];
      q = k % 4 == 0 ? Point3{offset, offset, 0.4 * c.scale}
                     : Point3{offset + 1.5 * (q.x - offset), offset + 1.5 * (q.y - offset),
                              q.z + 0.6 * c.scale};
    }
  }
  for (std::size_t k = 0; k < 5; ++k) c.queries.push_back(c.points[(k * 37) % n]);
  // Points of the set moved a little: each nearest to a query just outside it, which a
  // subtree bound that leaves the point out would skip.
  std::uniform_real_distribution<double> nudge(-1e-6, 1e-6);
  for (std::size_t k = 0; k < 40; ++k) {
    const Point3& p = c.points[(k * 53 + 11) % n];
    c.queries.push_back(
        {p.x + nudge(c.rng) * c.scale, p.y + nudge(c.rng) * c.scale, p.z + nudge(c.rng) * c.scale});
  }
  c.queries.push_back({offset + 1e3 * c.scale, -1e3 * c.scale, 7 * c.scale});
  return c;
}

}  // namespace

TEST_CASE("nearest point: the tree returns the scan's point, ties to the smallest index") {
  rc::prop("tree vs scan", [] {
    DrawnCase c = draw_case(20);
    check_queries(c.points, c.queries, c.leaf, c.scan, c.bounds, c.rng);
  });
}

TEST_CASE("nearest point: equidistant points in different subtrees, smallest index wins") {
  // The eight corners of a cube around the query, listed in every rotation of the order, with
  // many other points so that the corners land in different leaves.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(3.0, 9.0);
  std::vector<Point3> far_points(3000);
  for (Point3& p : far_points) p = {u(rng), u(rng), u(rng)};
  std::vector<Point3> corners;
  for (int k = 0; k < 8; ++k)
    corners.push_back({(k & 1) ? 1.0 : -1.0, (k & 2) ? 1.0 : -1.0, (k & 4) ? 1.0 : -1.0});
  for (int rotation = 0; rotation < 8; ++rotation) {
    std::vector<Point3> points = far_points;
    std::vector<std::uint32_t> corner_index;
    for (int k = 0; k < 8; ++k) {
      // Corners spread through the index range, the first listed one at a random spot.
      const auto at = static_cast<std::size_t>((k * 397 + rotation * 131) % points.size());
      points.insert(points.begin() + static_cast<std::ptrdiff_t>(at), corners[(k + rotation) % 8]);
    }
    std::uint32_t expected = 0xffffffffu;
    for (std::uint32_t i = 0; i < points.size(); ++i) {
      if (std::abs(points[i].x) == 1.0 && std::abs(points[i].y) == 1.0 &&
          std::abs(points[i].z) == 1.0) {
        expected = std::min(expected, i);
      }
    }
    for (const std::uint32_t leaf : {1U, 4U, 64U}) {
      for (const auto scan : {PointTree::Scan::best, PointTree::Scan::portable}) {
        const PointTree tree(points, leaf, scan);
        CHECK(tree.nearest({0, 0, 0}) == expected);
        // From the largest-index corner: the search must still find the smaller one.
        std::uint32_t last_corner = 0;
        for (std::uint32_t i = 0; i < points.size(); ++i) {
          if (std::abs(points[i].x) == 1.0 && std::abs(points[i].y) == 1.0 &&
              std::abs(points[i].z) == 1.0) {
            last_corner = i;
          }
        }
        CHECK(tree.nearest_from({0, 0, 0}, last_corner, 3.0) == expected);
      }
    }
  }
}

TEST_CASE("nearest point: a tree built on several threads answers as the scan does") {
  // Large enough that the first splits build their subtrees on threads of their own (two
  // levels with four threads), with ties (grid) and thin empty-bordered cells (clusters).
  for (const Shape shape : {Shape::uniform, Shape::grid, Shape::clustered}) {
    std::mt19937_64 rng(29 + static_cast<int>(shape));
    const auto points = make_points(shape, 150'000, 1.0, 0.0, rng);
    std::vector<Point3> queries = make_points(shape, 150, 1.0, 0.0, rng);
    if (shape == Shape::grid) {
      for (Point3& q : queries) q = {q.x + 0.5, q.y + 0.5, q.z};
    }
    for (std::size_t k = 0; k < 50; ++k) queries.push_back(points[k * 2999]);
    std::vector<std::uint32_t> expected;
    for (const Point3& q : queries) expected.push_back(scan_nearest(points, q));
    for (const unsigned threads : {2U, 3U, 4U}) {
      for (const std::uint32_t leaf : {1U, 64U}) {
        const PointTree tree(points, leaf, PointTree::Scan::best, threads);
        CHECK(tree.size() == points.size());
        std::size_t wrong = 0;
        for (std::size_t k = 0; k < queries.size(); ++k) {
          wrong += tree.nearest(queries[k]) != expected[k];
          const std::uint32_t start = static_cast<std::uint32_t>(k * 7919 % points.size());
          wrong += tree.nearest_from(queries[k], start,
                                     rstruct::squared_distance(queries[k], points[start])) !=
                   expected[k];
        }
        INFO("shape " << static_cast<int>(shape) << ", threads " << threads << ", leaf " << leaf);
        CHECK(wrong == 0);
      }
    }
  }
}

TEST_CASE("nearest point: queries on the points of a skew line, each point twice") {
  // Points along a line in no axis direction, each listed twice (index k and k + n): a
  // query at a point is at distance 0 from both, and the smaller index must win, from no
  // start and from the larger one. The capsules' segments and radii are computed with
  // rounding, so a subtree holding the point can get a positive computed bound, which
  // capsule_bound's margin must absorb.
  const std::size_t n = 1500;
  for (const double offset : {0.0, 1e3, -7.5e5}) {
    std::vector<Point3> points;
    for (std::size_t k = 0; k < n; ++k) {
      const double s = 0.37 * static_cast<double>(k) + 1e-3 * static_cast<double>(k % 7);
      points.push_back({offset + s, offset + 0.7071067811865476 * s, 0.3183098861837907 * s});
    }
    // The copies in shuffled order: copy n + m is point order[m], so point k's twin is
    // n + (the place of k in order).
    std::mt19937_64 rng(17);
    std::vector<std::uint32_t> order(n);
    std::iota(order.begin(), order.end(), 0U);
    std::shuffle(order.begin(), order.end(), rng);
    std::vector<std::uint32_t> twin(n);
    points.reserve(2 * n);
    for (std::uint32_t m = 0; m < n; ++m) {
      points.push_back(points[order[m]]);
      twin[order[m]] = static_cast<std::uint32_t>(n + m);
    }
    for (const std::uint32_t leaf : {1U, 2U, 5U, 64U}) {
      const PointTree tree(points, leaf);
      std::size_t wrong = 0;
      for (std::uint32_t k = 0; k < n; ++k) {
        wrong += tree.nearest(points[k]) != k;
        wrong += tree.nearest_from(points[k], twin[k], 0.0) != k;
      }
      INFO("offset " << offset << ", leaf " << leaf);
      CHECK(wrong == 0);
    }
  }
}

TEST_CASE("nearest point: degenerate sets") {
  SECTION("one point, and many copies of one point") {
    const std::vector<Point3> one = {{1, 2, 3}};
    CHECK(PointTree(one).nearest({-5, 0, 0}) == 0);
    const std::vector<Point3> same(1000, Point3{1, 2, 3});
    for (const std::uint32_t leaf : {1U, 64U}) {
      const PointTree tree(same, leaf);
      CHECK(tree.nearest({0, 0, 0}) == 0);
      CHECK(tree.nearest_from({0, 0, 0}, 999, rstruct::squared_distance({0, 0, 0}, same[0])) == 0);
    }
  }
  SECTION("a geometric progression: middle splits peel one point at a time") {
    // 1, 1/2, 1/4, ...: the middle of the cell leaves one point on one side at every level,
    // so the tree turns to median splits past its middle-split depth (no deep recursion).
    std::vector<Point3> points;
    for (int k = 0; k < 1000; ++k) points.push_back({std::ldexp(1.0, -k), 0, 0});
    std::mt19937_64 rng(5);
    std::shuffle(points.begin(), points.end(), rng);
    const PointTree tree(points, 1);
    for (const double x : {0.0, 1e-300, 0x1p-500, 0.3, 0.75, 2.0}) {
      CHECK(tree.nearest({x, 0, 0}) == scan_nearest(points, {x, 0, 0}));
    }
  }
  SECTION("no points") {
    const PointTree tree(std::span<const Point3>{});
    CHECK(tree.size() == 0);
    CHECK(tree.nearest_from({0, 0, 0}, 7, 1.0) == 7);
    std::vector<std::uint32_t> found;
    tree.candidates_within({0, 0, 0}, 1.0, found);
    CHECK(found.empty());
  }
}

TEST_CASE("nearest point: the vector scan is used where the processor has AVX2") {
  const std::vector<Point3> points = {{0, 0, 0}, {1, 1, 1}};
  const PointTree portable(points, 64, PointTree::Scan::portable);
  CHECK_FALSE(portable.vectorized());
#if defined(__x86_64__)
  const PointTree best(points, 64, PointTree::Scan::best);
  CHECK(best.vectorized() == (__builtin_cpu_supports("avx2") != 0));
#endif
}

TEST_CASE("candidates within r: every point of the exact ball, nothing past the inflated radius") {
  rc::prop("tree vs exact ball", [] {
    DrawnCase c = draw_case(10);
    const PointTree tree(c.points, c.leaf, c.scan, 1, c.bounds);
    const std::size_t n = c.points.size();
    std::uniform_real_distribution<double> fraction(0.0, 1.0);
    for (const Point3& q : c.queries) {
      // No radius, a random one, a huge one, and the rounded distances of points of the
      // set: points on or next to the sphere (grid: many at once).
      check_candidates(tree, c.points, q, 0.0);
      check_candidates(tree, c.points, q, fraction(c.rng) * 0.5 * c.scale);
      check_candidates(tree, c.points, q, 5e3 * c.scale);
      for (std::size_t k = 0; k < 3; ++k) {
        const auto at = static_cast<std::size_t>(fraction(c.rng) * static_cast<double>(n)) % n;
        const double r = rstruct::distance(q, c.points[at]);  // overflows at the largest scale
        if (std::isfinite(r)) check_candidates(tree, c.points, q, r);
      }
    }
  });
}

TEST_CASE("candidates within r: a tree built on several threads finds the same sets") {
  for (const Shape shape : {Shape::uniform, Shape::grid, Shape::clustered}) {
    std::mt19937_64 rng(41 + static_cast<int>(shape));
    const auto points = make_points(shape, 150'000, 1.0, 0.0, rng);
    const auto queries = make_points(shape, 100, 1.0, 0.0, rng);
    const PointTree one(points, 64, PointTree::Scan::best, 1);
    for (const unsigned threads : {2U, 4U}) {
      const PointTree several(points, 64, PointTree::Scan::best, threads);
      std::size_t differing = 0;
      std::size_t total = 0;
      for (const Point3& q : queries) {
        for (const double r : {0.0, 0.01, 0.1, 0.5}) {
          std::vector<std::uint32_t> a, b;
          one.candidates_within(q, r, a);
          several.candidates_within(q, r, b);
          std::sort(a.begin(), a.end());
          std::sort(b.begin(), b.end());
          differing += a != b;
          total += a.size();
        }
      }
      INFO("shape " << static_cast<int>(shape) << ", threads " << threads);
      CHECK(differing == 0);
      CHECK(total > 0);
    }
  }
}
