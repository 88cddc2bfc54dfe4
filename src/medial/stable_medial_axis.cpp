#include "rstruct/medial/stable_medial_axis.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "rstruct/core/error.hpp"
#include "rstruct/core/report.hpp"
#include "rstruct/poles/ball_sets.hpp"
#include "rstruct/poles/covering_sets.hpp"
#include "rstruct/poles/pole_analysis.hpp"

namespace rstruct::medial {

namespace {

double stage_seconds(const Report& report, std::size_t from) {
  double sum = 0;
  for (std::size_t i = from; i < report.stages().size(); ++i) sum += report.stages()[i].second;
  return sum;
}

void run_axis(StableMedialAxis& out, Report& rep) {
  const std::size_t first = rep.stages().size();
  {
    Report::Stage stage(rep, "medial axis");
    out.axis = medial_axis_of_union(out.kept_balls, &out.axis_stats);
  }
  {
    Report::Stage stage(rep, "medial homology");
    out.betti_axis = complex::betti_numbers(out.axis.simplicial_complex());
  }
  out.medial_seconds = stage_seconds(rep, first);
}

}  // namespace

StableMedialAxis stable_medial_axis(std::span<const Point3> samples,
                                    const StableMedialAxisOptions& options, Report* report) {
  Report scratch;
  Report& rep = report != nullptr ? *report : scratch;
  StableMedialAxis out;
  out.samples = samples.size();

  std::size_t first = rep.stages().size();
  poles::PoleAnalysisOptions pole_options;
  pole_options.threads = options.threads;
  const poles::PoleAnalysis analysis = poles::analyse_poles(samples, pole_options, &rep);
  out.polar_seconds = stage_seconds(rep, first);
  out.bbox_diagonal = analysis.bbox_diagonal;
  out.eps = options.eps >= 0 ? options.eps : options.eps_rel * analysis.bbox_diagonal;
  if (!std::isfinite(out.eps) || out.eps < 0) {
    std::ostringstream msg;
    msg << "medial: epsilon must be finite and non-negative, got " << out.eps;
    throw InvalidInput(msg.str());
  }

  first = rep.stages().size();
  poles::PolarBalls polar;
  {
    Report::Stage stage(rep, "enlarged polar balls");
    polar = poles::inner_polar_balls(analysis.poles, out.eps);
  }
  out.inner_poles = polar.balls.size();
  if (polar.balls.empty()) throw ComputationFailed("medial: no pole is labelled inner");
  out.polar_balls = polar.balls;

  // Covering every sample: the covering matrix of all samples has Σ(covered samples)
  // entries, which grows like ε² and dominated the run time. We solve the set cover on every
  // k-th sample only, then cover the samples the kept balls miss by a second, small set
  // cover (among all balls). A lower bound for a subset of the rows is a lower bound for all rows, so the
  // certified bound stays valid for the whole instance; the gap is against the final size.
  const double spacing = analysis.bbox_diagonal / std::sqrt(static_cast<double>(samples.size()));
  const double shell = 1.0 + out.eps / std::max(spacing, 1e-300);
  // A ball enlarged by ε covers about shell² times the samples it covers at ε = 0 (the
  // ε-shell around its sphere), so every shell²-th sample keeps the matrix near its ε = 0
  // size.
  const auto stride = static_cast<std::size_t>(std::clamp(std::floor(shell * shell), 1.0, 32.0));
  std::vector<Point3> row_points;
  for (std::size_t i = 0; i < samples.size(); i += stride) row_points.push_back(samples[i]);
  out.cover_rows = row_points.size();
  pipeline::PruneOptions prune_options;
  prune_options.seed = options.seed;
  prune_options.threads = options.threads;
  // Time only, as before the seed pipeline got a work budget (not calibrated here).
  prune_options.iterations = 0;
  // Proportional to the need: 0.05 s + 10 ms per thousand rows, at most 1.5 s.
  prune_options.time_limit =
      options.cover_time_limit >= 0
          ? options.cover_time_limit
          : std::min(1.5, 0.05 + 1e-5 * static_cast<double>(row_points.size()));
  out.cover_time_limit = prune_options.time_limit;
  out.prune = pipeline::prune_balls(polar.balls, row_points, prune_options, &rep);
  out.kept = out.prune.kept;
  if (stride > 1) {
    Report::Stage stage(rep, "cover repair");
    std::vector<Ball> kept_balls;
    for (auto k : out.kept) kept_balls.push_back(polar.balls[k]);
    const poles::CoveringSets check = poles::covering_sets(kept_balls, samples, options.threads);
    std::vector<bool> covered(samples.size(), false);
    for (auto r : check.rows) covered[r] = true;
    std::vector<Point3> missed;
    for (std::size_t i = 0; i < samples.size(); ++i) {
      if (!covered[i]) missed.push_back(samples[i]);
    }
    out.repaired_samples = missed.size();
    if (!missed.empty()) {
      // A second, small set cover over all balls for the missed samples.
      pipeline::PruneOptions repair_options = prune_options;
      repair_options.time_limit = std::min(prune_options.time_limit, 0.1);
      Report scratch_report;
      const pipeline::PruneResult repair =
          pipeline::prune_balls(polar.balls, missed, repair_options, &scratch_report);
      out.kept.insert(out.kept.end(), repair.kept.begin(), repair.kept.end());
      std::sort(out.kept.begin(), out.kept.end());
      out.kept.erase(std::unique(out.kept.begin(), out.kept.end()), out.kept.end());
      // The union of both covers is redundant: a last set cover over these balls only and
      // every sample (a small matrix) drops what the other balls cover. Its own bound is
      // not one for the whole instance (columns were removed), so the subset's is kept.
      std::vector<Ball> candidates;
      for (auto k : out.kept) candidates.push_back(polar.balls[k]);
      const pipeline::PruneResult final_cover =
          pipeline::prune_balls(candidates, samples, repair_options, &scratch_report);
      std::vector<std::uint32_t> kept;
      for (auto k : final_cover.kept) kept.push_back(out.kept[k]);
      out.kept = std::move(kept);
      out.prune.kept = out.kept;
      out.prune.entries += final_cover.entries;
      out.prune.cost = static_cast<double>(out.kept.size());
      out.prune.gap = (out.prune.cost - out.prune.lower_bound) / out.prune.cost;
      out.prune.optimal = out.prune.lower_bound >= out.prune.cost;
    }
  }
  for (auto k : out.kept) out.kept_balls.push_back(polar.balls[k]);
  out.pruning_seconds = stage_seconds(rep, first);

  if (options.check_outer_poles) {
    first = rep.stages().size();
    Report::Stage stage(rep, "outer pole check");
    std::vector<Point3> outer;
    for (std::uint32_t p = 0; p < analysis.poles.size(); ++p) {
      if (analysis.poles.label[p] != poles::PoleLabel::outer) continue;
      if (analysis.poles.is_box_pole(p)) {
        ++out.box_poles;
      } else {
        outer.push_back(analysis.poles.centre[p]);
      }
    }
    out.outer_poles = outer.size();
    if (!outer.empty()) {
      const poles::CoveringSets hits = poles::covering_sets(polar.balls, outer, options.threads);
      std::vector<bool> hit(outer.size(), false);
      for (auto r : hits.rows) hit[r] = true;
      out.violations = static_cast<std::size_t>(std::count(hit.begin(), hit.end(), true));
    }
    stage.finish();
    out.check_seconds = stage_seconds(rep, first);
  }

  run_axis(out, rep);
  return out;
}

StableMedialAxis medial_axis_of_balls(std::span<const Ball> balls, Report* report) {
  Report scratch;
  Report& rep = report != nullptr ? *report : scratch;
  StableMedialAxis out;
  out.kept_balls.assign(balls.begin(), balls.end());
  for (std::uint32_t i = 0; i < balls.size(); ++i) out.kept.push_back(i);
  run_axis(out, rep);
  return out;
}

}  // namespace rstruct::medial
