// analyse_poles: box sites, input errors, duplicates, and metamorphic checks (permutation,
// scaling by a power of two) on a Fibonacci sphere sample.

#include "rstruct/poles/pole_analysis.hpp"

#include <algorithm>
#include <atomic>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <tuple>
#include <vector>

#include "poles/resumable_labeling.hpp"
#include "rstruct/core/error.hpp"

using rstruct::Point3;
using rstruct::poles::analyse_poles;
using rstruct::poles::PoleAnalysisOptions;
using rstruct::poles::PoleLabel;

namespace {

/// n points of the golden-angle spiral on the sphere of radius `radius` around `centre`.
std::vector<Point3> fibonacci_sphere(std::size_t n, double radius, const Point3& centre) {
  std::vector<Point3> points;
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (std::size_t i = 0; i < n; ++i) {
    const double z = 1.0 - (2.0 * static_cast<double>(i) + 1.0) / static_cast<double>(n);
    const double rho = std::sqrt(1.0 - z * z);
    const double phi = golden * static_cast<double>(i);
    points.push_back(centre + radius * Point3{rho * std::cos(phi), rho * std::sin(phi), z});
  }
  return points;
}

using Key = std::tuple<double, double, double, double, int>;

/// The poles as a sorted list of (centre, radius, label): independent of numbering.
std::vector<Key> keys(const rstruct::poles::PoleSet& poles, double scale = 1.0) {
  std::vector<Key> k;
  for (std::uint32_t p = 0; p < poles.size(); ++p) {
    k.emplace_back(poles.centre[p].x * scale, poles.centre[p].y * scale,
                   poles.centre[p].z * scale, poles.radius[p] * scale,
                   static_cast<int>(poles.label[p]));
  }
  std::sort(k.begin(), k.end());
  return k;
}

/// n random points (uniform in the angles) on the torus with radii 3 and 1.
std::vector<Point3> torus_samples(int n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> angle(0.0, 2 * std::numbers::pi);
  std::vector<Point3> samples;
  for (int i = 0; i < n; ++i) {
    const double u = angle(rng);
    const double v = angle(rng);
    samples.push_back({(3 + std::cos(v)) * std::cos(u), (3 + std::cos(v)) * std::sin(u),
                       std::sin(v)});
  }
  return samples;
}

}  // namespace

TEST_CASE("box sites are centred on the data, also far from the origin") {
  const std::vector<Point3> samples = {{1e6, 1e6, 1e6}, {1e6 + 2, 1e6, 1e6},
                                       {1e6, 1e6 + 1, 1e6}, {1e6, 1e6, 1e6 + 1}};
  const auto sites = rstruct::poles::bounding_box_sites(samples, 3.0);
  REQUIRE(sites.size() == 8);
  Point3 mean{0, 0, 0};
  for (const auto& s : sites) mean += s / 8.0;
  CHECK(mean.x == Approx(1e6 + 1).epsilon(1e-15));
  CHECK(mean.y == Approx(1e6 + 0.5).epsilon(1e-15));
  for (const auto& s : sites) CHECK(std::fabs(s.x - (1e6 + 1)) == 6.0);  // 3 × extent 2
  CHECK_THROWS_AS(rstruct::poles::bounding_box_sites(samples, 1.5), rstruct::InvalidInput);
  CHECK_THROWS_AS(rstruct::poles::bounding_box_sites(
                      samples, std::numeric_limits<double>::quiet_NaN()),
                  rstruct::InvalidInput);
}

TEST_CASE("analyse_poles input errors") {
  std::vector<Point3> three = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  CHECK_THROWS_AS(analyse_poles(three), rstruct::InvalidInput);
  std::vector<Point3> same(5, Point3{1, 2, 3});
  CHECK_THROWS_WITH(analyse_poles(same), Catch::Contains("coincide"));
  auto bad = fibonacci_sphere(20, 1.0, {0, 0, 0});
  bad[7].y = std::numeric_limits<double>::infinity();
  CHECK_THROWS_WITH(analyse_poles(bad), Catch::Contains("sample 7"));
}

TEST_CASE("sphere sample: clean labels, inner poles near the centre, D̂ ≈ 1") {
  for (const Point3 centre : {Point3{0, 0, 0}, Point3{1e6, -2e6, 5e5}}) {
    const auto samples = fibonacci_sphere(1500, 1.0, centre);
    rstruct::Report report;
    const auto a = analyse_poles(samples, {}, &report);
    REQUIRE(a.poles.is_valid());
    CHECK(a.labeling.is_clean());
    CHECK(a.labeling.unlabelled == 0);
    CHECK(report.data()["poles"]["unlabelled"] == 0);
    CHECK(report.stages().size() == 3);  // delaunay, poles, labels + pole distance
    for (std::uint32_t p = 0; p < a.poles.size(); ++p) {
      // The tetrahedra come to compute_poles with their vertices sorted (the circumcentre
      // does not depend on the triangulation's vertex order in a cell).
      const auto& q = a.poles.sites[p];
      CHECK((q[0] < q[1] && q[1] < q[2] && q[2] < q[3]));
      const double d = rstruct::distance(a.poles.centre[p], centre);
      if (a.poles.label[p] == PoleLabel::inner) {
        CHECK(d < 0.1);
      } else {
        CHECK(d > 2.0);
      }
    }
    for (const double dhat : a.dhat.distance) CHECK(dhat == Approx(1.0).epsilon(0.02));
  }
}

TEST_CASE("duplicate samples share the poles of the sample they coincide with") {
  auto samples = fibonacci_sphere(600, 2.0, {0.5, 0.25, -1});
  samples.push_back(samples[10]);
  samples.push_back(samples[599]);
  samples.push_back(samples[10]);
  const auto a = analyse_poles(samples);
  REQUIRE(a.poles.is_valid());
  CHECK(a.duplicate_samples == 3);
  CHECK(a.labeling.is_clean());
  CHECK(a.poles.sample_poles[600] == a.poles.sample_poles[10]);
  CHECK(a.poles.sample_poles[601] == a.poles.sample_poles[599]);
  CHECK(a.dhat.distance[602] == a.dhat.distance[10]);
}

TEST_CASE("metamorphic: permuting samples or scaling by 2^k gives the same poles") {
  const auto samples = fibonacci_sphere(800, 1.0, {3, -1, 2});
  const auto base = analyse_poles(samples);
  REQUIRE(base.labeling.is_clean());

  std::vector<std::uint32_t> order(samples.size());
  for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  std::mt19937_64 rng(5);
  std::shuffle(order.begin(), order.end(), rng);
  std::vector<Point3> shuffled;
  for (const std::uint32_t i : order) shuffled.push_back(samples[i]);
  const auto permuted = analyse_poles(shuffled);
  CHECK(permuted.labeling.is_clean());
  // The Delaunay triangulation does not depend on the numbering here, but which of several
  // incident circumballs of (almost) equal radius is the farthest is decided on rounded
  // radii, and rounding depends on the vertex order inside a cell (on a sphere sample all
  // inner circumballs nearly coincide). So compare per sample: the polar radii agree to
  // rounding, the labels exactly.
  for (std::size_t k = 0; k < order.size(); ++k) {
    const std::uint32_t s = order[k];
    for (int j = 0; j < 2; ++j) {
      const std::uint32_t p = base.poles.sample_poles[s][j];
      const std::uint32_t q = permuted.poles.sample_poles[k][j];
      REQUIRE(p != rstruct::poles::kNoPole);
      REQUIRE(q != rstruct::poles::kNoPole);
      CHECK(permuted.poles.radius[q] == Approx(base.poles.radius[p]).epsilon(1e-9));
      CHECK(permuted.poles.label[q] == base.poles.label[p]);
    }
    CHECK(permuted.dhat.distance[k] == Approx(base.dhat.distance[s]).epsilon(1e-9));
  }

  std::vector<Point3> scaled = samples;
  for (auto& p : scaled) p *= 0x1p-20;
  const auto small = analyse_poles(scaled);
  CHECK(small.labeling.is_clean());
  CHECK(keys(small.poles, 0x1p20) == keys(base.poles));  // every operation scales exactly
  for (std::size_t s = 0; s < samples.size(); ++s) {
    CHECK(small.dhat.distance[s] * 0x1p20 == base.dhat.distance[s]);
  }
}

TEST_CASE("D̂ seeded with the own poles equals the plain kd-tree and the brute force") {
  const auto samples = fibonacci_sphere(700, 1.5, {1e6, 0.5, -1e6});
  const auto a = analyse_poles(samples);
  const auto plain = rstruct::poles::pole_distance(samples, a.poles.centre, 1);
  const auto brute = rstruct::poles::pole_distance_brute_force(samples, a.poles.centre);
  for (std::size_t s = 0; s < samples.size(); ++s) {
    CHECK(a.dhat.distance[s] == plain.distance[s]);
    CHECK(a.dhat.distance[s] == brute.distance[s]);
  }
}

TEST_CASE("labels and D̂ are the same whether they run side by side or one after the other") {
  // With two or more threads the labelling runs beside the D̂ queries: a data race or a
  // mix-up of the two would show as a difference from the sequential run.
  const std::vector<Point3> samples = torus_samples(3000, 7);
  PoleAnalysisOptions one;
  one.threads = 1;
  const auto sequential = analyse_poles(samples, one);
  for (const unsigned threads : {2u, 3u}) {
    PoleAnalysisOptions options;
    options.threads = threads;
    rstruct::Report report;
    const auto side_by_side = analyse_poles(samples, options, &report);
    CHECK(report.stages().back().first == "labels + pole distance");
    CHECK(side_by_side.poles.label == sequential.poles.label);
    CHECK(side_by_side.dhat.nearest == sequential.dhat.nearest);
    CHECK(side_by_side.dhat.distance == sequential.dhat.distance);
    CHECK(side_by_side.labeling.inner == sequential.labeling.inner);
    CHECK(side_by_side.labeling.outer == sequential.labeling.outer);
    CHECK(side_by_side.labeling.pairs_examined == sequential.labeling.pairs_examined);
  }
  // Both sides were labelled (the comparison above is not between two empty runs).
  CHECK(sequential.labeling.inner > 0);
  CHECK(sequential.labeling.outer > 0);
}

TEST_CASE("labels left for later: PendingLabels gives what analyse_poles would have") {
  const std::vector<Point3> samples = torus_samples(3000, 7);
  const auto labelled = analyse_poles(samples);
  REQUIRE(labelled.labelled);
  PoleAnalysisOptions later;
  later.label = false;
  rstruct::Report report;
  auto a = analyse_poles(samples, later, &report);
  CHECK_FALSE(a.labelled);
  CHECK(report.stages().back().first == "pole distance");
  CHECK(report.data()["poles"]["labelled"] == false);
  CHECK_FALSE(report.data()["poles"].contains("inner"));
  CHECK(a.poles.label ==
        std::vector<PoleLabel>(a.poles.size(), PoleLabel::unlabelled));
  CHECK(a.dhat.distance == labelled.dhat.distance);
  CHECK(a.dhat.nearest == labelled.dhat.nearest);
  {
    rstruct::poles::PendingLabels pending(a, samples, {}, &report);
    // The caller goes on meanwhile with what the labelling does not touch.
    double sum = 0;
    for (const double d : a.dhat.distance) sum += d;
    CHECK(sum > 0);
    const rstruct::poles::LabelingStats& stats = pending.wait();
    CHECK(&pending.wait() == &stats);  // a second wait returns at once, the same counts
    CHECK(stats.inner == labelled.labeling.inner);
    CHECK(stats.outer == labelled.labeling.outer);
    CHECK(stats.pairs_examined == labelled.labeling.pairs_examined);
  }
  CHECK(a.labelled);
  CHECK(a.poles.label == labelled.poles.label);
  CHECK(a.labeling.inner == labelled.labeling.inner);
  CHECK(a.labeling.contradictory == labelled.labeling.contradictory);
  CHECK(report.data()["poles"]["labelled"] == true);
  CHECK(report.data()["poles"]["inner"] == labelled.labeling.inner);
  CHECK(report.data()["poles"]["unlabelled"] == labelled.labeling.unlabelled);
  CHECK(report.data()["poles"]["labels_seconds"].get<double>() > 0);
  // Both sides were labelled (the comparisons are not between two empty runs).
  CHECK(labelled.labeling.inner > 0);
  CHECK(labelled.labeling.outer > 0);
  // Misuse: labelling twice, the wrong samples, bad thresholds (checked before the
  // expensive steps even when the labels come later).
  CHECK_THROWS_AS(rstruct::poles::PendingLabels(a, samples), rstruct::InvalidInput);
  auto b = analyse_poles(samples, later);
  const std::vector<Point3> fewer(samples.begin(), samples.end() - 1);
  CHECK_THROWS_AS(rstruct::poles::PendingLabels(b, fewer), rstruct::InvalidInput);
  rstruct::poles::LabelingParameters bad;
  bad.same_min_cos = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_AS(rstruct::poles::PendingLabels(b, samples, bad), rstruct::InvalidInput);
  later.labeling = bad;
  CHECK_THROWS_WITH(analyse_poles(samples, later), Catch::Contains("same_min_cos"));
  // Beside other work only when a second thread can take the labels.
  CHECK_FALSE(rstruct::poles::label_beside(1));
  CHECK(rstruct::poles::label_beside(2));
  // Destroyed without wait(): joins, and the analysis stays unlabelled.
  { rstruct::poles::PendingLabels unwaited(b, samples); }
  CHECK_FALSE(b.labelled);
}

TEST_CASE("a labelling stopped every 1024 poles and resumed gives label_poles' labels") {
  // PendingLabels::wait() stops its idle-priority thread and finishes on the caller's.
  const std::vector<Point3> samples = torus_samples(3000, 11);
  PoleAnalysisOptions later;
  later.label = false;
  auto a = analyse_poles(samples, later);
  rstruct::poles::PoleSet reference = a.poles;
  const rstruct::poles::LabelingStats expected = rstruct::poles::label_poles(reference, samples);
  REQUIRE(a.poles.size() > 4 * 1024);
  rstruct::poles::detail::ResumableLabeling labeling(a.poles, samples, {});
  const std::atomic<bool> stop{true};
  CHECK_FALSE(labeling.run(stop));
  CHECK_THROWS_AS(labeling.finish(), rstruct::InternalError);
  const auto labelled = [&] {
    return std::count_if(a.poles.label.begin(), a.poles.label.end(),
                         [](PoleLabel l) { return l != PoleLabel::unlabelled; });
  };
  // Stopped after 1023 poles: some labelled, not all (the two-colouring labels a pole
  // when it reaches it, the greedy when it pops it).
  CHECK(labelled() > 0);
  CHECK(labelled() < static_cast<std::ptrdiff_t>(a.poles.size()));
  int stops = 1;
  while (!labeling.run(stop)) ++stops;
  CHECK(stops >= 4);
  CHECK(labeling.run(stop));  // done stays done
  const rstruct::poles::LabelingStats stats = labeling.finish();
  CHECK(a.poles.label == reference.label);
  CHECK(stats == expected);  // every count
  CHECK(expected.inner > 0);
  CHECK(expected.outer > 0);
}

TEST_CASE("the pole analysis does not depend on the threads of its Delaunay triangulation") {
  // 24,000 samples: BRIO rounds large enough for the parallel passes, which on a surface
  // turn to vertex locks, so the cell ids (and the soup's order) depend on timing. Poles,
  // labels and D̂ must not.
  const std::vector<Point3> samples = torus_samples(24000, 11);
  PoleAnalysisOptions one;
  one.threads = 1;
  const auto sequential = analyse_poles(samples, one);
  REQUIRE(sequential.poles.is_valid());
  CHECK(sequential.delaunay.parallel_points == 0);
  for (const unsigned threads : {2u, 2u, 3u}) {
    PoleAnalysisOptions options;
    options.threads = threads;
    const auto parallel = analyse_poles(samples, options);
    // Samples of a surface: locks from the first parallel pass, no pass with fixed borders
    // (which would defer about half of its round).
    CHECK(parallel.delaunay.threads == threads);
    CHECK(parallel.delaunay.parallel_points > samples.size() / 2);
    CHECK(parallel.delaunay.border_passes == 0);
    CHECK(parallel.delaunay.lock_passes >= 1);
    CHECK(parallel.tetrahedra == sequential.tetrahedra);
    CHECK(parallel.poles.sites == sequential.poles.sites);
    CHECK(parallel.poles.centre == sequential.poles.centre);
    CHECK(parallel.poles.radius == sequential.poles.radius);
    CHECK(parallel.poles.sample_poles == sequential.poles.sample_poles);
    CHECK(parallel.poles.label == sequential.poles.label);
    CHECK(parallel.dhat.distance == sequential.dhat.distance);
    CHECK(parallel.dhat.nearest == sequential.dhat.nearest);
  }
}

namespace {

/// The labels and counts of the labelling `method` on a copy of `poles`, with whether the
/// automatic method fell back to the greedy; the labelling stops every 1024 poles when
/// `stopping` (resumed at once: the result must not change).
struct Labelled {
  std::vector<PoleLabel> labels;
  rstruct::poles::LabelingStats stats;
  bool fell_back = false;
};
Labelled label_with(const rstruct::poles::PoleSet& poles, const std::vector<Point3>& samples,
                    const rstruct::poles::LabelingParameters& parameters,
                    rstruct::poles::detail::LabelingMethod method, bool stopping) {
  rstruct::poles::PoleSet copy = poles;
  rstruct::poles::detail::ResumableLabeling labeling(copy, samples, parameters, method);
  const std::atomic<bool> stop{stopping};
  while (!labeling.run(stop)) {
  }
  Labelled out{copy.label, labeling.finish(), labeling.fell_back()};
  return out;
}

/// n points uniform in the unit cube: no r-sample of any surface.
std::vector<Point3> cube_points(int n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Point3> points;
  for (int i = 0; i < n; ++i) points.push_back({unit(rng), unit(rng), unit(rng)});
  return points;
}

}  // namespace

TEST_CASE("the labelling's two-colouring gives the greedy's labels and counts") {
  using rstruct::poles::detail::LabelingMethod;
  struct Input {
    const char* name;
    std::vector<Point3> samples;
    rstruct::poles::LabelingParameters parameters;
    bool contradicted;  // whether the evidence contradicts itself (the greedy then runs)
  };
  rstruct::poles::LabelingParameters strict;  // hardly any evidence: poles left unreached
  strict.same_min_cos = 1.0;
  strict.opposite_min_cos = 1.0;
  rstruct::poles::LabelingParameters loose;  // evidence from every pair, all of it consistent
  loose.same_min_cos = -0.2;
  loose.opposite_min_cos = -0.2;
  std::vector<Point3> noisy = torus_samples(3000, 8);  // moved off the torus by up to 0.3
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> shift(-0.1, 0.1);
  for (Point3& p : noisy) p = p + Point3{shift(rng), shift(rng), shift(rng)};
  std::vector<Point3> grid;  // exact ties between cosines: the greedy leaves poles unlabelled
  for (int i = 0; i < 8; ++i) {
    for (int j = 0; j < 8; ++j) {
      for (int k = 0; k < 8; ++k) grid.push_back({double(i), double(j), double(k)});
    }
  }
  const std::vector<Input> inputs = {
      {"torus", torus_samples(3000, 5), {}, false},
      {"sphere", fibonacci_sphere(2000, 1.0, {0.5, -2.0, 3.0}), {}, false},
      {"torus, strict thresholds", torus_samples(3000, 6), strict, false},
      {"torus, loose thresholds", torus_samples(3000, 6), loose, false},
      {"noisy torus", noisy, {}, true},
      {"cube", cube_points(3000, 9), {}, true},
      {"grid", grid, {}, true},
  };
  for (const Input& in : inputs) {
    INFO(in.name);
    PoleAnalysisOptions later;
    later.label = false;
    const auto a = analyse_poles(in.samples, later);
    for (const bool stopping : {false, true}) {
      INFO("stopping every 1024 poles: " << stopping);
      const Labelled greedy =
          label_with(a.poles, in.samples, in.parameters, LabelingMethod::greedy, stopping);
      const Labelled automatic =
          label_with(a.poles, in.samples, in.parameters, LabelingMethod::automatic, stopping);
      CHECK_FALSE(greedy.fell_back);
      CHECK(automatic.fell_back == in.contradicted);
      CHECK(automatic.labels == greedy.labels);
      CHECK(automatic.stats == greedy.stats);  // every count, pairs examined too
      // Not between two empty labellings; contradictions exactly where the greedy sees them.
      CHECK(greedy.stats.outer > 0);
      CHECK((greedy.stats.contradictory + greedy.stats.ties > 0) == in.contradicted);
      if (in.parameters.same_min_cos == strict.same_min_cos) {
        CHECK(greedy.stats.unlabelled > 0);
      } else {
        CHECK(greedy.stats.inner > 0);
      }
    }
  }
}
