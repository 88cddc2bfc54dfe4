// Benchmark of the predicates: ns per call of the filtered predicate on random inputs
// (filter path) and on nearly degenerate inputs (exact path), next to a plain double
// evaluation of the same determinant, with filter failure rates; then, on thin nearly
// cospherical cells that the filter leaves undecided, the dynamic filter followed by the
// exact stage against the exact stage alone. Each figure is the median of several runs;
// the machine may be shared, so compare ratios within one run.
//
// Usage: bench_predicates [calls_per_run (default 200000)] [runs (default 7)]
#include <algorithm>
#include <array>
#include <cmath>
#include <ctime>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "predicates/exact_stage.hpp"
#include "rstruct/predicates/detail/dynamic_filter.hpp"
#include "rstruct/predicates/detail/filters.hpp"
#include "rstruct/predicates/detail/polynomials.hpp"
#include "rstruct/predicates/almost_static_filter.hpp"
#include "rstruct/predicates/predicates.hpp"

namespace {

using rstruct::Point3;
using rstruct::WeightedPoint;
namespace pr = rstruct::predicates;
namespace pd = rstruct::predicates::detail;

/// Thread CPU time in ns: on a machine shared by several builds, wall time mostly
/// measures the scheduler.
double thread_cpu_ns() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) * 1e9 + double(ts.tv_nsec);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

/// Minimum ns per call: on a loaded machine the least disturbed run.
bool g_use_min = false;

/// Median ns per call of body(i) over i in [0, calls), several runs. The body is a
/// template parameter, so it is inlined into the timing loop for every predicate and for
/// the plain evaluations alike (no std::function indirection on either side).
template <class Body>
double time_ns(std::size_t calls, int runs, const Body& body, long& checksum) {
  std::vector<double> ns;
  for (int r = 0; r < runs; ++r) {
    const double t0 = thread_cpu_ns();
    long sum = 0;
    for (std::size_t i = 0; i < calls; ++i) sum += body(i);
    const double t1 = thread_cpu_ns();
    checksum += sum;
    ns.push_back((t1 - t0) /
                 static_cast<double>(calls));
  }
  return g_use_min ? *std::min_element(ns.begin(), ns.end()) : median(ns);
}

double plain_orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  return pd::det3(b.x - a.x, b.y - a.y, b.z - a.z, c.x - a.x, c.y - a.y, c.z - a.z, d.x - a.x,
                  d.y - a.y, d.z - a.z);
}

double plain_insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                      const Point3& e) {
  const Point3 ta = a - e, tb = b - e, tc = c - e, td = d - e;
  const pd::LiftedRows<double> r{ta.x, ta.y, ta.z, pd::squared_length(ta.x, ta.y, ta.z),
                                 tb.x, tb.y, tb.z, pd::squared_length(tb.x, tb.y, tb.z),
                                 tc.x, tc.y, tc.z, pd::squared_length(tc.x, tc.y, tc.z),
                                 td.x, td.y, td.z, pd::squared_length(td.x, td.y, td.z)};
  return pd::lifted_det4_negated(r);
}

int sgn(double v) { return (v > 0) - (v < 0); }

struct Inputs {
  std::vector<Point3> p;
  std::vector<double> w;
};

Inputs random_inputs(std::size_t n, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> d(-1, 1);
  Inputs in;
  for (std::size_t i = 0; i < n + 5; ++i) {
    in.p.push_back({d(rng), d(rng), d(rng)});
    in.w.push_back(0.1 * d(rng) * d(rng));
  }
  return in;
}

/// Integer points on the sphere of radius 65 (exactly cospherical), each coordinate then
/// moved by one ulp of 2^-20 with probability 1/2 after scaling by 2^-10: cospherical to
/// about 1e-16 relative, so the filter must give up.
Inputs near_degenerate_inputs(std::size_t n, std::mt19937_64& rng) {
  std::vector<Point3> sphere;
  for (int x = -65; x <= 65; ++x)
    for (int y = -65; y <= 65; ++y)
      for (int z = -65; z <= 65; ++z)
        if (x * x + y * y + z * z == 4225) sphere.push_back({double(x), double(y), double(z)});
  std::uniform_int_distribution<std::size_t> pick(0, sphere.size() - 1);
  Inputs in;
  for (std::size_t i = 0; i < n + 5; ++i) {
    Point3 q = sphere[pick(rng)] * 0x1p-10;
    if (rng() % 2 == 0 && q.x != 0) q.x = std::nextafter(q.x, 2.0);
    in.p.push_back(q);
    in.w.push_back(0);
  }
  return in;
}

/// Coordinates with random exponents in [-500, 500]: the filters' guards fail and the
/// exact stage needs GMP (hundreds of bits between the smallest and largest input).
Inputs wide_inputs(std::size_t n, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> d(0.5, 1);
  std::uniform_int_distribution<int> e(-500, 500);
  Inputs in;
  for (std::size_t i = 0; i < n + 5; ++i) {
    in.p.push_back({std::ldexp(d(rng), e(rng)), std::ldexp(d(rng), e(rng)),
                    std::ldexp(d(rng), e(rng))});
    in.w.push_back(0);
  }
  return in;
}

/// Long, thin cells nearly cospherical with the fifth point (as the balls inscribed in a
/// torus's tube: 10^6 points on a torus sent 2.8 % of their conflict tests past the
/// semi-static filter): three points in a small cap of a unit sphere centred 3 from the
/// origin, two anywhere on it, the fifth moved off the sphere by a relative 10^-11 to
/// 10^-9. Only the 5-tuples the semi-static filter leaves undecided are kept.
std::vector<std::array<Point3, 5>> thin_cospherical_inputs(std::size_t n, std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> cap(-0.03, 0.03), exponent(-11, -9), angle(0, 6.2831853);
  std::vector<std::array<Point3, 5>> out;
  while (out.size() < n) {
    const double phi = angle(rng);
    const Point3 centre{3 * std::cos(phi), 3 * std::sin(phi), 0.1 * normal(rng)};
    const rstruct::Vec3 axis = rstruct::normalized({normal(rng), normal(rng), normal(rng)});
    std::array<Point3, 5> p;
    for (std::size_t i = 0; i < 5; ++i) {
      const rstruct::Vec3 v =
          i < 3 ? rstruct::normalized(axis + rstruct::Vec3{cap(rng), cap(rng), cap(rng)})
                : rstruct::normalized({normal(rng), normal(rng), normal(rng)});
      p[i] = centre + v;
    }
    const double off = std::pow(10.0, exponent(rng)) * (rng() % 2 == 0 ? 1 : -1);
    p[4] = centre + (p[4] - centre) * (1 + off);
    if (pd::orient3d_filter(p[0], p[1], p[2], p[3]) == pd::kUndecided) continue;
    if (pd::insphere_filter(p[0], p[1], p[2], p[3], p[4]) != pd::kUndecided) continue;
    out.push_back(p);
  }
  return out;
}

struct Row {
  std::string name;
  double ns_random, ns_plain, ns_near, failure_rate, ns_wide = -1;
};

}  // namespace

int main(int argc, char** argv) {
  const std::size_t calls = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 200000;
  const int runs = argc > 2 ? std::atoi(argv[2]) : 7;
  if (calls < 1000 || runs < 1) {
    std::fprintf(stderr,
                 "usage: bench_predicates [calls_per_run >= 1000 (default 200000)] "
                 "[runs >= 1 (default 7)] [min]\n");
    return 2;
  }
  g_use_min = argc > 3 && std::string(argv[3]) == "min";
  std::mt19937_64 rng(12345);
  const Inputs rnd = random_inputs(calls, rng);
  const Inputs near = near_degenerate_inputs(calls, rng);
  const Inputs wide = wide_inputs(calls / 50, rng);
  long checksum = 0;
  auto P = [](const Inputs& in, std::size_t i) -> const Point3& { return in.p[i]; };
  auto W = [](const Inputs& in, std::size_t i) { return WeightedPoint{in.p[i], in.w[i]}; };

  std::vector<Row> rows;
  {
    Row r{"orient3d", 0, 0, 0, 0};
    r.ns_random = time_ns(calls, runs, [&](std::size_t i) {
      return long(pr::orient3d(P(rnd, i), P(rnd, i + 1), P(rnd, i + 2), P(rnd, i + 3)));
    }, checksum);
    r.ns_plain = time_ns(calls, runs, [&](std::size_t i) {
      return long(sgn(plain_orient3d(P(rnd, i), P(rnd, i + 1), P(rnd, i + 2), P(rnd, i + 3))));
    }, checksum);
    // Near-degenerate for orient3d: four points of one plane moved by an ulp.
    r.ns_near = time_ns(calls / 20, runs, [&](std::size_t i) {
      const Point3 a = P(near, i), b = P(near, i + 1), c = P(near, i + 2);
      Point3 d = a + (b - a) * 0.5;  // exactly on segment ab up to rounding
      d.z = std::nextafter(d.z, 1e300);
      return long(pr::orient3d(a, b, c, d));
    }, checksum);
    r.ns_wide = time_ns(calls / 50, runs, [&](std::size_t i) {
      return long(pr::orient3d(P(wide, i), P(wide, i + 1), P(wide, i + 2), P(wide, i + 3)));
    }, checksum);
    long undecided = 0;
    for (std::size_t i = 0; i < calls; ++i) {
      undecided += pd::orient3d_filter(P(rnd, i), P(rnd, i + 1), P(rnd, i + 2), P(rnd, i + 3)) ==
                   pd::kUndecided;
    }
    r.failure_rate = double(undecided) / double(calls);
    rows.push_back(r);
  }
  {
    Row r{"insphere", 0, 0, 0, 0};
    r.ns_random = time_ns(calls, runs, [&](std::size_t i) {
      return long(pr::insphere(P(rnd, i), P(rnd, i + 1), P(rnd, i + 2), P(rnd, i + 3),
                               P(rnd, i + 4)));
    }, checksum);
    r.ns_plain = time_ns(calls, runs, [&](std::size_t i) {
      return long(sgn(plain_insphere(P(rnd, i), P(rnd, i + 1), P(rnd, i + 2), P(rnd, i + 3),
                                     P(rnd, i + 4))));
    }, checksum);
    r.ns_near = time_ns(calls / 20, runs, [&](std::size_t i) {
      return long(pr::insphere(P(near, i), P(near, i + 1), P(near, i + 2), P(near, i + 3),
                               P(near, i + 4)));
    }, checksum);
    r.ns_wide = time_ns(calls / 50, runs, [&](std::size_t i) {
      return long(pr::insphere(P(wide, i), P(wide, i + 1), P(wide, i + 2), P(wide, i + 3),
                               P(wide, i + 4)));
    }, checksum);
    long undecided = 0;
    for (std::size_t i = 0; i < calls; ++i) {
      undecided += pd::lifted4_filter<false>(W(rnd, i), W(rnd, i + 1), W(rnd, i + 2),
                                             W(rnd, i + 3), W(rnd, i + 4)) == pd::kUndecided;
    }
    r.failure_rate = double(undecided) / double(calls);
    rows.push_back(r);
  }
  {
    // Almost-static filters (bound fixed once for the box [-1, 1]^3 holding every input).
    const pr::AlmostStaticFilter box({-1, -1, -1}, {1, 1, 1});
    Row o{"orient3d_almost_static", 0, 0, 0, 0};
    o.ns_random = time_ns(calls, runs, [&](std::size_t i) {
      return long(box.orient3d(P(rnd, i), P(rnd, i + 1), P(rnd, i + 2), P(rnd, i + 3)));
    }, checksum);
    o.ns_plain = time_ns(calls, runs, [&](std::size_t i) {
      return long(sgn(plain_orient3d(P(rnd, i), P(rnd, i + 1), P(rnd, i + 2), P(rnd, i + 3))));
    }, checksum);
    o.ns_near = time_ns(calls / 20, runs, [&](std::size_t i) {
      const Point3 a = P(near, i), b = P(near, i + 1), c = P(near, i + 2);
      Point3 d = a + (b - a) * 0.5;
      d.z = std::nextafter(d.z, 1e300);
      return long(box.orient3d(a, b, c, d));
    }, checksum);
    long undecided = 0;
    for (std::size_t i = 0; i < calls; ++i) {
      const double v = plain_orient3d(P(rnd, i), P(rnd, i + 1), P(rnd, i + 2), P(rnd, i + 3));
      undecided += !(std::fabs(v) > box.orient3d_bound());
    }
    o.failure_rate = double(undecided) / double(calls);
    rows.push_back(o);
    Row s{"insphere_almost_static", 0, 0, 0, 0};
    s.ns_random = time_ns(calls, runs, [&](std::size_t i) {
      return long(box.insphere(P(rnd, i), P(rnd, i + 1), P(rnd, i + 2), P(rnd, i + 3),
                               P(rnd, i + 4)));
    }, checksum);
    s.ns_plain = time_ns(calls, runs, [&](std::size_t i) {
      return long(sgn(plain_insphere(P(rnd, i), P(rnd, i + 1), P(rnd, i + 2), P(rnd, i + 3),
                                     P(rnd, i + 4))));
    }, checksum);
    s.ns_near = time_ns(calls / 20, runs, [&](std::size_t i) {
      return long(box.insphere(P(near, i), P(near, i + 1), P(near, i + 2), P(near, i + 3),
                               P(near, i + 4)));
    }, checksum);
    undecided = 0;
    for (std::size_t i = 0; i < calls; ++i) {
      const double v = plain_insphere(P(rnd, i), P(rnd, i + 1), P(rnd, i + 2), P(rnd, i + 3),
                                      P(rnd, i + 4));
      undecided += !(std::fabs(v) > box.insphere_bound());
    }
    s.failure_rate = double(undecided) / double(calls);
    rows.push_back(s);
  }
  {
    Row r{"power_test", 0, 0, 0, 0};
    r.ns_random = time_ns(calls, runs, [&](std::size_t i) {
      return long(pr::power_test(W(rnd, i), W(rnd, i + 1), W(rnd, i + 2), W(rnd, i + 3),
                                 W(rnd, i + 4)));
    }, checksum);
    r.ns_plain = -1;
    r.ns_near = time_ns(calls / 20, runs, [&](std::size_t i) {
      return long(pr::power_test(W(near, i), W(near, i + 1), W(near, i + 2), W(near, i + 3),
                                 W(near, i + 4)));
    }, checksum);
    long undecided = 0;
    for (std::size_t i = 0; i < calls; ++i) {
      undecided += pd::lifted4_filter<true>(W(rnd, i), W(rnd, i + 1), W(rnd, i + 2),
                                            W(rnd, i + 3), W(rnd, i + 4)) == pd::kUndecided;
    }
    r.failure_rate = double(undecided) / double(calls);
    rows.push_back(r);
  }
  {
    Row r{"compare_squared_distance", 0, 0, 0, 0};
    r.ns_random = time_ns(calls, runs, [&](std::size_t i) {
      return long(pr::compare_squared_distance(P(rnd, i), P(rnd, i + 1), P(rnd, i + 2)));
    }, checksum);
    r.ns_plain = time_ns(calls, runs, [&](std::size_t i) {
      return long(sgn(rstruct::squared_distance(P(rnd, i), P(rnd, i + 1)) -
                      rstruct::squared_distance(P(rnd, i), P(rnd, i + 2))));
    }, checksum);
    r.ns_near = time_ns(calls / 20, runs, [&](std::size_t i) {
      return long(pr::compare_squared_distance({0, 0, 0}, P(near, i), P(near, i + 1)));
    }, checksum);
    r.failure_rate = 0;
    rows.push_back(r);
  }
  std::printf("# bench_predicates: %zu calls/run, %s of %d runs (shared machine: compare "
              "ratios only)\n", calls, g_use_min ? "minimum" : "median", runs);
  std::printf("%-26s %12s %12s %8s %14s %8s %14s %12s\n", "predicate", "filtered_ns",
              "plain_ns", "ratio", "near_degen_ns", "x_filt", "filter_fail", "gmp_wide_ns");
  for (const Row& r : rows) {
    std::printf("%-26s %12.2f %12.2f %8.2f %14.1f %8.1f %14.3g %12.1f\n", r.name.c_str(),
                r.ns_random, r.ns_plain, r.ns_plain > 0 ? r.ns_random / r.ns_plain : 0.0,
                r.ns_near, r.ns_near / r.ns_random, r.failure_rate, r.ns_wide);
  }
  {
    // After the semi-static filter: the dynamic filter, then (if it cannot decide) the
    // exact stage, against the exact stage alone.
    const auto thin = thin_cospherical_inputs(calls / 20, rng);
    const auto T = [&](std::size_t i) -> const std::array<Point3, 5>& {
      return thin[i % thin.size()];
    };
    const double after_filter = time_ns(thin.size() - 5, runs, [&](std::size_t i) {
      const auto& p = T(i);
      return long(pd::insphere_after_filter(p[0], p[1], p[2], p[3], p[4]));
    }, checksum);
    const double exact_only = time_ns(thin.size() - 5, runs, [&](std::size_t i) {
      const auto& p = T(i);
      return long(pd::lifted4_exact({p[0], 0}, {p[1], 0}, {p[2], 0}, {p[3], 0}, {p[4], 0}));
    }, checksum);
    std::size_t decided = 0;
    for (const auto& p : thin) {
      decided += pd::lifted4_dynamic_filter<false>(p[0], p[1], p[2], p[3], p[4], 0, 0, 0, 0, 0) !=
                 pd::kUndecided;
    }
    std::printf("insphere on %zu thin, nearly cospherical cells the filter leaves undecided: "
                "dynamic filter then exact %.1f ns, exact stage alone %.1f ns; the dynamic "
                "filter decides %.1f %%\n",
                thin.size(), after_filter, exact_only,
                100.0 * static_cast<double>(decided) / static_cast<double>(thin.size()));
  }
  std::printf("checksum %ld\n", checksum);
  return 0;
}
