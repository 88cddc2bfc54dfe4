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
// Usage: bench_complex [max_simplices (default 3000000)] [runs (default 3)]

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "rstruct/complex/collapse.hpp"
#include "rstruct/complex/homology.hpp"
#include "rstruct/complex/manifold.hpp"
#include "rstruct/complex/simplicial_complex.hpp"

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
  return "(" + std::to_string(b[0]) + "," + std::to_string(b[1]) + "," + std::to_string(b[2]) +
         "," + std::to_string(b[3]) + ")";
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
  return 0;
}
