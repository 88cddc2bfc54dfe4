// Benchmark of the sampling module: certified r-samples over a ladder of r for the sphere,
// the torus with R/a = 3 and the 3:2:1 ellipsoid, and the paper's 85,237-point double
// torus (uniform by area). Prints medians over `runs` repetitions (argv[1], default 3) of
// generation and certification seconds, with the point count and the certified bound as
// checksums.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "rstruct/core/stopwatch.hpp"
#include "rstruct/sampling/double_torus.hpp"
#include "rstruct/sampling/ellipsoid.hpp"
#include "rstruct/sampling/r_sample.hpp"
#include "rstruct/sampling/sphere.hpp"
#include "rstruct/sampling/torus.hpp"
#include "rstruct/sampling/uniform_sampling.hpp"

using namespace rstruct;
using namespace rstruct::sampling;

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

void bench_r_sample(const Surface& s, double r, int runs) {
  std::vector<double> gen, cert;
  RSample last;
  for (int i = 0; i < runs; ++i) {
    RSampleOptions o;
    o.seed = 1;
    last = generate_r_sample(s, r, o);
    gen.push_back(last.generation_seconds);
    cert.push_back(last.certification_seconds);
  }
  std::printf("%-30s %6.3f %9zu %9.3f %9.3f %10.5f %10.5f %10zu\n", s.name().c_str(), r,
              last.points.size(), median(gen), median(cert), last.certificate.upper_bound,
              last.certificate.grid_max, last.certificate.leaf_cells);
}

}  // namespace

int main(int argc, char** argv) {
  const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 3;
  std::printf("# medians over %d runs; other processes may load the machine\n", runs);
  std::printf("%-30s %6s %9s %9s %9s %10s %10s %10s\n", "surface", "r", "points", "gen_s", "cert_s",
              "certified", "grid_max", "leaf_cells");
  const Sphere sphere(1.0);
  const Torus torus(3.0, 1.0);
  const Ellipsoid ellipsoid(3.0, 2.0, 1.0);
  for (double r : {0.16, 0.08, 0.04}) {
    bench_r_sample(sphere, r, runs);
    bench_r_sample(torus, r, runs);
    bench_r_sample(ellipsoid, r, runs);
  }
  bench_r_sample(sphere, 0.02, runs);
  const DoubleTorus dt;
  std::vector<double> seconds;
  std::size_t count = 0;
  for (int i = 0; i < runs; ++i) {
    Stopwatch clock;
    count = sample_uniform(dt, 85237, 2009).size();
    seconds.push_back(clock.seconds());
  }
  std::printf("double-torus uniform n=%zu: %.3f s (median)\n", count, median(seconds));
  return 0;
}
