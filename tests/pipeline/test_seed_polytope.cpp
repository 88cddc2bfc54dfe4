// The seed-polytope pipeline end to end on certified r-samples (issue 7): the dual complex
// of the kept surface balls and the collapsed output have the Betti numbers of the sampled
// surface, every output vertex is a sample, every sample maps to an output vertex, and
// pruning harder never keeps more balls.

#include "rstruct/pipeline/seed_polytope.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <set>

#include "rstruct/core/error.hpp"
#include "rstruct/poles/pole_analysis.hpp"
#include "rstruct/predicates/predicates.hpp"
#include "rstruct/sampling/sample_request.hpp"

using rstruct::pipeline::SeedOptions;
using rstruct::pipeline::SeedPolytope;

namespace {

std::vector<rstruct::Point3> certified_sample(const std::string& shape, double r,
                                              std::uint64_t seed, bool rotate) {
  rstruct::sampling::SampleRequest request;
  request.shape = shape;
  request.r = r;
  request.seed = seed;
  request.rotate = rotate;
  if (rotate) request.translate = {12.5, -3.0, 1e3};
  return rstruct::sampling::generate_sample(request).points;
}

void check_structure(const std::vector<rstruct::Point3>& samples, const SeedPolytope& seed) {
  // Output vertices are distinct kept samples.
  std::set<std::uint32_t> kept(seed.kept.begin(), seed.kept.end());
  std::set<std::uint32_t> vertices(seed.vertex_sample.begin(), seed.vertex_sample.end());
  CHECK(vertices.size() == seed.vertex_sample.size());
  for (std::uint32_t s : seed.vertex_sample) {
    REQUIRE(s < samples.size());
    CHECK(kept.count(s) == 1);
  }
  // Triangles index output vertices, no repeated vertex.
  for (const auto& t : seed.triangles) {
    for (std::uint32_t v : t) REQUIRE(v < seed.vertex_sample.size());
    CHECK((t[0] != t[1] && t[1] != t[2] && t[0] != t[2]));
  }
  // Every sample maps to an output vertex; a kept sample that is an output vertex maps to
  // itself unless its ball is hidden or another ball's power cell also contains it.
  REQUIRE(seed.sample_vertex.size() == samples.size());
  for (std::uint32_t v : seed.sample_vertex) REQUIRE(v < seed.vertex_sample.size());
  std::size_t self_mapped = 0;
  for (std::uint32_t k = 0; k < seed.vertex_sample.size(); ++k) {
    self_mapped += seed.sample_vertex[seed.vertex_sample[k]] == k;
  }
  CHECK(self_mapped >= seed.vertex_sample.size() * 9 / 10);
}

/// The same kept balls, output mesh, sample map and dual complex counts.
void check_same_output(const SeedPolytope& a, const SeedPolytope& b) {
  CHECK(a.kept == b.kept);
  CHECK(a.vertex_sample == b.vertex_sample);
  CHECK(a.triangles == b.triangles);
  CHECK(a.sample_vertex == b.sample_vertex);
  CHECK(a.k_counts == b.k_counts);
  CHECK(a.facet_classes == b.facet_classes);
}

}  // namespace

TEST_CASE("sphere: K and the output have the sphere's Betti numbers") {
  const auto samples = certified_sample("sphere", 0.08, 7, false);
  for (double rho : {0.24, 0.4, 0.56}) {
    SeedOptions options;
    options.rho = rho;
    options.rho_tilde = 0.03;
    INFO("rho = " << rho << ", " << samples.size() << " samples");
    const SeedPolytope seed = rstruct::pipeline::compute_seed_polytope(samples, options);
    CHECK(seed.labeling.is_clean());
    CHECK(seed.betti_k == rstruct::complex::BettiNumbers{{1, 0, 1, 0}});
    CHECK(seed.betti_output == rstruct::complex::BettiNumbers{{1, 0, 1, 0}});
    CHECK(seed.manifold.is_closed_2_manifold);
    CHECK(seed.oriented);
    CHECK(seed.warnings.empty());
    check_structure(samples, seed);
  }
}

TEST_CASE("torus (rotated, translated): genus 1 survives pruning at every shrink factor") {
  const auto samples = certified_sample("torus", 0.08, 3, true);
  std::size_t previous_kept = samples.size() + 1;
  for (double shrink : {0.0, 0.01, 0.03}) {
    SeedOptions options;
    options.rho = 0.4;
    options.rho_tilde = shrink;
    INFO("shrink = " << shrink << ", " << samples.size() << " samples");
    const SeedPolytope seed = rstruct::pipeline::compute_seed_polytope(samples, options);
    CHECK(seed.betti_k == rstruct::complex::BettiNumbers{{1, 2, 1, 0}});
    CHECK(seed.betti_output == rstruct::complex::BettiNumbers{{1, 2, 1, 0}});
    CHECK(seed.manifold.is_closed_2_manifold);
    CHECK(seed.oriented);
    check_structure(samples, seed);
    CHECK(seed.kept.size() <= previous_kept);
    if (shrink > 0) {
      CHECK(seed.pruned);
      CHECK(seed.prune.lower_bound <= seed.prune.cost);
    }
    previous_kept = seed.kept.size();
  }
}

TEST_CASE("absurd parameters are rejected, unguaranteed ones are warned about") {
  const auto samples = certified_sample("sphere", 0.08, 1, false);
  SeedOptions options;
  options.rho = std::nan("");
  CHECK_THROWS_AS(rstruct::pipeline::compute_seed_polytope(samples, options),
                  rstruct::InvalidInput);
  options.rho = 0.5;
  options.rho_tilde = 0.6;
  CHECK_THROWS_AS(rstruct::pipeline::compute_seed_polytope(samples, options),
                  rstruct::InvalidInput);
  options.rho = 0.7;
  options.rho_tilde = 0.05;
  const SeedPolytope seed = rstruct::pipeline::compute_seed_polytope(samples, options);
  CHECK(seed.warnings.size() == 2);
}

namespace {
bool has_stage(const rstruct::Report& report, const std::string& name) {
  for (const auto& stage : report.stages()) {
    if (stage.first == name) return true;
  }
  return false;
}
}  // namespace

TEST_CASE("the pole labels run beside the level: the same result, checked at the end") {
  const auto samples = certified_sample("torus", 0.15, 5, true);
  SeedOptions options;
  options.rho = 0.4;
  options.rho_tilde = 0;
  options.threads = 1;  // labels first
  rstruct::Report first_report;
  const SeedPolytope first =
      rstruct::pipeline::compute_seed_polytope(samples, options, &first_report);
  CHECK(has_stage(first_report, "labels + pole distance"));
  CHECK_FALSE(has_stage(first_report, "labels (wait)"));
  options.threads = 2;  // labels beside the level
  rstruct::Report beside_report;
  const SeedPolytope beside =
      rstruct::pipeline::compute_seed_polytope(samples, options, &beside_report);
  CHECK(has_stage(beside_report, "pole distance"));
  CHECK(has_stage(beside_report, "labels (wait)"));
  CHECK_FALSE(has_stage(beside_report, "labels + pole distance"));
  CHECK(beside_report.data()["poles"]["inner"] == first_report.data()["poles"]["inner"]);
  check_same_output(beside, first);
  CHECK(beside.labeling.is_clean());
  CHECK(beside.labeling.inner == first.labeling.inner);
  CHECK(beside.labeling.inner > 0);
  CHECK(beside.warnings == first.warnings);

  // A shared analysis without labels: the first level needs its PendingLabels.
  rstruct::poles::PoleAnalysisOptions later;
  later.label = false;
  rstruct::poles::PoleAnalysis analysis = rstruct::poles::analyse_poles(samples, later);
  CHECK_THROWS_WITH(rstruct::pipeline::compute_seed_polytope(samples, analysis, options),
                    Catch::Contains("not labelled"));
  rstruct::poles::PendingLabels pending(analysis, samples);
  {
    rstruct::poles::PoleAnalysis other = rstruct::poles::analyse_poles(samples, later);
    CHECK_THROWS_WITH(
        rstruct::pipeline::compute_seed_polytope(samples, other, options, nullptr, &pending),
        Catch::Contains("another analysis"));
  }
  rstruct::Report level_report;
  check_same_output(rstruct::pipeline::compute_seed_polytope(samples, analysis, options,
                                                             &level_report, &pending),
                    first);
  CHECK(has_stage(level_report, "labels (wait)"));
  CHECK(analysis.labelled);
  CHECK(analysis.labeling.inner == first.labeling.inner);
  // Later levels check the labels first, with or without the (finished) pending labels.
  rstruct::Report second_report;
  const SeedPolytope second =
      rstruct::pipeline::compute_seed_polytope(samples, analysis, options, &second_report);
  check_same_output(second, first);
  CHECK(second.labeling.inner == first.labeling.inner);
  CHECK_FALSE(has_stage(second_report, "labels (wait)"));
}

TEST_CASE("a labelling that is not clean: a warning, or with require_clean_labels an error") {
  // Points filling a cube are no r-sample of a closed surface: poles with contradictory
  // evidence. Labelled first (one thread) or beside the level (two), the same verdict.
  std::vector<rstruct::Point3> cube;
  std::uint64_t state = 12345;
  const auto next = [&] {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) * 0x1.0p-53;
  };
  for (int i = 0; i < 3000; ++i) cube.push_back({next(), next(), next()});
  SeedOptions options;
  options.rho = 0.4;
  options.rho_tilde = 0;
  std::vector<std::string> warnings[2];
  for (const unsigned threads : {1u, 2u}) {
    options.threads = threads;
    options.require_clean_labels = false;
    const SeedPolytope seed = rstruct::pipeline::compute_seed_polytope(cube, options);
    CHECK_FALSE(seed.labeling.is_clean());
    REQUIRE_FALSE(seed.warnings.empty());
    CHECK_THAT(seed.warnings.back(), Catch::Contains("not clean"));
    warnings[threads - 1] = seed.warnings;
    options.require_clean_labels = true;
    CHECK_THROWS_AS(rstruct::pipeline::compute_seed_polytope(cube, options),
                    rstruct::ComputationFailed);
  }
  std::sort(warnings[0].begin(), warnings[0].end());
  std::sort(warnings[1].begin(), warnings[1].end());
  CHECK(warnings[0] == warnings[1]);
}

TEST_CASE("levels share one pole analysis; results do not depend on it or on threads") {
  const auto samples = certified_sample("torus", 0.15, 5, true);
  // Unpruned, so that nothing depends on the set-cover solver's time limit.
  SeedOptions options;
  options.rho = 0.4;
  options.rho_tilde = 0;
  options.threads = 1;
  const SeedPolytope alone = rstruct::pipeline::compute_seed_polytope(samples, options);
  const rstruct::poles::PoleAnalysis analysis = rstruct::poles::analyse_poles(samples);
  options.threads = 3;
  const SeedPolytope shared =
      rstruct::pipeline::compute_seed_polytope(samples, analysis, options);
  check_same_output(shared, alone);
  CHECK(shared.betti_output == rstruct::complex::BettiNumbers{{1, 2, 1, 0}});

  options.rho_tilde = 0.03;
  options.prune.time_limit = 0.2;
  const SeedPolytope pruned =
      rstruct::pipeline::compute_seed_polytope(samples, analysis, options);
  CHECK(pruned.betti_output == rstruct::complex::BettiNumbers{{1, 2, 1, 0}});

  // Nested level: prune among the balls just kept with a larger shrink factor.
  SeedOptions coarse = options;
  coarse.rho = 0.56;
  coarse.rho_tilde = 0.06;
  coarse.candidates = pruned.kept;
  const SeedPolytope nested =
      rstruct::pipeline::compute_seed_polytope(samples, analysis, coarse);
  CHECK(nested.kept.size() <= pruned.kept.size());
  CHECK(std::includes(pruned.kept.begin(), pruned.kept.end(), nested.kept.begin(),
                      nested.kept.end()));
  CHECK(nested.betti_output == rstruct::complex::BettiNumbers{{1, 2, 1, 0}});
  check_structure(samples, nested);

  // Unpruned level restricted to candidates keeps exactly them.
  SeedOptions unpruned = options;
  unpruned.rho_tilde = 0;
  unpruned.candidates = pruned.kept;
  CHECK(rstruct::pipeline::compute_seed_polytope(samples, analysis, unpruned).kept ==
        pruned.kept);

  // Bad candidate lists and analyses of other samples are rejected.
  SeedOptions bad = options;
  bad.candidates = {3, 2};
  CHECK_THROWS_AS(rstruct::pipeline::compute_seed_polytope(samples, analysis, bad),
                  rstruct::InvalidInput);
  bad.candidates = {static_cast<std::uint32_t>(samples.size())};
  CHECK_THROWS_AS(rstruct::pipeline::compute_seed_polytope(samples, analysis, bad),
                  rstruct::InvalidInput);
  const std::vector<rstruct::Point3> fewer(samples.begin(), samples.end() - 1);
  CHECK_THROWS_AS(rstruct::pipeline::compute_seed_polytope(fewer, analysis, options),
                  rstruct::InvalidInput);
}

TEST_CASE("every sample maps to the output vertex of smallest power distance") {
  // Brute-force oracle with exact comparisons: a sample goes to a kept ball of smallest
  // power distance if that ball is an output vertex, else to an output vertex of smallest
  // power distance among the output vertices' balls.
  const auto samples = certified_sample("sphere", 0.12, 11, false);
  SeedOptions options;
  options.rho = 0.5;
  options.rho_tilde = 0.03;
  options.prune.time_limit = 0.2;
  const SeedPolytope seed = rstruct::pipeline::compute_seed_polytope(samples, options);
  REQUIRE(seed.sample_vertex.size() == samples.size());
  const auto ball = [&](std::uint32_t s) {
    return rstruct::WeightedPoint{samples[s], seed.radius[s] * seed.radius[s]};
  };
  const auto nearest = [&](const rstruct::Point3& q, const std::vector<std::uint32_t>& among) {
    std::uint32_t best = among.front();
    for (const std::uint32_t k : among) {
      if (rstruct::predicates::compare_power_distance(q, ball(k), ball(best)) ==
          rstruct::Sign::negative) {
        best = k;
      }
    }
    return best;
  };
  const std::set<std::uint32_t> outputs(seed.vertex_sample.begin(), seed.vertex_sample.end());
  for (std::size_t s = 0; s < samples.size(); ++s) {
    const std::uint32_t mine = seed.vertex_sample[seed.sample_vertex[s]];
    const std::uint32_t best = nearest(samples[s], seed.kept);
    const std::uint32_t expected =
        outputs.count(best) != 0 ? best : nearest(samples[s], seed.vertex_sample);
    INFO("sample " << s);
    REQUIRE(rstruct::predicates::compare_power_distance(samples[s], ball(mine),
                                                        ball(expected)) == rstruct::Sign::zero);
  }
}

TEST_CASE("the seed polytope does not depend on the threads of its triangulations") {
  // 24,000 samples of a torus: the Delaunay triangulation of the pole analysis and the
  // regular triangulation of the balls both insert in parallel, with vertex locks, so
  // their cell ids depend on timing; nothing in the output may.
  rstruct::sampling::SampleRequest request;
  request.shape = "torus";
  request.n = 24000;
  request.seed = 3;
  const auto samples = rstruct::sampling::generate_sample(request).points;
  SeedOptions options;
  options.rho = 0.4;
  options.rho_tilde = 0;
  options.threads = 1;
  const SeedPolytope one = rstruct::pipeline::compute_seed_polytope(samples, options);
  check_structure(samples, one);
  CHECK(one.betti_output == rstruct::complex::BettiNumbers{{1, 2, 1, 0}});
  for (const unsigned threads : {2u, 2u}) {
    options.threads = threads;
    const SeedPolytope many = rstruct::pipeline::compute_seed_polytope(samples, options);
    check_same_output(many, one);
    // Balls on a surface: locks from the first parallel pass (as the pole analysis's).
    CHECK(many.triangulation.threads == threads);
    CHECK(many.triangulation.parallel_points > samples.size() / 2);
    CHECK(many.triangulation.border_passes == 0);
    CHECK(many.triangulation.lock_passes >= 1);
  }
}
