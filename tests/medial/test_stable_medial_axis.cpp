// Stable medial axis from samples (paper §3, §5.1): topology of the axis of the pruned,
// enlarged inner polar balls, and the number of kept balls against ε.

#include "rstruct/medial/stable_medial_axis.hpp"

#include <catch2/catch.hpp>
#include <cstdint>
#include "rstruct/core/error.hpp"
#include <string>
#include <vector>

#include "rstruct/sampling/sample_request.hpp"

using namespace rstruct;
using namespace rstruct::medial;

namespace {

std::vector<Point3> sample(const std::string& shape, std::size_t n, std::uint64_t seed = 1) {
  sampling::SampleRequest request;
  request.shape = shape;
  request.n = n;
  request.seed = seed;
  return sampling::generate_sample(request).points;
}

StableMedialAxis run(const std::vector<Point3>& samples, double eps_rel) {
  StableMedialAxisOptions options;
  options.eps_rel = eps_rel;
  options.cover_time_limit = 0.2;
  options.threads = 1;
  return stable_medial_axis(samples, options);
}

}  // namespace

TEST_CASE("solid torus: axis with Betti (1, 1, 0)", "[medial][samples]") {
  const StableMedialAxis out = run(sample("torus", 3000), 0.01);
  INFO("kept " << out.kept.size() << " of " << out.inner_poles);
  CHECK(out.axis_stats.betti_k == complex::BettiNumbers{{1, 1, 0, 0}});
  CHECK(out.betti_axis == complex::BettiNumbers{{1, 1, 0, 0}});
  CHECK(out.violations == 0);
}

TEST_CASE("ellipsoid: axis with Betti (1, 0, 0)", "[medial][samples]") {
  const StableMedialAxis out = run(sample("ellipsoid", 3000), 0.01);
  CHECK(out.betti_axis == complex::BettiNumbers{{1, 0, 0, 0}});
  CHECK(out.betti_axis == out.axis_stats.betti_k);
}

TEST_CASE("double torus: axis with Betti (1, 2, 0)", "[medial][samples]") {
  const StableMedialAxis out = run(sample("double-torus", 5000), 0.01);
  CHECK(out.betti_axis == complex::BettiNumbers{{1, 2, 0, 0}});
  CHECK(out.betti_axis == out.axis_stats.betti_k);
}

TEST_CASE("the number of kept balls falls as epsilon grows", "[medial][samples]") {
  const std::vector<Point3> samples = sample("torus", 3000, 7);
  std::size_t previous = SIZE_MAX;
  for (const double eps_rel : {0.002, 0.01, 0.04}) {
    const StableMedialAxis out = run(samples, eps_rel);
    INFO("eps_rel " << eps_rel << ": kept " << out.kept.size());
    CHECK(out.kept.size() < previous);
    CHECK(out.kept.size() >= static_cast<std::size_t>(out.prune.lower_bound));
    previous = out.kept.size();
  }
}

TEST_CASE("negative epsilon is rejected", "[medial][samples]") {
  StableMedialAxisOptions options;
  options.eps = -1;
  options.eps_rel = -0.5;
  CHECK_THROWS_AS(stable_medial_axis(sample("ellipsoid", 500), options), InvalidInput);
}
