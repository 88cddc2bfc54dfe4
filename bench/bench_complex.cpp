// Benchmark of the complex module (issue 7: "fast at 10^5–10^6 simplices"): building a
// complex from top simplices, Z₂ Betti numbers (coreduction + reduction, and reduction
// alone on the smaller sizes), the closed-2-manifold test, orientation and free-face
// collapse, over a size ladder of generated complexes:
//  - torus surface: an n × n grid on the flat torus, 2n² triangles, β = (1, 2, 1, 0);
//  - solid torus: an n × n × 2n box, periodic in x, Kuhn-subdivided, β = (1, 1, 0, 0);
// each with grid-ordered and with randomly permuted vertex ids (the lexicographic order
// of simplices, hence the reduction's fill-in, follows the ids).
// Prints one line per measurement: complex, labels, simplices, step, median seconds over
// the runs, and a checksum (Betti numbers / counts).
//
//  - torus surface balls: the dual complex path of the seed pipeline (85,100 samples and
//    up), with the regular triangulation timed for reference.
//
// Usage: bench_complex [max_simplices (default 3000000)] [runs (default 3)]

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "rstruct/complex/collapse.hpp"
#include "rstruct/complex/dual_complex.hpp"
#include "rstruct/complex/orthosphere_predicates.hpp"
#include "rstruct/complex/homology.hpp"
#include "rstruct/complex/manifold.hpp"
#include "rstruct/complex/simplicial_complex.hpp"
#include "rstruct/triangulation/regular_triangulation_3.hpp"

using namespace rstruct::complex;

namespace {

std::vector<Triangle> torus_surface(VertexId n) {
  std::vector<Triangle> out;
  const auto id = [n](VertexId i, VertexId j) { return (i % n) + n * (j % n); };
  for (VertexId j = 0; j < n; ++j) {
    for (VertexId i = 0; i < n; ++i) {
      out.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      out.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  }
  return out;
}

/// Box nx × ny × nz of unit cubes, periodic in x (nx ≥ 3), six Kuhn tetrahedra per cube.
std::vector<Tetrahedron> solid_torus(VertexId nx, VertexId ny, VertexId nz) {
  const auto id = [&](VertexId x, VertexId y, VertexId z) {
    return (x % nx) + nx * (y + (ny + 1) * z);
  };
  static constexpr std::array<std::array<int, 3>, 6> kOrders = {
      {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
  std::vector<Tetrahedron> tets;
  for (VertexId z = 0; z < nz; ++z) {
    for (VertexId y = 0; y < ny; ++y) {
      for (VertexId x = 0; x < nx; ++x) {
        for (const auto& order : kOrders) {
          std::array<VertexId, 3> p = {x, y, z};
          Tetrahedron t{id(x, y, z), 0, 0, 0};
          for (int s = 0; s < 3; ++s) {
            ++p[order[s]];
            t[s + 1] = id(p[0], p[1], p[2]);
          }
          tets.push_back(t);
        }
      }
    }
  }
  return tets;
}

template <class Simplex>
void shuffle_labels(std::vector<Simplex>& simplices, std::uint32_t seed) {
  VertexId n = 0;
  for (const auto& s : simplices) n = std::max(n, *std::max_element(s.begin(), s.end()) + 1);
  std::vector<VertexId> perm(n);
  std::iota(perm.begin(), perm.end(), VertexId{0});
  std::mt19937 engine(seed);
  std::shuffle(perm.begin(), perm.end(), engine);
  for (auto& s : simplices) {
    for (auto& v : s) v = perm[v];
  }
}

double median_seconds(int runs, const std::function<void()>& f) {
  std::vector<double> t;
  for (int r = 0; r < runs; ++r) {
    const auto start = std::chrono::steady_clock::now();
    f();
    t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

std::string betti_text(const BettiNumbers& b) {
  // snprintf rather than operator+ chains: GCC 12 warns falsely (-Wrestrict) on those.
  char text[96];
  std::snprintf(text, sizeof text, "(%lld,%lld,%lld,%lld)", static_cast<long long>(b[0]),
                static_cast<long long>(b[1]), static_cast<long long>(b[2]),
                static_cast<long long>(b[3]));
  return text;
}

void report(const char* name, const char* labels, std::size_t simplices, const char* step,
            double seconds, const std::string& checksum) {
  std::printf("%-13s %-8s %10zu  %-22s %9.4f s  %s\n", name, labels, simplices, step, seconds,
              checksum.c_str());
  std::fflush(stdout);
}

template <class Simplex>
void bench_complex(const char* name, const char* labels, const std::vector<Simplex>& top,
                   int runs, bool with_plain_reduction) {
  SimplicialComplex k;
  const double t_build = median_seconds(runs, [&] { k = SimplicialComplex::closure_of(top); });
  const std::size_t n = k.total_size();
  report(name, labels, n, "closure_of", t_build, std::to_string(n) + " simplices");
  BettiNumbers b;
  HomologyStats stats;
  const double t_betti = median_seconds(runs, [&] {
    b = betti_numbers(k, HomologyMethod::coreduction_then_reduction, &stats);
  });
  report(name, labels, n, "betti (coreduction)", t_betti,
         betti_text(b) + " left " + std::to_string(stats.cells_reduced[1] + stats.cells_reduced[2] +
                                                   stats.cells_reduced[3]));
  if (with_plain_reduction) {
    const double t_red = median_seconds(1, [&] {
      b = betti_numbers(k, HomologyMethod::reduction, &stats);
    });
    report(name, labels, n, "betti (reduction)", t_red,
           betti_text(b) + " additions " + std::to_string(stats.column_additions));
  }
  bool manifold = false;
  const double t_man = median_seconds(runs, [&] { manifold = is_closed_2_manifold(k); });
  report(name, labels, n, "closed 2-manifold?", t_man, manifold ? "yes" : "no");
  if (k.dimension() == 2) {
    bool orientable = false;
    const double t_or = median_seconds(runs, [&] { orientable = orient_triangles(k).has_value(); });
    report(name, labels, n, "orient", t_or, orientable ? "orientable" : "not orientable");
  }
  CollapseResult c;
  const double t_col = median_seconds(runs, [&] { c = collapse_free_faces(k); });
  report(name, labels, n, "collapse", t_col,
         std::to_string(c.collapses) + " collapses, " + std::to_string(c.complex.total_size()) +
             " left");
}

/// The seed-polytope path of the pipeline on torus surface balls: jittered nu × nv grid on
/// the torus (1, 0.4), balls B(s, ρ · 0.4) (lfs ≡ 0.4), regular triangulation (reference
/// only, another module), then this module: K, β(K), depth-first collapse, manifold test.
void bench_surface_balls(int nu, int nv, double rho, int runs) {
  const double pi = std::acos(-1.0);
  std::mt19937 engine(5);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  std::vector<rstruct::Point3> centres;
  std::vector<double> weights;
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      const double u = 2 * pi * (i + jitter(engine)) / nu;
      const double v = 2 * pi * (j + jitter(engine)) / nv;
      const double ring = 1 + 0.4 * std::cos(v);
      centres.push_back({ring * std::cos(u), ring * std::sin(u), 0.4 * std::sin(v)});
      weights.push_back(rho * 0.4 * rho * 0.4);
    }
  }
  const std::size_t n = centres.size();
  const auto t0 = std::chrono::steady_clock::now();
  const rstruct::triangulation::RegularTriangulation3 r(centres, weights);
  const double t_tri = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  report("torus-balls", "grid", n, "regular triangulation", t_tri,
         std::to_string(r.number_of_finite_cells()) + " cells (other module)");
  DualComplex dual;
  reset_orthosphere_predicate_counters();
  const double t_dual = median_seconds(runs, [&] { dual = dual_complex(r); });
  const auto counters = orthosphere_predicate_counters();
  report("torus-balls", "grid", n, "dual complex K", t_dual,
         std::to_string(dual.triangulation.total_size()) + " simplices of R, exact stage " +
             std::to_string(counters.exact) + "/" +
             std::to_string(counters.exact + counters.filtered));
  SimplicialComplex k;
  const double t_sub = median_seconds(runs, [&] { k = dual.complex(); });
  report("torus-balls", "grid", n, "K as a complex", t_sub,
         std::to_string(k.total_size()) + " simplices");
  BettiNumbers b;
  const double t_betti = median_seconds(runs, [&] { b = betti_numbers(k); });
  report("torus-balls", "grid", n, "betti(K)", t_betti, betti_text(b));
  CollapseResult c;
  const double t_col =
      median_seconds(runs, [&] { c = collapse_free_faces(k, CollapseOrder::depth_first); });
  report("torus-balls", "grid", n, "collapse (depth-first)", t_col,
         std::to_string(c.complex.size(2)) + " triangles left");
  bool manifold = false;
  const double t_man = median_seconds(runs, [&] { manifold = is_closed_2_manifold(c.complex); });
  report("torus-balls", "grid", n, "closed 2-manifold?", t_man, manifold ? "yes" : "no");
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t max_simplices = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 3000000;
  const int runs = argc > 2 ? std::atoi(argv[2]) : 3;
  std::printf("complex       labels     simplices  step                     median      checksum\n");
  for (const VertexId n : {100u, 300u, 600u}) {
    auto tris = torus_surface(n);
    if (tris.size() * 3 > max_simplices) break;
    bench_complex("torus-surf", "grid", tris, runs, n <= 300);
    shuffle_labels(tris, 1);
    bench_complex("torus-surf", "shuffled", tris, runs, n <= 100);
  }
  for (const VertexId n : {10u, 20u, 32u}) {
    auto tets = solid_torus(2 * n, n, n);
    if (tets.size() * 8 > max_simplices) break;
    bench_complex("solid-torus", "grid", tets, runs, n <= 10);
    shuffle_labels(tets, 2);
    bench_complex("solid-torus", "shuffled", tets, runs, n <= 10);
  }
  for (const int scale : {1, 2, 4}) {
    const int nu = 460 * scale, nv = 185 * scale;  // 85,100 samples at scale 1
    if (static_cast<std::size_t>(nu) * nv * 30 > max_simplices * 4) break;
    bench_surface_balls(nu, nv, 0.4, runs);
  }
  return 0;
}
