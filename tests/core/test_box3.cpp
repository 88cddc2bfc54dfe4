// Box3::add: the bounding box of the points added, a NaN coordinate leaving its axis as it
// was (the box of the finite coordinates), infinities taken as they come.

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "rstruct/geometry/vec3.hpp"

using rstruct::Box3;
using rstruct::Point3;

TEST_CASE("Box3::add bounds the points added") {
  Box3 box;
  CHECK(box.empty());
  box.add({1, -2, 3});
  CHECK_FALSE(box.empty());
  CHECK(box.lo == Point3{1, -2, 3});
  CHECK(box.hi == Point3{1, -2, 3});
  box.add({-4, 5, 0.5});
  box.add({0, 0, 7});
  CHECK(box.lo == Point3{-4, -2, 0.5});
  CHECK(box.hi == Point3{1, 5, 7});
  CHECK(box.max_extent() == 7.0);
}

TEST_CASE("Box3::add ignores NaN coordinates and keeps infinities") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Box3 box;
  box.add({nan, 1, nan});  // first point: only y is bounded
  CHECK(std::isinf(box.lo.x));
  CHECK(box.lo.x > 0);  // still the empty +inf
  CHECK(box.lo.y == 1.0);
  CHECK(box.hi.y == 1.0);
  box.add({2, nan, -3});
  box.add({-1, 4, nan});
  CHECK(box.lo == Point3{-1, 1, -3});
  CHECK(box.hi == Point3{2, 4, -3});
  box.add({HUGE_VAL, 0, -HUGE_VAL});
  CHECK(box.hi.x == HUGE_VAL);
  CHECK(box.lo.z == -HUGE_VAL);
  CHECK(box.lo.y == 0.0);
}
