#include "rstruct/poles/pole_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <span>
#include <sstream>

#if defined(__linux__)
#include <pthread.h>
#include <sched.h>
#endif

#include "resumable_labeling.hpp"
#include "rstruct/core/error.hpp"
#include "rstruct/core/parallel.hpp"
#include "rstruct/core/stopwatch.hpp"
#include "rstruct/triangulation/regular_triangulation_3.hpp"

namespace rstruct::poles {
namespace {

Box3 checked_bounding_box(std::span<const Point3> samples) {
  if (samples.size() < 4) {
    throw InvalidInput("poles: need at least 4 samples, got " + std::to_string(samples.size()));
  }
  Box3 box;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    if (!is_finite(samples[i])) {
      throw InvalidInput("poles: sample " + std::to_string(i) + " has a non-finite coordinate");
    }
    box.add(samples[i]);
  }
  if (!(box.max_extent() > 0)) throw InvalidInput("poles: all samples coincide");
  return box;
}

/// The finite cells as a flat array (in the triangulation's cell array, which it takes),
/// and each sample's representative vertex.
struct Soup {
  triangulation::CellQuadruples tets;
  std::vector<std::uint32_t> representative;
};

/// The Delaunay triangulation's finite cells, in id order, each with its vertex ids
/// sorted: a tetrahedron's circumcentre is computed from the same vertex order whatever
/// the triangulation stored (with parallel insertion, that depends on timing). The cells
/// are compacted over the cell array instead of copied to a new one, whose pages were
/// touched for the first time (about 1.8 s per GB on this machine), and the cells' pages
/// past them go back to the allocator for compute_poles. 10^6 torus samples (bench_seed
/// --torus 1000000 --levels 0.5:0.03), 5 interleaved pairs: the delaunay stage, which
/// includes the soup, 6.46-7.03 -> 5.71-6.32 s; the poles stage 1.31-1.49 -> 1.55-1.82 s
/// (its circumcentres no longer fit in pages the triangulation freed); end to end, median
/// 15.54 -> 15.08 s; peak memory 1377 -> 1204 MiB.
Soup soup_of(triangulation::DelaunayCells& dt, std::size_t sample_count) {
  Soup soup;
  soup.representative.resize(sample_count);
  for (std::uint32_t s = 0; s < sample_count; ++s) soup.representative[s] = s;
  for (const auto& d : dt.duplicates) {
    if (d.point < sample_count) soup.representative[d.point] = d.vertex;
  }
  soup.tets = std::move(dt.cells);
  return soup;
}

void record_labels(Report& report, const LabelingStats& l) {
  auto& j = report.data()["poles"];
  j["inner"] = l.inner;
  j["outer"] = l.outer;
  j["unlabelled"] = l.unlabelled;
  j["ties"] = l.ties;
  j["contradictory"] = l.contradictory;
  j["inconsistent_samples"] = l.inconsistent_samples;
  j["samples_without_inner_pole"] = l.samples_without_inner;
  j["label_pairs_examined"] = l.pairs_examined;
}

void record(Report& report, const PoleAnalysis& analysis) {
  auto& j = report.data()["poles"];
  j["samples"] = analysis.poles.sample_count;
  j["duplicate_samples"] = analysis.duplicate_samples;
  j["tetrahedra"] = analysis.tetrahedra;
  j["poles"] = analysis.poles.size();
  const triangulation::TriangulationStats& d = analysis.delaunay;
  j["delaunay_threads"] = d.threads;
  j["delaunay_parallel_points"] = d.parallel_points;
  j["delaunay_deferred_points"] = d.deferred_points;
  j["delaunay_border_passes"] = d.border_passes;
  j["delaunay_lock_passes"] = d.lock_passes;
  j["labelled"] = analysis.labelled;
  if (analysis.labelled) record_labels(report, analysis.labeling);
}

}  // namespace

std::vector<Point3> bounding_box_sites(std::span<const Point3> samples, double box_scale) {
  if (!std::isfinite(box_scale) || box_scale < 2) {
    std::ostringstream message;
    message << "poles: box scale " << box_scale << " must be finite and >= 2";
    throw InvalidInput(message.str());
  }
  const Box3 box = checked_bounding_box(samples);
  const Point3 centre = box.centre();
  const double h = box_scale * box.max_extent();
  std::vector<Point3> sites;
  for (int k = 0; k < 8; ++k) {
    sites.push_back({centre.x + ((k & 1) != 0 ? h : -h), centre.y + ((k & 2) != 0 ? h : -h),
                     centre.z + ((k & 4) != 0 ? h : -h)});
  }
  return sites;
}

PoleAnalysis analyse_poles(std::span<const Point3> samples, const PoleAnalysisOptions& options,
                           Report* report) {
  Report local;
  Report& r = report != nullptr ? *report : local;
  check_labeling_parameters(options.labeling);  // before the expensive steps
  PoleAnalysis analysis;
  const std::vector<Point3> box = bounding_box_sites(samples, options.box_scale);
  analysis.bbox_diagonal = checked_bounding_box(samples).diagonal();
  // The samples and the box corners, in an array of their size (appending the corners to
  // a copy of the samples would double its capacity: 24 MB more for 10^6 samples).
  const auto make_sites = [&](std::vector<Point3>& sites) {
    sites.clear();
    sites.reserve(samples.size() + box.size());
    sites.insert(sites.end(), samples.begin(), samples.end());
    sites.insert(sites.end(), box.begin(), box.end());
  };
  std::vector<Point3> sites;
  make_sites(sites);
  Soup soup;
  {
    Report::Stage stage(r, "delaunay");
    auto dt_options = triangulation::TriangulationOptions::for_surface_points(options.threads);
    dt_options.insert_first = box.size();  // shared by the workers (see insert_first)
    // The sites are given up (a copy would stay in memory beside the cells at their
    // largest) and made again after.
    triangulation::DelaunayCells dt =
        triangulation::RegularTriangulation3::delaunay_cells(std::move(sites), dt_options);
    analysis.duplicate_samples = dt.duplicates.size();
    analysis.delaunay = dt.stats;
    soup = soup_of(dt, samples.size());
    make_sites(sites);
  }
  analysis.tetrahedra = soup.tets.size();
  {
    Report::Stage stage(r, "poles");
    analysis.poles =
        compute_poles({sites, samples.size(), soup.tets.quadruples(), soup.representative},
                      options.threads);
  }
  soup = Soup{};
  if (options.label) {
    // The labelling (sequential) and D̂ are independent: the labels write PoleSet::label,
    // D̂ reads the centres and sample_poles. The labelling runs on one thread beside the
    // D̂ queries, and that thread takes queries too once it is done; one stage, since they
    // overlap.
    Report::Stage stage(r, "labels + pole distance");
    analysis.dhat = pole_distance_beside(samples, analysis.poles, options.threads, [&] {
      analysis.labeling = label_poles(analysis.poles, samples, options.labeling);
    });
    analysis.labelled = true;
  } else {
    Report::Stage stage(r, "pole distance");  // compute_poles left every pole unlabelled
    analysis.dhat = pole_distance(samples, analysis.poles, options.threads);
  }
  if (report != nullptr) record(*report, analysis);
  return analysis;
}

bool label_beside(unsigned threads) { return thread_count(threads, 2) > 1; }

PendingLabels::PendingLabels(PoleAnalysis& analysis, std::span<const Point3> samples,
                             const LabelingParameters& parameters, Report* report)
    : analysis_(&analysis), report_(report) {
  if (analysis.labelled) throw InvalidInput("pending labels: the pole analysis is labelled");
  if (samples.size() != analysis.poles.sample_count) {
    throw InvalidInput("pending labels: " + std::to_string(samples.size()) +
                       " samples given for a pole analysis of " +
                       std::to_string(analysis.poles.sample_count));
  }
  check_labeling_parameters(parameters);
  // The thread touches only analysis.poles (the labelling writes its labels and reads the
  // rest) and this object's labeling_, done_, seconds_ and error_ (and reads stop_);
  // wait() reads those after join().
  //
  // It runs at idle priority (Linux's SCHED_IDLE): it takes a core only when the level's
  // threads leave one idle (the set cover's one-thread phases, the waits for its greedy),
  // instead of slicing time with them. An unprivileged thread cannot come back from that
  // priority, so wait() stops it and finishes the labelling on the caller's thread.
  // 10^6 torus samples (bench_seed --torus 1000000 --levels 0.5:0.03), 3 pairs interleaved:
  // level 1 8.03 / 6.92 / 6.61 -> 7.87 / 6.57 / 6.54 s (covering sets 1.78 / 1.84 / 1.42 ->
  // 1.52 / 1.30 / 1.40 s), the labels done before the level's end in every run; double
  // torus, level 1 with the shared stages 1.73 / 1.68 / 1.84 -> 1.65 / 1.60 / 1.63 s.
  thread_ = std::thread([this, samples, parameters] {
#if defined(__linux__)
    sched_param idle{};
    idle.sched_priority = 0;
    (void)pthread_setschedparam(pthread_self(), SCHED_IDLE, &idle);  // a hint: may fail
#endif
    try {
      const Stopwatch clock;
      labeling_ = std::make_unique<detail::ResumableLabeling>(analysis_->poles, samples, parameters);
      done_ = labeling_->run(stop_);
      seconds_ = clock.seconds();
    } catch (...) {
      error_ = std::current_exception();
    }
  });
}

PendingLabels::~PendingLabels() {
  stop_.store(true, std::memory_order_relaxed);  // nobody will read the labels
  if (thread_.joinable()) thread_.join();
}

const LabelingStats& PendingLabels::wait() {
  if (thread_.joinable()) {
    stop_.store(true, std::memory_order_relaxed);
    thread_.join();
    if (error_) std::rethrow_exception(error_);
    if (!done_) {
      const Stopwatch clock;
      const std::atomic<bool> never{false};
      labeling_->run(never);
      seconds_ += clock.seconds();
    }
    stats_ = labeling_->finish();
    labeling_.reset();
    analysis_->labeling = stats_;
    analysis_->labelled = true;
    if (report_ != nullptr) {
      record_labels(*report_, stats_);
      report_->data()["poles"]["labelled"] = true;
      report_->data()["poles"]["labels_seconds"] = seconds_;
    }
  } else if (error_) {
    std::rethrow_exception(error_);
  }
  return stats_;
}

}  // namespace rstruct::poles
