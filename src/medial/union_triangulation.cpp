#include "medial/union_triangulation.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "rstruct/core/error.hpp"

namespace rstruct::medial {

using triangulation::RegularTriangulation3;

// Weight 0 at 16 times the extent of the balls from their box centre: their
// bisectors with any ball lie beyond the union, so they change neither K nor V.
std::array<Point3, 4> far_points(std::span<const Ball> balls) {
  Box3 box;
  for (const Ball& b : balls) {
    box.add(b.c - Vec3{b.r, b.r, b.r});
    box.add(b.c + Vec3{b.r, b.r, b.r});
  }
  const Point3 mid = 0.5 * (box.lo + box.hi);
  const Vec3 e = box.hi - box.lo;
  const double s = 16.0 * std::max({e.x, e.y, e.z});
  return {mid + s * Vec3{1, 1, 1}, mid + s * Vec3{1, -1, -1}, mid + s * Vec3{-1, 1, -1},
          mid + s * Vec3{-1, -1, 1}};
}

void check_balls(std::span<const Ball> balls) {
  for (std::size_t i = 0; i < balls.size(); ++i) {
    const Ball& b = balls[i];
    if (!is_finite(b.c) || !std::isfinite(b.r) || !(b.r > 0)) {
      throw InvalidInput("medial axis: ball " + std::to_string(i) +
                         " needs a finite centre and a finite positive radius");
    }
  }
}

/// Regular triangulation of the balls and the far points (ids n..n+3).
RegularTriangulation3 ball_triangulation(std::span<const Ball> balls) {
  std::vector<Point3> points;
  std::vector<double> weights;
  points.reserve(balls.size() + 4);
  for (const Ball& b : balls) {
    points.push_back(b.c);
    weights.push_back(b.r * b.r);
  }
  for (const Point3& p : far_points(balls)) {
    points.push_back(p);
    weights.push_back(0.0);
  }
  return RegularTriangulation3(std::move(points), std::move(weights));
}

/// K without the far points (which are isolated vertices of K).
complex::SimplicialComplex ball_complex(const complex::DualComplex& k, std::size_t n) {
  const complex::SimplicialComplex all = k.complex();
  complex::SimplexLists lists;
  for (auto v : all.vertices()) {
    if (v < n) lists.vertices.push_back(v);
  }
  for (const auto& e : all.edges()) {
    if (e[1] < n) lists.edges.push_back(e);
  }
  for (const auto& t : all.triangles()) {
    if (t[2] < n) lists.triangles.push_back(t);
  }
  for (const auto& t : all.tetrahedra()) {
    if (t[3] < n) lists.tetrahedra.push_back(t);
  }
  return complex::SimplicialComplex::from_closed_lists(lists);
}

}  // namespace rstruct::medial
