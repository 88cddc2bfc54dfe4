// Benchmark of issue 5: on a uniform r-sample of a torus (R/a = 3), the time of
// poles + labels + D̂ + covering sets (ρ̃ = 0.03) against the time of the Delaunay
// triangulation of the same input. Prints one line per size with medians over --runs.
//
//   bench_poles [--sizes 10000,100000,1000000] [--runs 3] [--rho-tilde 0.03] [--threads 0]

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "rstruct/core/report.hpp"
#include "rstruct/core/stopwatch.hpp"
#include "rstruct/poles/ball_sets.hpp"
#include "rstruct/poles/covering_sets.hpp"
#include "rstruct/poles/pole_analysis.hpp"
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

double stage(const rstruct::Report& report, const std::string& name) {
  for (const auto& [n, s] : report.stages()) {
    if (n == name) return s;
  }
  return 0;
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
  std::printf("# torus R=3 a=1 uniform sample; medians of %d runs; threads=%u; seconds\n", runs,
              threads);
  std::printf("%9s %9s %9s %8s %8s %8s %8s %9s %7s %9s %8s %5s %10s\n", "n", "delaunay",
              "del+box", "poles", "labels", "dhat", "cover", "ours", "ratio", "poles#",
              "inner#", "bad#", "entries");
  for (const std::size_t n : sizes) {
    const auto samples = torus_sample(n, 12345 + n);
    std::vector<double> t_ref, t_box, t_poles, t_labels, t_dhat, t_cover;
    std::size_t pole_count = 0, inner = 0, bad = 0, entries = 0;
    for (int run = 0; run < runs; ++run) {
      {
        rstruct::Stopwatch clock;
        const rstruct::triangulation::RegularTriangulation3 dt(samples);
        t_ref.push_back(clock.seconds());
      }
      rstruct::Report report;
      rstruct::poles::PoleAnalysisOptions options;
      options.threads = threads;
      const auto analysis = rstruct::poles::analyse_poles(samples, options, &report);
      rstruct::Stopwatch clock;
      const auto balls =
          rstruct::poles::scaled_sample_balls(samples, analysis.dhat.distance, rho_tilde);
      const auto sets = rstruct::poles::covering_sets(balls, samples, threads);
      t_cover.push_back(clock.seconds());
      t_box.push_back(stage(report, "delaunay"));
      t_poles.push_back(stage(report, "poles"));
      t_labels.push_back(stage(report, "labels"));
      t_dhat.push_back(stage(report, "pole distance"));
      pole_count = analysis.poles.size();
      inner = analysis.labeling.inner;
      bad = analysis.labeling.unlabelled + analysis.labeling.contradictory;
      entries = sets.entry_count();
    }
    const double ours = median(t_poles) + median(t_labels) + median(t_dhat) + median(t_cover);
    std::printf("%9zu %9.3f %9.3f %8.3f %8.3f %8.3f %8.3f %9.3f %7.2f %9zu %8zu %5zu %10zu\n", n,
                median(t_ref), median(t_box), median(t_poles), median(t_labels), median(t_dhat),
                median(t_cover), ours, ours / median(t_ref), pole_count, inner, bad, entries);
    std::fflush(stdout);
  }
  return 0;
}
