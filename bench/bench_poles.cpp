// Benchmark of issue 5: on a uniform r-sample of a torus (R/a = 3), the time of
// poles + labels + D̂ + covering sets (ρ̃ = 0.03) against the time of the Delaunay
// triangulation of the same input. Prints one line per size with medians over --runs.
//
//   bench_poles [--sizes 10000,100000,1000000] [--runs 3] [--rho-tilde 0.03] [--threads 0]

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "rstruct/core/stopwatch.hpp"
#include "rstruct/poles/ball_sets.hpp"
#include "rstruct/poles/covering_sets.hpp"
#include "rstruct/poles/pole_analysis.hpp"
#include "rstruct/poles/pole_labeling.hpp"
#include "rstruct/triangulation/regular_triangulation_3.hpp"

namespace {

using rstruct::Point3;

/// n points uniform by area on the torus with major radius 3 and minor radius 1 (rejection
/// on the angle φ around the tube, whose area element is ∝ R + a cos φ).
std::vector<Point3> torus_sample(std::size_t n, std::uint64_t seed) {
  const double R = 3.0, a = 1.0;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> angle(0.0, 2 * std::numbers::pi);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Point3> points;
  points.reserve(n);
  while (points.size() < n) {
    const double theta = angle(rng), phi = angle(rng);
    if (unit(rng) * (R + a) > R + a * std::cos(phi)) continue;
    const double rho = R + a * std::cos(phi);
    points.push_back({rho * std::cos(theta), rho * std::sin(theta), a * std::sin(phi)});
  }
  return points;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t k = v.size() / 2;
  return v.size() % 2 == 1 ? v[k] : 0.5 * (v[k - 1] + v[k]);
}

/// Process CPU seconds (all threads): stable on a loaded machine, unlike wall time.
double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

/// Wall and CPU seconds of one stage.
struct Timer {
  rstruct::Stopwatch wall;
  double cpu0 = cpu_seconds();
  void stop(std::vector<double>& w, std::vector<double>& c) {
    w.push_back(wall.seconds());
    c.push_back(cpu_seconds() - cpu0);
  }
};

enum Stage { kDelaunay, kDelaunayBox, kPoles, kLabels, kDhat, kCover, kStages };
const char* const kNames[kStages] = {"delaunay", "del+box", "poles", "labels", "dhat", "cover"};

struct Counts {
  std::size_t poles = 0, inner = 0, bad = 0, entries = 0, pairs = 0;
};

/// One run of every stage, the way analyse_poles chains them, timing each.
Counts run_once(const std::vector<Point3>& samples, double rho_tilde, unsigned threads,
                std::vector<double> (&wall)[kStages], std::vector<double> (&cpu)[kStages]) {
  namespace poles = rstruct::poles;
  using rstruct::triangulation::RegularTriangulation3;
  {
    Timer t;
    const RegularTriangulation3 dt(samples);
    t.stop(wall[kDelaunay], cpu[kDelaunay]);
  }
  Timer t_box;
  std::vector<Point3> sites = samples;
  const auto box = poles::bounding_box_sites(samples, 3.0);
  sites.insert(sites.end(), box.begin(), box.end());
  const RegularTriangulation3 dt(sites);
  std::vector<std::array<std::uint32_t, 4>> tets;
  tets.reserve(dt.number_of_finite_cells());
  dt.for_each_finite_cell([&](rstruct::triangulation::CellId c) { tets.push_back(dt.vertices(c)); });
  t_box.stop(wall[kDelaunayBox], cpu[kDelaunayBox]);
  Timer t_poles;
  poles::PoleSet pole_set = poles::compute_poles({sites, samples.size(), tets, {}}, threads);
  t_poles.stop(wall[kPoles], cpu[kPoles]);
  Timer t_labels;
  const auto labeling = poles::label_poles(pole_set, samples);
  t_labels.stop(wall[kLabels], cpu[kLabels]);
  Timer t_dhat;
  const auto dhat = poles::pole_distance(samples, pole_set, threads);
  t_dhat.stop(wall[kDhat], cpu[kDhat]);
  Timer t_cover;
  const auto balls = poles::scaled_sample_balls(samples, dhat.distance, rho_tilde);
  const auto sets = poles::covering_sets(balls, samples, threads);
  t_cover.stop(wall[kCover], cpu[kCover]);
  return {pole_set.size(), labeling.inner, labeling.unlabelled + labeling.contradictory,
          sets.entry_count(), labeling.pairs_examined};
}

std::vector<std::size_t> parse_sizes(const std::string& text) {
  std::vector<std::size_t> sizes;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) sizes.push_back(std::stoull(item));
  return sizes;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::size_t> sizes = {10000, 100000, 1000000};
  int runs = 3;
  double rho_tilde = 0.03;
  unsigned threads = 0;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i], value = argv[i + 1];
    if (key == "--sizes") sizes = parse_sizes(value);
    else if (key == "--runs") runs = std::max(1, std::atoi(value.c_str()));
    else if (key == "--rho-tilde") rho_tilde = std::atof(value.c_str());
    else if (key == "--threads") threads = static_cast<unsigned>(std::atoi(value.c_str()));
    else {
      std::fprintf(stderr, "unknown option %s\n", key.c_str());
      return 2;
    }
  }
  std::printf("# torus R=3 a=1 uniform sample; medians of %d runs; threads=%u\n", runs, threads);
  std::printf("# ours = poles + labels + dhat + cover; ratio = ours / delaunay (same input)\n");
  for (const std::size_t n : sizes) {
    const auto samples = torus_sample(n, 12345 + n);
    std::vector<double> wall[kStages], cpu[kStages];
    Counts counts;
    for (int run = 0; run < runs; ++run) counts = run_once(samples, rho_tilde, threads, wall, cpu);
    for (const auto* kind : {"wall", "cpu"}) {
      auto& times = std::string(kind) == "wall" ? wall : cpu;
      std::printf("n=%zu %s:", n, kind);
      for (int k = 0; k < kStages; ++k) std::printf(" %s=%.3f", kNames[k], median(times[k]));
      const double ours = median(times[kPoles]) + median(times[kLabels]) +
                          median(times[kDhat]) + median(times[kCover]);
      std::printf(" ours=%.3f ratio=%.2f\n", ours, ours / median(times[kDelaunay]));
    }
    std::printf(
        "n=%zu checksum: poles=%zu inner=%zu unlabelled+contradictory=%zu entries=%zu "
        "label_pairs=%zu\n",
        n, counts.poles, counts.inner, counts.bad, counts.entries, counts.pairs);
    std::fflush(stdout);
  }
  return 0;
}
