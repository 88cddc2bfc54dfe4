#include "rstruct/poles/ball_parameters.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "rstruct/core/error.hpp"

using rstruct::InvalidInput;
using rstruct::poles::BallParameters;
using rstruct::poles::check_ball_parameters;

TEST_CASE("parameters inside the guaranteed ranges give no warning") {
  for (const double rho : {0.24, 0.3, 0.56}) {
    for (const double rho_tilde : {0.0, 0.01, 0.03}) {
      const auto check = check_ball_parameters({rho, rho_tilde, 0.0, false});
      CHECK(check.warnings.empty());
      CHECK(check.topology_guarantee_holds());
    }
  }
}

TEST_CASE("rho outside [0.24, 0.56] warns that the guarantee is lost") {
  for (const double rho : {0.2399, 0.5601, 0.05, 2.0}) {
    const auto check = check_ball_parameters({rho, 0.01, 0.0, false});
    REQUIRE(check.warnings.size() == 1);
    CHECK(check.warnings[0].find("rho") != std::string::npos);
    CHECK(check.warnings[0].find("Lemma 5.6") != std::string::npos);
    CHECK_FALSE(check.topology_guarantee_holds());
  }
}

TEST_CASE("rho_tilde above 0.03 or not below rho warns") {
  const auto above = check_ball_parameters({0.3, 0.05, 0.0, false});
  REQUIRE(above.warnings.size() == 1);
  CHECK(above.warnings[0].find("Theorem 6.1") != std::string::npos);
  CHECK_FALSE(above.topology_guarantee_holds());
  const auto both = check_ball_parameters({0.1, 0.2, 0.0, false});
  CHECK(both.warnings.size() == 3);  // rho range, rho_tilde > 0.03, rho_tilde >= rho
}

TEST_CASE("nonsense parameter values are errors") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  CHECK_THROWS_AS(check_ball_parameters({nan, 0.01, 0, false}), InvalidInput);
  CHECK_THROWS_AS(check_ball_parameters({-0.3, 0.01, 0, false}), InvalidInput);
  CHECK_THROWS_AS(check_ball_parameters({0.0, 0.01, 0, false}), InvalidInput);
  CHECK_THROWS_AS(check_ball_parameters({inf, 0.01, 0, false}), InvalidInput);
  CHECK_THROWS_AS(check_ball_parameters({0.3, nan, 0, false}), InvalidInput);
  CHECK_THROWS_AS(check_ball_parameters({0.3, -0.01, 0, false}), InvalidInput);
  CHECK_THROWS_AS(check_ball_parameters({0.3, 0.01, -1e-9, false}), InvalidInput);
  CHECK_THROWS_AS(check_ball_parameters({0.3, 0.01, nan, false}), InvalidInput);
  CHECK_THROWS_WITH(check_ball_parameters({0.3, -0.5, 0, false}),
                    Catch::Contains("rho_tilde") && Catch::Contains("-0.5"));
}

TEST_CASE("eps is absolute or relative to the bounding-box diagonal") {
  CHECK(rstruct::poles::absolute_eps({0.3, 0.01, 0.25, false}, 8.0) == 0.25);
  CHECK(rstruct::poles::absolute_eps({0.3, 0.01, 0.25, true}, 8.0) == 2.0);
  CHECK_THROWS_AS(rstruct::poles::absolute_eps({0.3, 0.01, 0.25, true}, -1.0), InvalidInput);
  CHECK_THROWS_AS(rstruct::poles::absolute_eps({0.3, 0.01, -0.25, false}, 1.0), InvalidInput);
}
