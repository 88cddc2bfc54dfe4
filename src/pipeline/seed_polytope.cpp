#include "rstruct/pipeline/seed_polytope.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "rstruct/complex/collapse.hpp"
#include "rstruct/complex/dual_complex.hpp"
#include "rstruct/core/assert.hpp"
#include "rstruct/core/error.hpp"
#include "rstruct/core/report.hpp"
#include "rstruct/poles/ball_parameters.hpp"
#include "rstruct/poles/ball_sets.hpp"
#include "rstruct/predicates/predicates.hpp"
#include "rstruct/triangulation/regular_triangulation_3.hpp"
#include "rstruct/triangulation/spatial_sort.hpp"

namespace rstruct::pipeline {

namespace {

using triangulation::RegularTriangulation3;
using triangulation::VertexId;

constexpr std::uint32_t kNone = 0xffffffffu;

void check_options(const SeedOptions& options, SeedPolytope& out) {
  poles::BallParameters parameters;
  parameters.rho = options.rho;
  parameters.rho_tilde = options.rho_tilde;
  const poles::ParameterCheck check = poles::check_ball_parameters(parameters);
  if (options.rho > 1.0) {
    throw InvalidInput("rho = " + std::to_string(options.rho) +
                       " is absurd: surface balls would reach past the nearest pole");
  }
  if (options.rho_tilde > 0 && options.rho_tilde >= options.rho) {
    throw InvalidInput("rho_tilde must be smaller than rho (Theorem 6.1)");
  }
  out.warnings = check.warnings;
}

/// Output vertex of every sample: the kept ball whose power cell contains it (exact). If
/// that ball's vertex did not survive the collapse, the power cell among the output
/// vertices' balls decides instead (a second regular triangulation, built only if needed).
void map_samples(std::span<const Point3> samples, const RegularTriangulation3& rt,
                 const std::vector<std::uint32_t>& output_vertex_of_ball, SeedPolytope& out) {
  out.sample_vertex.assign(samples.size(), kNone);
  std::vector<std::uint32_t> pending;
  triangulation::CellId hint = triangulation::kNoCell;
  // Queries along a Hilbert curve keep each walk from the previous answer short.
  const std::vector<std::uint32_t> order = triangulation::hilbert_order(samples);
  for (std::uint32_t s : order) {
    const VertexId v = rt.nearest_power_vertex(samples[s], hint);
    hint = rt.incident_cell(v);
    if (output_vertex_of_ball[v] != kNone) {
      out.sample_vertex[s] = output_vertex_of_ball[v];
    } else {
      pending.push_back(s);
    }
  }
  out.remapped_samples = pending.size();
  if (pending.empty() || out.vertex_sample.empty()) return;
  // Balls of the output vertices, in output order (ball k ↔ output vertex k).
  std::vector<Point3> centres;
  std::vector<double> weights;
  for (std::uint32_t ball = 0; ball < output_vertex_of_ball.size(); ++ball) {
    if (output_vertex_of_ball[ball] == kNone) continue;
    centres.push_back(rt.point(ball));
    weights.push_back(rt.weight(ball));
  }
  if (centres.size() < 4) {
    // Too few for a 3D triangulation: compare powers directly (exactly).
    for (std::uint32_t s : pending) {
      std::uint32_t best = 0;
      for (std::uint32_t k = 1; k < centres.size(); ++k) {
        if (predicates::compare_power_distance(samples[s], {centres[k], weights[k]},
                                               {centres[best], weights[best]}) ==
            Sign::negative) {
          best = k;
        }
      }
      out.sample_vertex[s] = best;
    }
    return;
  }
  const RegularTriangulation3 output_rt(std::move(centres), std::move(weights));
  hint = triangulation::kNoCell;
  for (std::uint32_t s : pending) {
    const VertexId k = output_rt.nearest_power_vertex(samples[s], hint);
    hint = output_rt.incident_cell(k);
    out.sample_vertex[s] = k;
  }
}

/// Flips every triangle if the (orientable, closed) surface encloses negative volume.
void orient_outward(std::vector<std::array<std::uint32_t, 3>>& triangles,
                    std::span<const Point3> vertices) {
  double volume6 = 0;  // a measurement: only the sign of a large sum is used
  for (const auto& t : triangles) {
    volume6 += dot(vertices[t[0]], cross(vertices[t[1]], vertices[t[2]]));
  }
  if (volume6 < 0) {
    for (auto& t : triangles) std::swap(t[1], t[2]);
  }
}

}  // namespace

SeedPolytope compute_seed_polytope(std::span<const Point3> samples, const SeedOptions& options,
                                   Report* report) {
  SeedPolytope out;
  check_options(options, out);
  Report scratch;
  Report& rep = report ? *report : scratch;

  const poles::PoleAnalysis analysis = poles::analyse_poles(samples, options.poles, &rep);
  out.labeling = analysis.labeling;
  if (!analysis.labeling.is_clean()) {
    std::ostringstream msg;
    msg << "pole labeling is not clean (" << analysis.labeling.unlabelled << " unlabelled, "
        << analysis.labeling.contradictory << " contradictory poles): is the input an "
        << "r-sample of a closed surface?";
    if (options.require_clean_labels) throw ComputationFailed(msg.str());
    out.warnings.push_back(msg.str());
  }
  out.dhat = analysis.dhat.distance;

  Report::Stage balls_stage(rep, "surface balls");
  const std::vector<Ball> surface = poles::scaled_sample_balls(samples, out.dhat, options.rho);
  out.radius.reserve(surface.size());
  for (const Ball& b : surface) out.radius.push_back(b.r);
  balls_stage.finish();

  if (options.rho_tilde > 0) {
    const std::vector<Ball> shrunk =
        poles::scaled_sample_balls(samples, out.dhat, options.rho_tilde);
    out.prune = prune_balls(shrunk, samples, options.prune, &rep);
    out.kept = out.prune.kept;
    out.pruned = true;
  } else {
    out.kept.resize(samples.size());
    for (std::uint32_t i = 0; i < samples.size(); ++i) out.kept[i] = i;
  }

  Report::Stage rt_stage(rep, "regular triangulation");
  std::vector<Point3> centres;
  std::vector<double> weights;
  std::vector<WeightedPoint> balls;
  centres.reserve(out.kept.size());
  for (std::uint32_t s : out.kept) {
    centres.push_back(samples[s]);
    weights.push_back(surface[s].r * surface[s].r);
    balls.push_back({samples[s], weights.back()});
  }
  const RegularTriangulation3 rt(centres, weights);
  out.hidden_balls = rt.hidden_points().size() + rt.duplicate_points().size();
  std::vector<complex::Tetrahedron> cells;
  cells.reserve(rt.number_of_finite_cells());
  rt.for_each_finite_cell([&](triangulation::CellId c) { cells.push_back(rt.vertices(c)); });
  rt_stage.finish();

  Report::Stage dual_stage(rep, "dual complex");
  const complex::DualComplex dual = complex::dual_complex(balls, cells);
  const complex::SimplicialComplex k = dual.complex();
  out.k_counts = dual.counts();
  out.facet_classes = dual.facet_class_counts();
  dual_stage.finish();

  Report::Stage collapse_stage(rep, "collapse");
  // Depth-first collapse eats through a thick shell from one side, which ends on a closed
  // surface; breadth-first fronts from both sides meet in non-manifold walls (measured in
  // include/rstruct/complex/collapse.hpp).
  const complex::CollapseResult collapsed =
      complex::collapse_free_faces(k, complex::CollapseOrder::depth_first);
  const complex::SimplicialComplex& result = collapsed.complex;
  collapse_stage.finish();

  Report::Stage homology_stage(rep, "homology");
  out.betti_k = complex::betti_numbers(k);
  out.betti_output = complex::betti_numbers(result);
  out.manifold = complex::check_closed_2_manifold(result);
  homology_stage.finish();

  // Output vertices: the kept balls that are vertices of the collapsed complex.
  std::vector<std::uint32_t> output_vertex_of_ball(out.kept.size(), kNone);
  for (complex::VertexId v : result.vertices()) {
    output_vertex_of_ball[v] = static_cast<std::uint32_t>(out.vertex_sample.size());
    out.vertex_sample.push_back(out.kept[v]);
  }
  std::vector<complex::Triangle> oriented;
  bool orientable = false;
  if (out.manifold.is_closed_2_manifold) {
    if (auto o = complex::orient_triangles(result)) {
      oriented = std::move(*o);
      orientable = true;
    }
  }
  const std::vector<complex::Triangle>& tris = orientable ? oriented : result.triangles();
  out.triangles.reserve(tris.size());
  for (const auto& t : tris) {
    out.triangles.push_back({output_vertex_of_ball[t[0]], output_vertex_of_ball[t[1]],
                             output_vertex_of_ball[t[2]]});
  }
  out.oriented = orientable;
  if (orientable) {
    std::vector<Point3> positions;
    positions.reserve(out.vertex_sample.size());
    for (std::uint32_t s : out.vertex_sample) positions.push_back(samples[s]);
    orient_outward(out.triangles, positions);
  }

  Report::Stage map_stage(rep, "sample map");
  map_samples(samples, rt, output_vertex_of_ball, out);
  map_stage.finish();
  return out;
}

}  // namespace rstruct::pipeline
