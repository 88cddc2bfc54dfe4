#include "rstruct/poles/ball_sets.hpp"

#include <catch2/catch.hpp>
#include <limits>
#include <vector>

#include "rstruct/core/error.hpp"

using rstruct::Point3;
using rstruct::poles::PoleLabel;

TEST_CASE("surface and shrunk balls are centred at the samples with radius factor·D̂") {
  const std::vector<Point3> samples = {{0, 0, 0}, {1e6, 1, 2}};
  const std::vector<double> dhat = {2.0, 0.5};
  const auto surface = rstruct::poles::scaled_sample_balls(samples, dhat, 0.3);
  REQUIRE(surface.size() == 2);
  CHECK(surface[1].c == samples[1]);
  CHECK(surface[0].r == 0.3 * 2.0);
  CHECK(surface[1].r == 0.3 * 0.5);
  const auto shrunk = rstruct::poles::scaled_sample_balls(samples, dhat, 0.03);
  CHECK(shrunk[0].r == 0.03 * 2.0);
}

TEST_CASE("ball-set input errors") {
  const std::vector<Point3> samples = {{0, 0, 0}};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_AS(rstruct::poles::scaled_sample_balls(samples, std::vector<double>{}, 0.3),
                  rstruct::InvalidInput);
  CHECK_THROWS_AS(rstruct::poles::scaled_sample_balls(samples, std::vector<double>{1.0}, -0.3),
                  rstruct::InvalidInput);
  CHECK_THROWS_AS(rstruct::poles::scaled_sample_balls(samples, std::vector<double>{nan}, 0.3),
                  rstruct::InvalidInput);
  rstruct::poles::PoleSet poles;
  CHECK_THROWS_AS(rstruct::poles::inner_polar_balls(poles, -1.0), rstruct::InvalidInput);
  CHECK_THROWS_AS(rstruct::poles::inner_polar_balls(poles, nan), rstruct::InvalidInput);
}

TEST_CASE("DMAT'_in holds exactly the inner poles with radius + eps") {
  rstruct::poles::PoleSet poles;
  poles.centre = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}};
  poles.radius = {1.0, 2.0, 3.0, 4.0};
  poles.label = {PoleLabel::inner, PoleLabel::outer, PoleLabel::unlabelled, PoleLabel::inner};
  const auto balls = rstruct::poles::inner_polar_balls(poles, 0.25);
  REQUIRE(balls.balls.size() == 2);
  CHECK(balls.pole == std::vector<std::uint32_t>{0, 3});
  CHECK(balls.balls[1].c == Point3{3, 0, 0});
  CHECK(balls.balls[1].r == 4.25);
}
