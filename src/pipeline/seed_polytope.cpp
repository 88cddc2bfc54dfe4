#include "rstruct/pipeline/seed_polytope.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <optional>
#include <sstream>
#include <thread>

#include "rstruct/complex/collapse.hpp"
#include "rstruct/complex/dual_complex.hpp"
#include "rstruct/complex/triangulation_dual_complex.hpp"
#include "rstruct/core/assert.hpp"
#include "rstruct/core/error.hpp"
#include "rstruct/core/parallel.hpp"
#include "rstruct/core/report.hpp"
#include "rstruct/poles/ball_parameters.hpp"
#include "rstruct/poles/ball_sets.hpp"
#include "rstruct/predicates/predicates.hpp"
#include "rstruct/triangulation/regular_triangulation_3.hpp"
#include "rstruct/triangulation/spatial_sort.hpp"
#include "rstruct/triangulation/vertex_stars.hpp"

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

/// options.candidates, checked, or every sample.
std::vector<std::uint32_t> candidate_samples(const SeedOptions& options, std::size_t n) {
  std::vector<std::uint32_t> c = options.candidates;
  if (c.empty()) {
    c.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) c[i] = i;
    return c;
  }
  for (std::size_t k = 0; k < c.size(); ++k) {
    if (c[k] >= n || (k > 0 && c[k] <= c[k - 1])) {
      throw InvalidInput("candidates: entry " + std::to_string(k) + " (" +
                         std::to_string(c[k]) + ") is out of range or not increasing (" +
                         std::to_string(n) + " samples)");
    }
  }
  return c;
}

/// Downhill walk in power distance from the vertex `start`: moves to the neighbour of
/// smallest power distance to q while that is smaller than the current vertex's. A power
/// cell is cut out by the vertex's neighbours alone, so the walk ends at a vertex whose
/// power cell contains q; the power distance decreases strictly, so it ends. Exact.
VertexId descend(const RegularTriangulation3& rt, const triangulation::VertexStars& stars,
                 const Point3& q, VertexId start) {
  VertexId best = start;
  WeightedPoint best_ball = rt.weighted_point(best);
  for (;;) {
    VertexId next = best;
    WeightedPoint next_ball = best_ball;
    for (const VertexId u : stars.neighbors(best)) {
      const WeightedPoint ball = rt.weighted_point(u);
      if (predicates::compare_power_distance(q, ball, next_ball) == Sign::negative) {
        next = u;
        next_ball = ball;
      }
    }
    if (next == best) return best;
    best = next;
    best_ball = next_ball;
  }
}

/// The vertex of `rt` whose power cell contains each query (queries[k] = samples[ids[k]]),
/// in parallel chunks of a Hilbert order of the queries. A query starts from `own[id]`
/// when that is a vertex, else from the previous query's answer in its chunk, else from a
/// point location.
std::vector<VertexId> power_cells_of(std::span<const Point3> samples,
                                     std::span<const std::uint32_t> ids,
                                     const RegularTriangulation3& rt,
                                     const triangulation::VertexStars& stars,
                                     std::span<const std::uint32_t> own, unsigned threads) {
  std::vector<Point3> queries;
  queries.reserve(ids.size());
  for (const std::uint32_t s : ids) queries.push_back(samples[s]);
  const std::vector<std::uint32_t> order = triangulation::hilbert_order(queries, threads);
  std::vector<VertexId> answer(ids.size(), kNone);
  parallel_chunks(order.size(), threads, 4096, [&](std::size_t b, std::size_t e, unsigned) {
    VertexId previous = kNone;
    for (std::size_t k = b; k < e; ++k) {
      const std::uint32_t q = order[k];
      const std::uint32_t mine = own.empty() ? kNone : own[ids[q]];
      VertexId start = mine != kNone && rt.is_vertex(mine) ? mine : previous;
      const VertexId v = start != kNone ? descend(rt, stars, queries[q], start)
                                        : rt.nearest_power_vertex(queries[q]);
      answer[q] = v;
      previous = v;
    }
  });
  return answer;
}

/// Output vertex of every sample: the kept ball whose power cell contains it (exact). If
/// that ball's vertex did not survive the collapse, the power cell among the output
/// vertices' balls decides instead (a second regular triangulation, built only if needed).
void map_samples(std::span<const Point3> samples, const RegularTriangulation3& rt,
                 const triangulation::VertexStars& stars,
                 const std::vector<std::uint32_t>& ball_of_sample,
                 const std::vector<std::uint32_t>& output_vertex_of_ball, unsigned threads,
                 SeedPolytope& out) {
  std::vector<std::uint32_t> all(samples.size());
  for (std::uint32_t s = 0; s < samples.size(); ++s) all[s] = s;
  const std::vector<VertexId> ball = power_cells_of(samples, all, rt, stars, ball_of_sample,
                                                    threads);
  out.sample_vertex.assign(samples.size(), kNone);
  std::vector<std::uint32_t> pending;
  for (std::uint32_t s = 0; s < samples.size(); ++s) {
    const std::uint32_t v = output_vertex_of_ball[ball[s]];
    if (v != kNone) {
      out.sample_vertex[s] = v;
    } else {
      pending.push_back(s);
    }
  }
  out.remapped_samples = pending.size();
  if (pending.empty() || out.vertex_sample.empty()) return;
  // Balls of the output vertices, in output order (ball k ↔ output vertex k).
  std::vector<Point3> centres;
  std::vector<double> weights;
  for (std::uint32_t b = 0; b < output_vertex_of_ball.size(); ++b) {
    if (output_vertex_of_ball[b] == kNone) continue;
    centres.push_back(rt.point(b));
    weights.push_back(rt.weight(b));
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
  const triangulation::VertexStars output_stars(output_rt, threads);
  const std::vector<VertexId> vertex =
      power_cells_of(samples, pending, output_rt, output_stars, {}, threads);
  for (std::size_t k = 0; k < pending.size(); ++k) out.sample_vertex[pending[k]] = vertex[k];
}

/// The labelling's counts into `out`; a labelling that is not clean is an error with
/// require_clean_labels, a warning otherwise.
void check_labels(const poles::LabelingStats& labeling, const SeedOptions& options,
                  SeedPolytope& out) {
  out.labeling = labeling;
  if (labeling.is_clean()) return;
  std::ostringstream msg;
  msg << "pole labeling is not clean (" << labeling.unlabelled << " unlabelled, "
      << labeling.contradictory << " contradictory poles): is the input an "
      << "r-sample of a closed surface?";
  if (options.require_clean_labels) throw ComputationFailed(msg.str());
  out.warnings.push_back(msg.str());
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
  {
    SeedPolytope probe;
    check_options(options, probe);  // bad parameters fail before the expensive poles
  }
  candidate_samples(options, samples.size());  // throws on a bad list, in the caller's ids
  Report scratch;
  Report& rep = report ? *report : scratch;
  // The whole pipeline runs on the samples in Hilbert order (position i holds sample
  // order[i]), so that every array indexed by sample is read with locality; the result is
  // mapped back to the caller's sample ids at the end. (A non-finite coordinate keeps
  // the caller's order: the poles stage rejects it with the sample's id.)
  bool finite = true;
  for (const Point3& p : samples) finite = finite && is_finite(p);
  std::vector<std::uint32_t> order;
  if (finite) {
    order = triangulation::hilbert_order(samples, options.threads);
  } else {
    order.resize(samples.size());
    for (std::uint32_t i = 0; i < samples.size(); ++i) order[i] = i;
  }
  std::vector<std::uint32_t> position(samples.size());
  std::vector<Point3> sorted(samples.size());
  for (std::uint32_t i = 0; i < order.size(); ++i) {
    position[order[i]] = i;
    sorted[i] = samples[order[i]];
  }
  SeedOptions sorted_options = options;
  if (!options.candidates.empty()) {
    for (std::uint32_t& c : sorted_options.candidates) c = position[c];
    std::sort(sorted_options.candidates.begin(), sorted_options.candidates.end());
  }
  poles::PoleAnalysisOptions pole_options = options.poles;
  if (pole_options.threads == 0) pole_options.threads = options.threads;
  // With more than one thread the labels are computed beside the level (they are only
  // checked at its end); with one, before it, as analyse_poles does by default.
  const bool beside = poles::label_beside(options.threads);
  pole_options.label = !beside;
  poles::PoleAnalysis analysis = poles::analyse_poles(sorted, pole_options, &rep);
  std::optional<poles::PendingLabels> pending;
  if (beside) pending.emplace(analysis, sorted, pole_options.labeling, &rep);
  SeedPolytope out = compute_seed_polytope(sorted, analysis, sorted_options, &rep,
                                           pending ? &*pending : nullptr);

  const auto to_caller = [&](std::vector<std::uint32_t>& ids, bool sort) {
    for (std::uint32_t& id : ids) id = order[id];
    if (sort) std::sort(ids.begin(), ids.end());
  };
  to_caller(out.kept, true);
  to_caller(out.prune.kept, true);
  to_caller(out.vertex_sample, false);
  const auto unpermute = [&](auto& per_sample) {
    auto copy = per_sample;
    for (std::uint32_t i = 0; i < order.size(); ++i) per_sample[order[i]] = copy[i];
  };
  unpermute(out.sample_vertex);
  unpermute(out.dhat);
  unpermute(out.radius);
  return out;
}

SeedPolytope compute_seed_polytope(std::span<const Point3> samples,
                                   const poles::PoleAnalysis& analysis,
                                   const SeedOptions& options, Report* report,
                                   poles::PendingLabels* pending) {
  SeedPolytope out;
  check_options(options, out);
  if (analysis.dhat.distance.size() != samples.size()) {
    throw InvalidInput("seed polytope: the pole analysis has " +
                       std::to_string(analysis.dhat.distance.size()) + " samples, expected " +
                       std::to_string(samples.size()));
  }
  const std::vector<std::uint32_t> candidates = candidate_samples(options, samples.size());
  Report scratch;
  Report& rep = report ? *report : scratch;

  // Read once: pending->wait() sets it at the end.
  const bool labels_pending = !analysis.labelled;
  if (!labels_pending) {
    check_labels(analysis.labeling, options, out);  // before the expensive stages
  } else if (pending == nullptr || &pending->analysis() != &analysis) {
    throw InvalidInput(std::string("seed polytope: the pole analysis is not labelled and ") +
                       (pending == nullptr ? "no pending labelling was given"
                                           : "the pending labelling is another analysis's"));
  }
  out.dhat = analysis.dhat.distance;

  Report::Stage balls_stage(rep, "surface balls");
  const std::vector<Ball> surface = poles::scaled_sample_balls(samples, out.dhat, options.rho);
  out.radius.reserve(surface.size());
  for (const Ball& b : surface) out.radius.push_back(b.r);
  balls_stage.finish();

  if (options.rho_tilde > 0) {
    const std::vector<Ball> all_shrunk =
        poles::scaled_sample_balls(samples, out.dhat, options.rho_tilde);
    std::vector<Ball> shrunk;
    shrunk.reserve(candidates.size());
    for (const std::uint32_t s : candidates) shrunk.push_back(all_shrunk[s]);
    PruneOptions prune_options = options.prune;
    if (prune_options.threads == 0) prune_options.threads = options.threads;
    out.prune = prune_balls(shrunk, samples, prune_options, &rep);
    for (std::uint32_t& k : out.prune.kept) k = candidates[k];
    out.kept = out.prune.kept;
    out.pruned = true;
  } else {
    out.kept = candidates;
  }

  Report::Stage rt_stage(rep, "regular triangulation");
  // Ball r of the triangulation is sample ball_sample[r]: the kept balls along a Hilbert
  // curve, so that every array indexed by ball (points, stars, flags) is read with
  // locality; in sample order these reads miss the cache once the input outgrows it.
  std::vector<std::uint32_t> ball_sample;
  {
    std::vector<Point3> kept_points;
    kept_points.reserve(out.kept.size());
    for (std::uint32_t s : out.kept) kept_points.push_back(samples[s]);
    ball_sample = triangulation::hilbert_order(kept_points, options.threads);
    for (std::uint32_t& b : ball_sample) b = out.kept[b];
  }
  std::vector<Point3> centres;
  std::vector<double> weights;
  centres.reserve(ball_sample.size());
  weights.reserve(ball_sample.size());
  for (std::uint32_t s : ball_sample) {
    centres.push_back(samples[s]);
    weights.push_back(surface[s].r * surface[s].r);
  }
  // Balls centred on surface samples.
  const auto rt_options = triangulation::TriangulationOptions::for_surface_points(options.threads);
  const RegularTriangulation3 rt(std::move(centres), std::move(weights), rt_options);
  out.hidden_balls = rt.hidden_points().size() + rt.duplicate_points().size();
  out.triangulation = rt.stats();
  rt_stage.finish();

  Report::Stage stars_stage(rep, "vertex stars");
  // The neighbour lists are left to the dual complex's edge pass, which reads every star.
  using triangulation::VertexStars;
  VertexStars stars(rt, options.threads, VertexStars::kCellsPerThread,
                    VertexStars::Neighbors::deferred);
  stars_stage.finish();

  Report::Stage dual_stage(rep, "dual complex");
  complex::TriangulationDualComplex dual =
      complex::classify_dual_complex(rt, stars, options.threads);
  const complex::SimplicialComplex k = std::move(dual.complex);
  for (int d = 0; d < 4; ++d) out.k_counts[static_cast<std::size_t>(d)] = k.size(d);
  out.facet_classes = dual.facet_classes;
  dual_stage.finish();

  // The Betti numbers of K do not depend on the collapse: with two or more threads they are
  // computed on one beside the collapse and the output's checks (all read K, none writes
  // it); one stage, since they overlap.
  Report::Stage collapse_stage(rep, "collapse + homology");
  const auto collapse_and_check = [&] {
    // Depth-first collapse eats through a thick shell from one side, which ends on a closed
    // surface; breadth-first fronts from both sides meet in non-manifold walls (measured
    // in include/rstruct/complex/collapse.hpp).
    complex::CollapseResult c = complex::collapse_free_faces(k, complex::CollapseOrder::depth_first);
    out.betti_output = complex::betti_numbers(c.complex);
    out.manifold = complex::check_closed_2_manifold(c.complex);
    return c;
  };
  complex::CollapseResult collapsed;
  if (thread_count(options.threads, 2) < 2) {
    out.betti_k = complex::betti_numbers(k);
    collapsed = collapse_and_check();
  } else {
    std::exception_ptr betti_error;
    std::thread betti_k([&] {
      try {
        out.betti_k = complex::betti_numbers(k);
      } catch (...) {
        betti_error = std::current_exception();
      }
    });
    try {
      collapsed = collapse_and_check();
    } catch (...) {
      betti_k.join();
      throw;
    }
    betti_k.join();
    if (betti_error) std::rethrow_exception(betti_error);
  }
  const complex::SimplicialComplex& result = collapsed.complex;
  collapse_stage.finish();

  // Output vertices: the kept balls that are vertices of the collapsed complex.
  std::vector<std::uint32_t> output_vertex_of_ball(ball_sample.size(), kNone);
  for (complex::VertexId v : result.vertices()) {
    output_vertex_of_ball[v] = static_cast<std::uint32_t>(out.vertex_sample.size());
    out.vertex_sample.push_back(ball_sample[v]);
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
  std::vector<std::uint32_t> ball_of_sample(samples.size(), kNone);
  for (std::uint32_t b = 0; b < ball_sample.size(); ++b) ball_of_sample[ball_sample[b]] = b;
  map_samples(samples, rt, stars, ball_of_sample, output_vertex_of_ball, options.threads, out);
  map_stage.finish();
  if (labels_pending) {
    Report::Stage wait_stage(rep, "labels (wait)");
    const poles::LabelingStats& labeling = pending->wait();
    wait_stage.finish();
    check_labels(labeling, options, out);
  }
  return out;
}

}  // namespace rstruct::pipeline
