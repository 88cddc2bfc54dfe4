// Reproduces the sample points of bench/bench_setcover.cpp geometric_instance (same RNG calls)
// and writes "x y z" per line, so rows can be grouped into geometric patches.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>
struct Point { double x, y, z; };
constexpr double kMajor = 3.0, kMinor = 1.0, kShift = 2.6;
Point torus_point(std::mt19937_64& rng, double cx) {
  std::uniform_real_distribution<double> angle(0.0, 2.0 * M_PI), unit(0.0, 1.0);
  while (true) {
    const double u = angle(rng), v = angle(rng);
    if (unit(rng) * (kMajor + kMinor) > kMajor + kMinor * std::cos(v)) continue;
    const double w = kMajor + kMinor * std::cos(v);
    return {cx + w * std::cos(u), w * std::sin(u), kMinor * std::sin(v)};
  }
}
bool inside_torus(const Point& p, double cx) {
  const double rho = std::hypot(p.x - cx, p.y) - kMajor;
  return rho * rho + p.z * p.z < kMinor * kMinor;
}
int main(int argc, char** argv) {
  const bool dt = std::atoi(argv[1]) != 0;
  const int n = argc > 2 ? std::atoi(argv[2]) : 100000;
  const unsigned long long seed = argc > 3 ? std::strtoull(argv[3], nullptr, 10) : 1;
  std::mt19937_64 rng(seed);
  std::vector<Point> pts;
  while ((int)pts.size() < n) {
    const double cx = dt ? (rng() % 2 == 0 ? -kShift : kShift) : 0.0;
    const Point p = torus_point(rng, cx);
    if (dt && inside_torus(p, -cx)) continue;
    pts.push_back(p);
  }
  for (auto& p : pts) std::printf("%.17g %.17g %.17g\n", p.x, p.y, p.z);
}
