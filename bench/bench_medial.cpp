// Benchmark of issue 8 (paper Table 2): a real model resampled to about 40,000 points,
// the stable medial axis at four ε values. Per level: polar balls, kept balls, certified
// bound and gap, seconds per stage (polar balls, pruning, §5.1 check, medial axis), end to
// end, and the Betti numbers of the union and of the axis. Medians over --runs.
//
//   bench_medial [--model PATH] [--samples 40000] [--eps 0.002,0.005,0.01,0.02] [--runs 3]
//
// The default model is ../shared/data/models/fertility.off relative to the source tree
// (override with --model). The polar balls depend only on the sample, but each level runs
// the whole pipeline end to end, as `rstruct medial` does.

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "rstruct/core/stopwatch.hpp"
#include "rstruct/io/mesh_io.hpp"
#include "rstruct/medial/stable_medial_axis.hpp"
#include "rstruct/sampling/uniform_sampling.hpp"

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

std::vector<double> parse_list(const std::string& text) {
  std::vector<double> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) out.push_back(std::atof(item.c_str()));
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  std::string model = "/work/shared/data/models/fertility.off";
  std::size_t samples = 40000;
  std::vector<double> levels{0.002, 0.005, 0.01, 0.02};
  int runs = 3;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i];
    const std::string value = argv[i + 1];
    if (key == "--model") {
      model = value;
    } else if (key == "--samples") {
      samples = static_cast<std::size_t>(std::atol(value.c_str()));
    } else if (key == "--eps") {
      levels = parse_list(value);
    } else if (key == "--runs") {
      runs = std::max(1, std::atoi(value.c_str()));
    } else {
      std::fprintf(stderr,
                   "usage: bench_medial [--model PATH] [--samples N] [--eps E1,E2,...] "
                   "[--runs R]\n");
      return 2;
    }
  }
  const rstruct::TriangleMesh mesh = rstruct::io::read_mesh(model);
  const std::vector<rstruct::Point3> points =
      rstruct::sampling::sample_mesh_uniform(mesh, samples, 1);
  std::printf("model %s, %zu samples, %d runs (medians)\n", model.c_str(), points.size(), runs);
  std::printf("%8s %8s %6s %8s %6s %8s %8s %8s %8s %8s %9s %9s\n", "eps_rel", "polar", "kept",
              "bound", "gap%", "polar_s", "prune_s", "check_s", "axis_s", "total_s", "betti_U",
              "betti_MA");
  for (const double eps_rel : levels) {
    std::vector<double> polar_s, prune_s, check_s, axis_s, total_s;
    rstruct::medial::StableMedialAxis last;
    for (int r = 0; r < runs; ++r) {
      rstruct::medial::StableMedialAxisOptions options;
      options.eps_rel = eps_rel;
      rstruct::Stopwatch clock;
      last = rstruct::medial::stable_medial_axis(points, options);
      total_s.push_back(clock.seconds());
      polar_s.push_back(last.polar_seconds);
      prune_s.push_back(last.pruning_seconds);
      check_s.push_back(last.check_seconds);
      axis_s.push_back(last.medial_seconds);
    }
    const auto& bu = last.axis_stats.betti_k;
    const auto& bm = last.betti_axis;
    char betti_u[32], betti_m[32];
    std::snprintf(betti_u, sizeof betti_u, "(%lld,%lld,%lld)", bu[0], bu[1], bu[2]);
    std::snprintf(betti_m, sizeof betti_m, "(%lld,%lld,%lld)", bm[0], bm[1], bm[2]);
    std::printf("%8.4f %8zu %6zu %8.1f %6.1f %8.3f %8.3f %8.3f %8.3f %8.3f %9s %9s\n", eps_rel,
                last.inner_poles, last.kept.size(), last.prune.lower_bound,
                100 * last.prune.gap, median(polar_s), median(prune_s), median(check_s),
                median(axis_s), median(total_s), betti_u, betti_m);
    std::fflush(stdout);
  }
  return 0;
}
