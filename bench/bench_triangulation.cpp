// Benchmark of RegularTriangulation3 (issue 4): Delaunay of uniform points in a cube over a
// size ladder, of points on a torus surface, and the regular triangulation of weighted
// points (some hidden). Every case runs in a forked child so that its peak resident memory
// is its own; each case runs --runs times and the medians are printed.
//
// Usage: bench_triangulation [--runs R] [--max N] [--huge] [--case NAME] [--threads T]
//                            [--scheme automatic|borders|locks] [--canonical] [--brio D]
//                            [--warm-pages]
//   --max N   largest uniform size of the ladder (default 1e6); --huge adds 1e7.
//   --threads T  insertion threads (default 1, the targets are single-thread).
//   --scheme S   how the parallel passes share the work (TriangulationOptions).
//   --canonical  number the cells in the canonical order (counted in the insertion time).
//   --brio D     BRIO rounds of 1/D (TriangulationOptions::brio_divisor, default 4).
//   --warm-pages before every run, touch and free 800 bytes per point (at least 64 MiB) of
//                transparent huge pages, so that the run's large blocks get pages that the
//                VM's host has not taken back (this VM hands idle memory back: a cold cell
//                array costs about 0.3 s at 10^6 points; bench/HISTORY.md, 2026-12-08).
// Columns: case, points, vertices, finite cells, hidden+merged, sort s, insertion s,
// total wall and CPU s, bytes per point (peak RSS minus RSS before the points were generated, so the
// input points, which the triangulation owns, are included), walk steps and conflict
// cells per point, the filter's failure rate (the share of the conflict search's insphere /
// power tests on finite cells that the almost-static filter's floating-point stages left
// undecided: TriangulationStats::filter_misses), the share of predicate calls that reached
// the exact stage (neither the filter nor, for the in-sphere and power tests, the dynamic
// filter could decide; only in a build with -Dcounters=true, otherwise n/a), and the share
// of points the parallel passes deferred to the sequential one.
#include <sys/mman.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "rstruct/core/stopwatch.hpp"
#include "rstruct/predicates/counters.hpp"
#include "rstruct/triangulation/regular_triangulation_3.hpp"

namespace {

using rstruct::Point3;
using rstruct::triangulation::RegularTriangulation3;

struct Result {
  double points, vertices, cells, removed, sort_s, insert_s, total_s, cpu_s, bytes_per_point,
      walk_per_point, conflict_per_point, filter_misses, exact_share, deferred;
};

/// CPU seconds of this process: on a loaded machine the wall clock also counts the time
/// other jobs hold the cores, so both are printed.
double cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

std::uint64_t mix(std::uint64_t& s) {
  std::uint64_t z = (s += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}
double unit(std::uint64_t& s) { return static_cast<double>(mix(s) >> 11) * 0x1p-53; }

std::vector<Point3> uniform_cube(std::size_t n, std::uint64_t seed) {
  std::vector<Point3> p(n);
  for (Point3& q : p) q = {unit(seed), unit(seed), unit(seed)};
  return p;
}

std::vector<Point3> torus(std::size_t n, std::uint64_t seed) {
  const double big = 1.0;
  const double small = 0.35;
  std::vector<Point3> p(n);
  for (Point3& q : p) {
    const double u = 2 * M_PI * unit(seed);
    const double v = 2 * M_PI * unit(seed);
    q = {(big + small * std::cos(v)) * std::cos(u), (big + small * std::cos(v)) * std::sin(u),
         small * std::sin(v)};
  }
  return p;
}

double exact_stage_share() {
  namespace pr = rstruct::predicates;
  if (!pr::counters_enabled()) return -1;
  std::uint64_t all = 0;
  std::uint64_t slow = 0;
  for (int i = 0; i < static_cast<int>(pr::PredicateId::count_); ++i) {
    const pr::StageCounts c = pr::stage_counts(static_cast<pr::PredicateId>(i));
    all += c.total();
    slow += c.exact + c.perturbed;
  }
  return all == 0 ? 0.0 : static_cast<double>(slow) / static_cast<double>(all);
}

unsigned g_threads = 1;
rstruct::triangulation::TriangulationOptions::ParallelScheme g_scheme =
    rstruct::triangulation::TriangulationOptions::ParallelScheme::automatic;
bool g_canonical = false;
std::uint32_t g_brio_divisor = rstruct::triangulation::TriangulationOptions{}.brio_divisor;

Result run_case(const std::string& name, std::size_t n, std::uint64_t seed) {
  const std::size_t before = rstruct::current_memory_bytes();
  std::vector<Point3> points = name == "torus" ? torus(n, seed) : uniform_cube(n, seed);
  std::vector<double> weights;
  if (name == "weighted") {
    // Weights up to (0.8 x mean spacing)^2: a few percent of the points end up hidden.
    const double spacing = std::cbrt(1.0 / static_cast<double>(n));
    weights.resize(n);
    for (double& w : weights) w = unit(seed) * 0.64 * spacing * spacing;
  }
  rstruct::predicates::reset_stage_counts();
  const double cpu0 = cpu_seconds();
  rstruct::Stopwatch clock;
  rstruct::triangulation::TriangulationOptions options;
  options.threads = g_threads;
  options.parallel_scheme = g_scheme;
  options.canonical_order = g_canonical;
  options.brio_divisor = g_brio_divisor;
  const RegularTriangulation3 t =
      weights.empty() ? RegularTriangulation3(std::move(points), options)
                      : RegularTriangulation3(std::move(points), std::move(weights), options);
  const double total = clock.seconds();
  const double cpu = cpu_seconds() - cpu0;
  const double peak = static_cast<double>(rstruct::peak_memory_bytes());
  const double dn = static_cast<double>(n);
  const auto& s = t.stats();
  return {dn,
          static_cast<double>(t.number_of_vertices()),
          static_cast<double>(t.number_of_finite_cells()),
          static_cast<double>(t.hidden_points().size() + t.duplicate_points().size()),
          s.sort_seconds,
          s.insertion_seconds,
          total,
          cpu,
          (peak - static_cast<double>(before)) / dn,
          static_cast<double>(s.walk_steps) / dn,
          static_cast<double>(s.conflict_cells) / dn,
          s.power_test_calls == 0 ? 0.0
                                  : static_cast<double>(s.filter_misses) /
                                        static_cast<double>(s.power_test_calls),
          exact_stage_share(),
          static_cast<double>(s.deferred_points) / dn};
}

bool g_warm_pages = false;

/// Touches and frees `bytes` of transparent huge pages (--warm-pages).
void warm_pages(std::size_t bytes) {
  constexpr std::size_t kHuge = std::size_t{2} << 20;
  void* raw = mmap(nullptr, bytes + kHuge, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS,
                   -1, 0);
  if (raw == MAP_FAILED) return;
  const auto base = (reinterpret_cast<std::uintptr_t>(raw) + kHuge - 1) & ~(kHuge - 1);
  volatile char* const p = reinterpret_cast<char*>(base);
  (void)madvise(reinterpret_cast<void*>(base), bytes, MADV_HUGEPAGE);
  for (std::size_t i = 0; i < bytes; i += 4096) p[i] = 1;
  munmap(raw, bytes + kHuge);
}

// Runs one case in a child process; the result comes back through a pipe.
bool run_forked(const std::string& name, std::size_t n, std::uint64_t seed, Result& out) {
  if (g_warm_pages) warm_pages(std::max<std::size_t>(800 * n, std::size_t{64} << 20));
  int fd[2];
  if (pipe(fd) != 0) return false;
  const pid_t pid = fork();
  if (pid == 0) {
    close(fd[0]);
    Result r{};
    try {
      r = run_case(name, n, seed);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "%s %zu: %s\n", name.c_str(), n, e.what());
      _exit(1);
    }
    const ssize_t written = write(fd[1], &r, sizeof r);
    _exit(written == static_cast<ssize_t>(sizeof r) ? 0 : 1);
  }
  close(fd[1]);
  const ssize_t got = read(fd[0], &out, sizeof out);
  close(fd[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  return got == static_cast<ssize_t>(sizeof out) && WIFEXITED(status) &&
         WEXITSTATUS(status) == 0;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

void bench(const std::string& name, std::size_t n, int runs) {
  std::vector<Result> rs;
  for (int r = 0; r < runs; ++r) {
    Result x{};
    if (!run_forked(name, n, 0x1234567ull + static_cast<std::uint64_t>(r), x)) {
      std::printf("%-9s %10zu  FAILED\n", name.c_str(), n);
      return;
    }
    rs.push_back(x);
  }
  const auto med = [&](double Result::*f) {
    std::vector<double> v;
    for (const Result& x : rs) v.push_back(x.*f);
    return median(v);
  };
  std::printf("%-9s %10zu %10.0f %11.0f %8.0f %7.3f %7.3f %7.3f %7.3f %7.1f %6.2f %6.2f %9.2e",
              name.c_str(), n, med(&Result::vertices), med(&Result::cells),
              med(&Result::removed), med(&Result::sort_s), med(&Result::insert_s),
              med(&Result::total_s), med(&Result::cpu_s),
              med(&Result::bytes_per_point), med(&Result::walk_per_point),
              med(&Result::conflict_per_point), med(&Result::filter_misses));
  const double f = med(&Result::exact_share);
  if (f >= 0) {
    std::printf(" %9.2e", f);
  } else {
    std::printf("       n/a");
  }
  std::printf(" %6.2f%%\n", 100 * med(&Result::deferred));
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  int runs = 3;
  double max = 1e6;
  bool huge = false;
  std::string only;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--runs" && i + 1 < argc) {
      runs = std::max(1, std::atoi(argv[++i]));
    } else if (a == "--max" && i + 1 < argc) {
      max = std::atof(argv[++i]);
    } else if (a == "--huge") {
      huge = true;
    } else if (a == "--case" && i + 1 < argc) {
      only = argv[++i];
    } else if (a == "--threads" && i + 1 < argc) {
      g_threads = static_cast<unsigned>(std::max(0, std::atoi(argv[++i])));
    } else if (a == "--scheme" && i + 1 < argc) {
      using Scheme = rstruct::triangulation::TriangulationOptions::ParallelScheme;
      const std::string v = argv[++i];
      if (v != "automatic" && v != "borders" && v != "locks") {
        std::fprintf(stderr, "--scheme: automatic, borders or locks\n");
        return 2;
      }
      g_scheme = v == "borders" ? Scheme::borders
                 : v == "locks"   ? Scheme::locks
                                  : Scheme::automatic;
    } else if (a == "--warm-pages") {
      g_warm_pages = true;
    } else if (a == "--canonical") {
      g_canonical = true;
    } else if (a == "--brio" && i + 1 < argc) {
      const int d = std::atoi(argv[++i]);
      if (d < 2) {
        std::fprintf(stderr, "--brio: a divisor of at least 2\n");
        return 2;
      }
      g_brio_divisor = static_cast<std::uint32_t>(d);
    } else {
      std::fprintf(stderr,
                   "usage: %s [--runs R] [--max N] [--huge] [--case NAME] [--threads T] "
                   "[--scheme automatic|borders|locks] [--canonical] [--brio D] "
                   "[--warm-pages]\n",
                   argv[0]);
      return 2;
    }
  }
  std::printf("# medians of %d runs, %u insertion thread(s); the machine may be loaded by other jobs\n",
              runs, g_threads);
  std::printf("%-9s %10s %10s %11s %8s %7s %7s %7s %7s %7s %6s %6s %9s %9s %7s\n", "case",
              "points", "vertices", "fin.cells", "removed", "sort_s", "ins_s", "total_s",
              "cpu_s", "B/pt", "walk", "confl", "filt.miss", "exact", "defer");
  const auto want = [&](const char* c) { return only.empty() || only == c; };
  if (want("uniform")) {
    for (double n = 1e4; n <= max * 1.0001; n *= 10) bench("uniform", std::size_t(n), runs);
    if (huge) bench("uniform", 10000000, 1);
  }
  if (want("torus")) bench("torus", std::size_t(std::min(max, 1e6)), runs);
  if (want("weighted")) bench("weighted", std::size_t(std::min(max, 1e6)), runs);
  return 0;
}
