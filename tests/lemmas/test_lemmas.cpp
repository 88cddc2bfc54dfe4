// Property tests of the paper's lemmas on certified r-samples (issue 9, first half):
// Aichholzer et al., "Recovering Structure from r-Sampled Objects", SGP 2009
// (/work/shared/seeds/000_48c8301408300b5e.txt); the constants are re-derived in proofs/
// (proofs/README.md, proofs/ERRATA.md). Random spheres, ellipsoids and tori (random
// parameters, rotation, translation; lemma_instance.hpp for the environment variables),
// certified r-samples with r ≤ 0.08, run through the project's own pipeline (poles, labels,
// D̂, regular triangulations, dual complexes, homology, pruning, seed polytope). For every
// statement the paper's bound is asserted and the tightest observed value is recorded in
// one table, printed last and written to lemmas_table.md in the build directory.
//
// Bounding-box poles: the 8 box sites of the pole analysis stand in for poles at infinity
// (unbounded Voronoi cells). Their polar balls are artefacts of the box, not polar balls of
// S; they are left out of DMAT_out, A_out, Lemma 4.2, Theorem 4.1, Lemma 4.3 and 5.2. With
// them in A_out, Lemma 5.3 fails massively (a box ball meets the outer polar balls of hull
// samples at small angles: with the default seed, 2213 of 104165 edges of the first three
// instances are below 120°, down to 73.6°), which says nothing about the paper.

#include <rapidcheck.h>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <vector>

#include "lemma_geometry.hpp"
#include "lemma_instance.hpp"
#include "lemma_table.hpp"
#include "poles/circumsphere.hpp"
#include "rstruct/complex/dual_complex.hpp"
#include "rstruct/complex/homology.hpp"
#include "rstruct/core/stopwatch.hpp"
#include "rstruct/pipeline/seed_polytope.hpp"
#include "rstruct/poles/ball_sets.hpp"
#include "rstruct/sampling/random.hpp"

namespace lem = rstruct::lemmas;
using lem::Direction;
using lem::Instance;
using lem::Observation;
using rstruct::Point3;
using rstruct::Vec3;
using rstruct::poles::PoleLabel;

namespace {

/// Lemma 4.2's bound as a function of r: dist(p, F) ≥ R_p (sqrt(1 − 4(r² − r⁴/4)) − r²).
double lemma_4_2_bound(double r) {
  return std::sqrt(1.0 - 4.0 * (r * r - r * r * r * r / 4.0)) - r * r;
}

/// All rows of the table, in the order printed.
struct Table {
  Observation l42{"L4.2 dist(p,F)/R_p", "> 0.9807", 0.9807, Direction::at_least};
  Observation l42r{"L4.2 dist(p,F)/R_p − c(r), c(r) = sqrt(1−4(r²−r⁴/4))−r²", "≥ 0 (r certified)",
                   0.0, Direction::at_least};
  Observation t41in{"Thm 4.1 dist(p,M_in)/R_p, inner poles", "≤ 0.2802 (L5.1 proof, r ≤ 0.08)",
                    0.2802, Direction::at_most};
  Observation t41in_c{"Thm 4.1 C = dist(p,M_in)/(r R_p), inner",
                      "O(1) (3.5025 at r = 0.08; reported)", 0.2802 / 0.08, Direction::at_most};
  Observation t41out{"Thm 4.1 dist(p,M_out)/R_p, outer poles (torus)",
                     "≤ 0.2802 (L5.1 proof, r ≤ 0.08)", 0.2802, Direction::at_most};
  Observation t41out_c{"Thm 4.1 C = dist(p,M_out)/(r R_p), outer",
                       "O(1) (3.5025 at r = 0.08; reported)", 0.2802 / 0.08, Direction::at_most};
  Observation l43a{"L4.3a angle(xp, n_x), x ∈ F ∩ B_p [deg]", "≤ 14.99° (r = 0.08)", 14.99,
                   Direction::at_most};
  Observation l43b{"L4.3b penetration (R_p − ‖x−p‖)/lfs(x)", "≤ 0.0114 (3/2 r² lfs)", 0.0114,
                   Direction::at_most};
  Observation l51{"L5.1 lfs(s)/D̂(s)", "≤ 1.2802", 1.2802, Direction::at_most};
  Observation l52a{"L5.2a ‖v−s‖/lfs(s), Voronoi vertex outside its polar ball", "≤ 0.123", 0.123,
                   Direction::at_most};
  Observation l52b{"L5.2b dist(v,F)/lfs(s)", "≤ 0.0355", 0.0355, Direction::at_most};
  Observation l52c{"L5.2b dist(v,F)/lfs(v̄)", "≤ 0.0424", 0.0424, Direction::at_most};
  Observation l53in{"L5.3 exterior angle, edges of A_in [deg]", "≥ 120°", 120.0,
                    Direction::at_least};
  Observation l53out{"L5.3 exterior angle, edges of A_out [deg]", "≥ 120°", 120.0,
                     Direction::at_least};
  Observation l54{"L5.4 ‖m−s‖/min_vertex ‖q−s‖, m ∈ edge/triangle of A", "≥ 0.817", 0.817,
                  Direction::at_least};
  Observation c55lo{"Cor 5.5 dist(s, A_in ∪ A_out)/D̂(s)", "≥ 0.817", 0.817, Direction::at_least};
  Observation c55hi{"Cor 5.5 upper: dist(s, A_in ∪ A_out)/D̂(s)", "≤ 1 (reported)", 1.0,
                    Direction::at_most};
  Observation l56{"L5.6 Betti(K(surface balls)) = Betti(F), ρ ∈ [0.24, 0.56]", "instances failing",
                  0, Direction::count};
  Observation l56f{"L5.6 fibres v→p of U(DMAT_in) crossing ∂U(B_F) not exactly once",
                   "fibres failing", 0, Direction::count};
  Observation t61{"Thm 6.1 Betti(K(pruned balls)) = Betti(F), ρ̃ = 0.03", "instances failing", 0,
                  Direction::count};

  std::vector<Observation*> rows() {
    return {&l42,  &l42r, &t41in, &t41in_c, &t41out, &t41out_c, &l43a,  &l43b, &l51,  &l52a,
            &l52b, &l52c, &l53in, &l53out,  &l54,    &c55lo,    &c55hi, &l56,  &l56f, &t61};
  }
};

/// Records value in row `o` for instance `id`; returns whether it satisfied the bound.
bool record(Observation& o, double value, int id) {
  const long long before = o.failures;
  o.add(value, id);
  return o.failures == before;
}

// ---- Lemma 4.2, Theorem 4.1, Lemma 4.3: one pass over the (non-box) poles -------------

void check_poles(const Instance& in, Table& t) {
  const auto& poles = in.analysis.poles;
  const auto& surface = *in.surface;
  const double c_r = lemma_4_2_bound(in.r_certified);
  for (std::uint32_t p = 0; p < poles.size(); ++p) {
    if (poles.is_box_pole(p)) continue;  // stand-ins for poles at infinity (file comment)
    const Point3 c = poles.centre[p];
    const double rp = poles.radius[p];
    const Point3 x0 = surface.closest_point(c);
    const double dist_f = rstruct::distance(c, x0);
    record(t.l42, dist_f / rp, in.id);
    record(t.l42r, dist_f / rp - c_r, in.id);

    const bool inside = in.pole_inside[p];
    const auto medial =
        inside ? surface.nearest_inner_medial_point(c) : surface.nearest_outer_medial_point(c);
    if (medial) {
      const double d = rstruct::distance(c, *medial);
      record(inside ? t.t41in : t.t41out, d / rp, in.id);
      record(inside ? t.t41in_c : t.t41out_c, d / (in.r_certified * rp), in.id);
    }

    // Lemma 4.3 on surface points x of the closed ball B_p: the four samples on its sphere
    // (boundary of the lens F ∩ B_p) and a grid over the lens around the deepest point x0
    // (the closest point of F to p), projected onto F.
    auto measure = [&](const Point3& x) {
      const double dx = rstruct::distance(x, c);
      if (dx > rp) return;
      const Vec3 n = surface.normal(x) * (inside ? -1.0 : 1.0);  // normal towards p's side
      record(t.l43a, lem::angle_deg(c - x, n), in.id);
      record(t.l43b, (rp - dx) / surface.lfs(x), in.id);
    };
    double extent = 0;
    for (const std::uint32_t v : poles.sites[p]) {
      const Point3& s = in.samples[v];
      extent = std::max(extent, rstruct::distance(s, x0));
      const Vec3 n = surface.normal(s) * (inside ? -1.0 : 1.0);
      record(t.l43a, lem::angle_deg(c - s, n), in.id);
    }
    if (dist_f >= rp) continue;  // F does not enter the open ball
    const Vec3 n0 = surface.normal(x0);
    const Vec3 t1 = rstruct::normalized(std::fabs(n0.x) < 0.6 ? cross(n0, Vec3{1, 0, 0})
                                                              : cross(n0, Vec3{0, 1, 0}));
    const Vec3 t2 = cross(n0, t1);
    constexpr int kGrid = 3;  // (2·3 + 1)² points
    for (int i = -kGrid; i <= kGrid; ++i) {
      for (int j = -kGrid; j <= kGrid; ++j) {
        const double u = extent * i / kGrid, w = extent * j / kGrid;
        measure(surface.closest_point(x0 + t1 * u + t2 * w));
      }
    }
  }
}

// ---- Lemma 5.1 and Lemma 5.2 ---------------------------------------------------------

void check_voronoi_vertices(const Instance& in, Table& t, std::size_t& no_pole_on_side) {
  const auto& poles = in.analysis.poles;
  const auto& surface = *in.surface;
  const std::size_t n = in.samples.size();
  for (std::size_t s = 0; s < n; ++s) {
    record(t.l51, surface.lfs(in.samples[s]) / in.analysis.dhat.distance[s], in.id);
  }
  const auto& tri = *in.delaunay;
  tri.for_each_finite_cell([&](rstruct::triangulation::CellId cell) {
    const auto vs = tri.vertices(cell);
    for (const auto v : vs) {
      if (v >= n) return;  // a box site: not a Voronoi vertex of Vor(S)
    }
    // Not tri.circumcenter(): that plain double construction is inaccurate for the
    // slivers of surface samples (centres off by several lfs were seen); the poles
    // module's circumsphere falls back to exact arithmetic for them.
    const Point3& a = tri.point(vs[0]);
    const Point3 v = a + rstruct::poles::detail::circumsphere(a, tri.point(vs[1]), tri.point(vs[2]),
                                                              tri.point(vs[3]))
                             .offset;
    const bool v_inside = surface.value(v) < 0;
    const Point3 vbar = surface.closest_point(v);
    const double dist_f = rstruct::distance(v, vbar);
    for (const auto s : vs) {
      // The pole of s on v's side of F (ground truth sides).
      std::uint32_t pole = rstruct::poles::kNoPole;
      for (const std::uint32_t q : poles.sample_poles[s]) {
        if (q != rstruct::poles::kNoPole && in.pole_inside[q] == v_inside) pole = q;
      }
      if (pole == rstruct::poles::kNoPole) {
        ++no_pole_on_side;
        continue;
      }
      if (poles.is_box_pole(pole)) continue;  // polar "ball" at infinity: v is inside it
      if (rstruct::distance(v, poles.centre[pole]) < poles.radius[pole]) continue;
      const double lfs_s = surface.lfs(in.samples[s]);
      record(t.l52a, rstruct::distance(v, in.samples[s]) / lfs_s, in.id);
      record(t.l52b, dist_f / lfs_s, in.id);
      record(t.l52c, dist_f / surface.lfs(vbar), in.id);
    }
  });
}

// ---- Lemma 5.3, Lemma 5.4, Corollary 5.5: the α-shapes of the polar balls -------------

struct AlphaShape {
  std::vector<std::uint32_t> pole;  ///< ball k is pole[k]
  rstruct::complex::SimplicialComplex k;
};

AlphaShape alpha_shape(const Instance& in, PoleLabel label, Observation& angles) {
  const auto& poles = in.analysis.poles;
  AlphaShape a;
  std::vector<Point3> centres;
  std::vector<double> weights;
  for (std::uint32_t p = 0; p < poles.size(); ++p) {
    if (poles.label[p] != label || poles.is_box_pole(p)) continue;
    a.pole.push_back(p);
    centres.push_back(poles.centre[p]);
    weights.push_back(poles.radius[p] * poles.radius[p]);
  }
  if (a.pole.size() < 4) return a;  // e.g. a sphere's A_out: no finite outer poles
  const rstruct::triangulation::RegularTriangulation3 regular(centres, weights);
  a.k = rstruct::complex::dual_complex(regular).complex();
  for (const auto& e : a.k.edges()) {
    const std::uint32_t p = a.pole[e[0]], q = a.pole[e[1]];
    record(
        angles,
        lem::exterior_intersection_angle_deg(poles.radius[p], poles.radius[q],
                                             rstruct::distance(poles.centre[p], poles.centre[q])),
        in.id);
  }
  return a;
}

struct UpperBoundFailures {
  long long nearest_pole_not_in_k = 0;  ///< samples whose nearest pole is not a vertex of A
  long long failures = 0;               ///< of which dist(s, A) > D̂(s)
  double worst_excess = 0;              ///< largest dist(s, A)/D̂(s) − 1 among them
  /// Largest distance, over them, from the nearest pole to the nearest vertex of A,
  /// relative to the nearest pole's polar radius.
  double worst_pole_gap = 0;
};

/// Theorem 6.1's shrink factor.
constexpr double kRhoTilde = 0.03;

/// Samples per instance for which Lemma 5.4 is checked against every nearby simplex, and
/// (about) for which Corollary 5.5 is measured: the α-shapes of the poles are thin
/// clusters along the medial axis at distance ≈ D̂(s), so each query meets thousands of
/// simplices; these caps keep the test within the CI budget.
constexpr int kLemma54Samples = 24;
constexpr std::size_t kCorollary55Samples = 1500;

void check_alpha_shapes(const Instance& in, Table& t, UpperBoundFailures& upper) {
  const auto& poles = in.analysis.poles;
  const AlphaShape inner = alpha_shape(in, PoleLabel::inner, t.l53in);
  const AlphaShape outer = alpha_shape(in, PoleLabel::outer, t.l53out);
  // Both complexes in one index; positions are the pole centres.
  std::vector<Point3> position(poles.centre.begin(), poles.centre.end());
  std::vector<lem::EmbeddedSimplex> simplices;
  std::vector<bool> pole_in_k(poles.size(), false);
  for (const AlphaShape* a : {&inner, &outer}) {
    for (const auto v : a->k.vertices()) {
      simplices.push_back({{a->pole[v], 0, 0}, 1});
      pole_in_k[a->pole[v]] = true;
    }
    for (const auto& e : a->k.edges()) simplices.push_back({{a->pole[e[0]], a->pole[e[1]], 0}, 2});
    for (const auto& f : a->k.triangles()) {
      simplices.push_back({{a->pole[f[0]], a->pole[f[1]], a->pole[f[2]]}, 3});
    }
  }
  const lem::SimplexIndex index(std::move(simplices), position);
  std::vector<std::uint32_t> near;
  // Lemma 5.4 with v = s (a sample is outside every open polar ball), for a random subset
  // of the samples: every edge and triangle of A within 2 D̂(s) of s.
  rstruct::sampling::Random random(rstruct::sampling::derive_seed(in.samples.size(), 54));
  for (int k = 0; k < kLemma54Samples; ++k) {
    const std::size_t s = random.below(in.samples.size());
    const Point3& q = in.samples[s];
    const double cap = 2.0 * in.analysis.dhat.distance[s];
    index.within(q, cap, near);
    for (const std::uint32_t i : near) {
      const auto& simplex = index.simplex(i);
      if (simplex.size == 1) continue;
      const double d = std::sqrt(index.squared_distance_to_simplex(q, i));
      if (d > cap) continue;
      double nearest_vertex = HUGE_VAL;
      for (int j = 0; j < simplex.size; ++j) {
        nearest_vertex =
            std::min(nearest_vertex,
                     rstruct::distance(q, index.position(simplex.v[static_cast<std::size_t>(j)])));
      }
      record(t.l54, d / nearest_vertex, in.id);
    }
  }
  // Corollary 5.5 for every step-th sample (all of them in small instances), measured as dist(s, A)
  // ≤ l̃fs(s) (Proposition 2.1: DM ⊆ A). Lower bound: only simplices nearer than the smallest ratio
  // seen so far can lower it, so the search radius is that ratio times D̂(s) (at most D̂(s)); when
  // nothing is that near, the ratio is at least the radius's, which is what is recorded (never
  // above the true ratio, so no violation can be hidden). Upper bound: if the nearest pole
  // is a vertex of A, dist(s, A) ≤ D̂(s) holds and 1 is recorded (never below the true
  // ratio); otherwise dist(s, A) is measured.
  std::vector<std::uint32_t> vertex_tree_ids;
  std::vector<Point3> vertex_positions;
  for (std::uint32_t p = 0; p < poles.size(); ++p) {
    if (pole_in_k[p]) {
      vertex_tree_ids.push_back(p);
      vertex_positions.push_back(poles.centre[p]);
    }
  }
  const rstruct::poles::detail::PointTree vertex_tree(vertex_positions);
  double smallest_ratio = 1.0;
  const std::size_t n = in.samples.size();
  const std::size_t step = (n + kCorollary55Samples - 1) / kCorollary55Samples;
  for (std::size_t s = random.below(step); s < n; s += step) {
    const Point3& q = in.samples[s];
    const double dhat = in.analysis.dhat.distance[s];
    const double cap = smallest_ratio * dhat;
    const double d = index.distance_within(q, cap, near);
    const double lower = (d <= cap ? d : cap) / dhat;
    smallest_ratio = std::min(smallest_ratio, lower);
    record(t.c55lo, lower, in.id);
    double upper_ratio = 1.0;
    if (!pole_in_k[in.analysis.dhat.nearest[s]]) {
      double full = index.distance_within(q, dhat, near);
      if (full == HUGE_VAL) full = std::min(index.distance_within(q, 2.0 * dhat, near), 2.0 * dhat);
      upper_ratio = full / dhat;
      ++upper.nearest_pole_not_in_k;
    }
    if (!record(t.c55hi, upper_ratio, in.id)) {
      upper.worst_excess = std::max(upper.worst_excess, upper_ratio - 1.0);
      ++upper.failures;
      // How far the nearest pole is from a pole that is a vertex of A, relative to its
      // polar radius: the suspected cause is a second, nearly coincident Voronoi vertex.
      const std::uint32_t p = in.analysis.dhat.nearest[s];
      double gap = HUGE_VAL;
      near.clear();  // candidates_within appends
      vertex_tree.candidates_within(poles.centre[p], poles.radius[p], near);
      for (const std::uint32_t k : near) {
        gap = std::min(gap, rstruct::distance(poles.centre[p], poles.centre[vertex_tree_ids[k]]));
      }
      upper.worst_pole_gap = std::max(upper.worst_pole_gap, gap / poles.radius[p]);
    }
  }
}

}  // namespace

TEST_CASE("measurement helpers agree with brute force", "[lemmas]") {
  rc::prop("point-triangle distance is the minimum over the triangle", [] {
    const auto coord = rc::gen::inRange(-1000, 1000);
    auto point = [&] { return Point3{*coord / 100.0, *coord / 100.0, *coord / 100.0}; };
    const Point3 a = point(), b = point(), c = point(), q = point();
    const double d2 = lem::squared_distance_to_triangle(q, a, b, c);
    double brute = HUGE_VAL;
    constexpr int kSteps = 60;
    for (int i = 0; i <= kSteps; ++i) {
      for (int j = 0; i + j <= kSteps; ++j) {
        const double u = static_cast<double>(i) / kSteps, v = static_cast<double>(j) / kSteps;
        brute = std::min(brute, rstruct::squared_distance(q, a + (b - a) * u + (c - a) * v));
      }
    }
    // Never above any point of the triangle, and not much below the grid minimum.
    RC_ASSERT(d2 <= brute * (1 + 1e-12) + 1e-12);
    const double diameter =
        std::max({rstruct::distance(a, b), rstruct::distance(b, c), rstruct::distance(a, c)});
    RC_ASSERT(std::sqrt(brute) - std::sqrt(d2) <= diameter / kSteps + 1e-9);
  });
  rc::prop("segment-ball interval holds exactly the points inside", [] {
    const auto coord = rc::gen::inRange(-100, 100);
    const Point3 a{*coord / 10.0, *coord / 10.0, *coord / 10.0};
    const Point3 b{*coord / 10.0, *coord / 10.0, *coord / 10.0};
    const Point3 c{*coord / 10.0, *coord / 10.0, *coord / 10.0};
    const double radius = *rc::gen::inRange(1, 100) / 10.0;
    const auto interval = lem::segment_ball_interval(a, b, c, radius);
    for (int k = 0; k <= 200; ++k) {
      const double t = k / 200.0;
      const double d = rstruct::distance(a + (b - a) * t, c);
      if (std::fabs(d - radius) < 1e-9 * (1 + radius)) continue;  // on the sphere
      const bool in_interval =
          interval && t >= interval->first - 1e-12 && t <= interval->second + 1e-12;
      RC_ASSERT(in_interval == (d < radius));
    }
  });
  // Exterior angle: tangent spheres 0°, orthogonal ones 90°, concentric-like 180°.
  CHECK(lem::exterior_intersection_angle_deg(1, 1, 2) == Approx(0).margin(1e-6));
  CHECK(lem::exterior_intersection_angle_deg(3, 4, 5) == Approx(90));
  CHECK(lem::exterior_intersection_angle_deg(1, 1, 1e-9) == Approx(180).margin(1e-6));
  CHECK(lemma_4_2_bound(0.08) == Approx(0.980738).margin(1e-6));
  CHECK(lem::cell("|v − s|") == "\\|v − s\\|");  // table cells keep their pipes
}

namespace {

// ---- Lemma 5.6 and Theorem 6.1: surface balls --------------------------------------------

/// Whether the fibre a → b (a on ∂U(DMAT_in), b the centre of a's polar ball, on DM_in)
/// starts in U(B_F) and crosses ∂U(B_F) exactly once: the parameters t ∈ [0, 1] inside
/// the union of surface balls form one interval [0, t*] with t* < 1.
bool fibre_crosses_once(const Point3& a, const Point3& b, std::span<const rstruct::Ball> balls,
                        const rstruct::poles::detail::PointTree& centres, double max_radius,
                        std::vector<std::uint32_t>& scratch) {
  scratch.clear();
  centres.candidates_within((a + b) * 0.5, rstruct::distance(a, b) * 0.5 + max_radius, scratch);
  std::vector<std::pair<double, double>> intervals;
  for (const std::uint32_t k : scratch) {
    if (auto i = lem::segment_ball_interval(a, b, balls[k].c, balls[k].r)) intervals.push_back(*i);
  }
  if (intervals.empty()) return false;
  std::sort(intervals.begin(), intervals.end());
  if (intervals.front().first > 0.0) return false;  // a is not in U(B_F)
  double end = intervals.front().second;
  for (const auto& [lo, hi] : intervals) {
    if (lo > end) return false;  // a gap: the fibre leaves and re-enters U(B_F)
    end = std::max(end, hi);
  }
  return end < 1.0;  // the fibre leaves U(B_F) before reaching the medial axis
}

void check_surface_balls(const Instance& in, Table& t, int fibres_per_instance) {
  const auto balls =
      rstruct::poles::scaled_sample_balls(in.samples, in.analysis.dhat.distance, in.rho);
  std::vector<Point3> centres;
  double max_radius = 0;
  for (const auto& b : balls) {
    centres.push_back(b.c);
    max_radius = std::max(max_radius, b.r);
  }
  // K of the union of all surface balls: regular triangulation, dual complex (α = 0),
  // homology over Z₂.
  std::vector<double> weights;
  for (const auto& ball : balls) weights.push_back(ball.r * ball.r);
  const rstruct::triangulation::RegularTriangulation3 regular(centres, weights);
  const auto betti =
      rstruct::complex::betti_numbers(rstruct::complex::dual_complex(regular).complex());
  INFO("Lemma 5.6: Betti numbers of the union of surface balls " << betti << ", of F "
                                                                 << in.surface_betti);
  CHECK(record(t.l56, betti == in.surface_betti ? 0 : 1, in.id));

  // Fibres from points v on spherical patches of ∂U(DMAT_in) to the centre of their ball:
  // v on the sphere of inner pole p, outside every other inner polar ball.
  const auto& poles = in.analysis.poles;
  std::vector<std::uint32_t> inner;
  std::vector<Point3> inner_centres;
  double max_inner = 0;
  for (std::uint32_t p = 0; p < poles.size(); ++p) {
    if (poles.label[p] != PoleLabel::inner) continue;
    inner.push_back(p);
    inner_centres.push_back(poles.centre[p]);
    max_inner = std::max(max_inner, poles.radius[p]);
  }
  if (inner.empty()) return;
  const rstruct::poles::detail::PointTree inner_tree(inner_centres);
  const rstruct::poles::detail::PointTree sample_tree(centres);
  rstruct::sampling::Random random(rstruct::sampling::derive_seed(in.samples.size(), 56));
  std::vector<std::uint32_t> scratch;
  int fibres = 0;
  for (int attempt = 0; attempt < 20 * fibres_per_instance && fibres < fibres_per_instance;
       ++attempt) {
    const std::uint32_t p = inner[random.below(inner.size())];
    const Point3 c = poles.centre[p];
    const double radius = poles.radius[p];
    // A random point of the spherical cap spanned by the tetrahedron's four samples (the
    // part of ∂B_p that bulges out of F between them, typically on ∂U(DMAT_in)).
    Vec3 sum{};
    for (const std::uint32_t v : poles.sites[p]) {
      sum = sum + rstruct::normalized(in.samples[v] - c) * (random.uniform01() + 1e-3);
    }
    const Vec3 direction = rstruct::normalized(sum);
    const Point3 v = c + direction * radius;
    scratch.clear();
    inner_tree.candidates_within(v, max_inner, scratch);
    bool covered = false;
    for (const std::uint32_t k : scratch) {
      const std::uint32_t q = inner[k];
      if (q != p && rstruct::distance(v, poles.centre[q]) <= poles.radius[q]) covered = true;
    }
    if (covered) continue;
    ++fibres;
    const bool ok = fibre_crosses_once(v, c, balls, sample_tree, max_radius, scratch);
    INFO("fibre from " << v.x << ", " << v.y << ", " << v.z << " to pole " << p);
    CHECK(record(t.l56f, ok ? 0 : 1, in.id));
  }
}

/// Theorem 6.1 through the pipeline (seed_polytope.hpp, which prunes with prune_balls): a
/// set cover of the samples by the shrunk balls B(u, ρ̃ D̂(u)), ρ̃ = 0.03; the union of the
/// kept original balls B(u, ρ D̂(u)) must have F's Betti numbers (K of the kept balls).
void check_pruned_balls(const Instance& in, Table& t, std::size_t& kept, std::size_t& total) {
  rstruct::pipeline::SeedOptions options;
  options.rho = in.rho;
  options.rho_tilde = kRhoTilde;
  options.prune.time_limit = 0.05;  // any cover carries Theorem 6.1; no need for the best
  // The instance's own pole analysis, so the balls are exactly those the other checks use.
  // (The overload without it recomputes the poles on the samples in Hilbert order, whose
  // rounded circumcentres, hence D̂, may differ in the last bits.)
  const auto seed = rstruct::pipeline::compute_seed_polytope(in.samples, in.analysis, options);
  CHECK(seed.dhat == in.analysis.dhat.distance);  // the same D̂ as the pole analysis
  CHECK(seed.pruned);
  kept += seed.kept.size();
  total += in.samples.size();
  INFO("Theorem 6.1: Betti numbers of the pruned union "
       << seed.betti_k << ", of F " << in.surface_betti << ", kept " << seed.kept.size());
  CHECK(record(t.t61, seed.betti_k == in.surface_betti ? 0 : 1, in.id));
}

std::string table_path() {
  if (const char* path = std::getenv("RSTRUCT_LEMMAS_TABLE"); path != nullptr && *path != '\0') {
    return path;
  }
  return RSTRUCT_LEMMAS_TABLE_PATH;
}

std::string fixed(double v, int digits) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.*f", digits, v);
  return buffer;
}

/// Counts gathered over the run for the notes of the table.
struct RunCounts {
  std::size_t no_pole_on_side = 0, kept = 0, total = 0, samples = 0;
  int rho_beyond_proof = 0, rho_outside_6_1 = 0;
  UpperBoundFailures upper;
  double r_lo = HUGE_VAL, r_hi = 0;
};

constexpr int kFibresPerInstance = 150;

/// Builds instance `id`, runs every check on it and asserts the rows' bounds.
void run_instance(const lem::LemmaSettings& settings, int id, Table& t, RunCounts& counts) {
  rstruct::Stopwatch instance_watch;
  const Instance in = lem::make_instance(settings, id);
  std::cout << "  " << in.describe() << " (built in " << fixed(instance_watch.seconds(), 2)
            << " s)\n";
  INFO(in.describe());
  REQUIRE(in.r_certified <= in.r_drawn);
  REQUIRE(in.r_drawn <= lem::kPaperR);
  counts.r_lo = std::min(counts.r_lo, in.r_drawn);
  counts.r_hi = std::max(counts.r_hi, in.r_drawn);
  counts.samples += in.samples.size();
  // The lemmas speak of true inner/outer poles; the α-shapes use the labels.
  const auto& poles = in.analysis.poles;
  std::size_t wrong_labels = 0;
  for (std::uint32_t p = 0; p < poles.size(); ++p) {
    const PoleLabel truth = in.pole_inside[p] ? PoleLabel::inner : PoleLabel::outer;
    if (poles.label[p] != truth) ++wrong_labels;
  }
  CHECK(wrong_labels == 0);
  CHECK(in.analysis.labeling.is_clean());

  std::map<const Observation*, long long> before;
  for (Observation* o : t.rows()) before[o] = o->failures;
  rstruct::Stopwatch watch;
  auto lap = [&watch](const char* next) {
    std::cout << fixed(watch.seconds(), 2) << next << std::flush;
    watch.reset();
  };
  std::cout << "    seconds: poles " << std::flush;
  check_poles(in, t);
  lap(", Voronoi ");
  check_voronoi_vertices(in, t, counts.no_pole_on_side);
  lap(", alpha shapes ");
  check_alpha_shapes(in, t, counts.upper);
  lap(", surface balls ");
  check_surface_balls(in, t, kFibresPerInstance);
  lap(", pruning ");
  check_pruned_balls(in, t, counts.kept, counts.total);
  lap("\n");
  if (in.rho > 0.3979) ++counts.rho_beyond_proof;
  if (in.rho < 0.2815 || in.rho > 0.3272) ++counts.rho_outside_6_1;
  for (Observation* o : t.rows()) {
    if (!o->asserted) continue;  // reported only (see the row's note)
    INFO(o->statement << ": worst " << o->worst << ", bound " << o->constant);
    CHECK(o->failures == before[o]);
  }
}

void write_notes(Table& t, const RunCounts& c) {
  t.l42r.note = "c(0.08) = 0.980738";
  t.t41in.note = "C = " + lem::format_value(t.t41in_c.worst);
  t.t41out.note = "C = " + lem::format_value(t.t41out_c.worst) + "; sphere, ellipsoid: no M_out";
  t.l43a.note = "proof omitted in the paper (ERRATA E7); 4 samples on ∂B_p + 7×7 lens grid";
  t.l43b.note = "proof omitted (E7)";
  t.l51.note = "conditional on L4.3a (E7)";
  t.l52a.note = "box-pole sides skipped; " + std::to_string(c.no_pole_on_side) +
                " (v, s) pairs without a pole on v's side";
  t.l52b.note = "the paper's own argument gives 0.035601 (E2)";
  t.l52c.note = "E2: 0.0425 corrected";
  t.l53in.note =
      "box poles excluded (with them 2213 edges of A_out fail, file comment); E3: only 110.8° "
      "proved";
  t.l53out.note = "box poles excluded";
  t.l54.note = "v = s, " + std::to_string(kLemma54Samples) +
               " samples per instance; edges and triangles of A within 2 D̂(s)";
  t.c55lo.note = "E4: sqrt(2/3) = 0.8165 < 0.817; about " + std::to_string(kCorollary55Samples) +
                 " samples per instance";
  t.c55hi.note = "reported: " + std::to_string(c.upper.nearest_pole_not_in_k) +
                 " samples whose nearest pole is not a vertex of A (hidden); largest excess " +
                 lem::format_value(c.upper.worst_excess) + ", their nearest pole within " +
                 lem::format_value(c.upper.worst_pole_gap) + " R_p of a vertex of A";
  t.l56.note = std::to_string(c.rho_beyond_proof) +
               " instances with ρ > 0.3979, beyond the corrected proof (E5)";
  t.l56f.note = "type-1 fibres of U(DMAT_in) (spherical patch → centre), up to " +
                std::to_string(kFibresPerInstance) + " per instance";
  t.t61.note = std::to_string(c.rho_outside_6_1) +
               " instances with ρ outside [0.2815, 0.3272] (E6); kept " + std::to_string(c.kept) +
               " of " + std::to_string(c.total) + " balls";
}

}  // namespace

TEST_CASE("paper lemmas on certified r-samples of spheres, ellipsoids and tori", "[lemmas]") {
  const lem::LemmaSettings settings = lem::settings_from_environment();
  std::cout << "test_lemmas: RSTRUCT_LEMMAS_SEED=" << settings.seed
            << " RSTRUCT_LEMMAS_INSTANCES=" << settings.instances
            << " RSTRUCT_LEMMAS_RMIN=" << settings.r_min
            << " RSTRUCT_LEMMAS_MAX_POINTS=" << settings.max_points << "\n";
  Table t;
  // Theorem 4.1 states O(r)·R_p without a constant; C is reported against 0.2802/0.08 (the
  // constant that Lemma 5.1's proof gives at r = 0.08). The upper bound of Corollary 5.5 is
  // reported (see the end of this test).
  t.t41in_c.asserted = false;
  t.t41out_c.asserted = false;
  t.c55hi.asserted = false;
  RunCounts counts;
  for (int id = 0; id < settings.instances; ++id) run_instance(settings, id, t, counts);
  write_notes(t, counts);

  std::vector<Observation> rows;
  for (Observation* o : t.rows()) rows.push_back(*o);
  const std::string title =
      "### Lemma property tests (tests/lemmas/test_lemmas): seed " + std::to_string(settings.seed) +
      ", " + std::to_string(settings.instances) + " instances, " + std::to_string(counts.samples) +
      " samples, r ∈ [" + fixed(counts.r_lo, 4) + ", " + fixed(counts.r_hi, 4) + "]";
  const std::string table = lem::markdown_table(rows, title);
  std::ofstream(table_path()) << table;
  std::cout << "\n" << table << std::flush;
  // The upper bound of Corollary 5.5 is reported, not asserted: A only bounds l̃fs from
  // below (Proposition 2.1), so dist(s, A) ≤ D̂(s) is a necessary condition of l̃fs ≤ D̂,
  // not a test of it; and the violations seen are rounding artefacts (the nearest pole
  // nearly coincides with a pole of A that hides it). What is asserted is that they stay
  // below the poles' construction error (poles/circumsphere.hpp: a small multiple of 2⁻²⁶
  // of the circumradius); a larger one would contradict the corollary (up to the box poles
  // left out of A_out).
  INFO("Corollary 5.5 upper bound: largest excess " << counts.upper.worst_excess);
  CHECK(counts.upper.worst_excess <= 0x1p-20);
}
