#pragma once
/// \file
/// From an r-sample to its poles, their inner/outer labels and the pole distance D̂: the
/// first stage of every pipeline of the paper (§3, Figure 1; DESIGN.md §1).
///
/// 1. Delaunay triangulation of the samples plus the 8 corners of a box centred at the
///    centre (min + max)/2 of the samples' bounding box, half-width `box_scale` times the
///    largest extent, so every sample's Voronoi cell is bounded (inputs far from the origin
///    work because the box follows the data). The box sites get no poles.
/// 2. Poles (pole_set.hpp). Samples merged with an identical sample share its poles.
/// 3. Labels (pole_labeling.hpp). With PoleAnalysisOptions::label false they are left to a
///    PendingLabels, which runs them on a thread of its own beside the caller's next work.
/// 4. D̂(s) for every sample (pole_distance.hpp), over all poles.

#include <atomic>
#include <cstddef>
#include <exception>
#include <memory>
#include <span>
#include <thread>
#include <vector>

#include "rstruct/core/report.hpp"
#include "rstruct/poles/pole_distance.hpp"
#include "rstruct/poles/pole_labeling.hpp"
#include "rstruct/poles/pole_set.hpp"
#include "rstruct/triangulation/regular_triangulation_3.hpp"

namespace rstruct::poles {

namespace detail {
class ResumableLabeling;
}

struct PoleAnalysisOptions {
  /// Half-width of the bounding-box sites' box, in units of the samples' largest extent.
  /// Must be ≥ 2: then a circumball through a box site and empty of samples has its centre
  /// outside the samples' bounding box (so box poles are outer).
  double box_scale = 3.0;
  LabelingParameters labeling;
  /// Threads for circumspheres and D̂ (0: hardware concurrency).
  unsigned threads = 0;
  /// Step 3. False: the poles are left unlabelled (PoleAnalysis::labelled false) for a
  /// PendingLabels to label beside other work. The seed pipeline reads only D̂ until its
  /// last step, so its first level can run while the (sequential) labelling does (double
  /// torus, medians of 7 interleaved runs: shared stage 0.72 -> 0.61 s, level 1 1.24 ->
  /// 1.28 s, the two together 1.97 -> 1.89 s).
  bool label = true;
};

struct PoleAnalysis {
  PoleSet poles;
  bool labelled = false;           ///< step 3 done: poles.label and `labeling` are set
  LabelingStats labeling;
  PoleDistance dhat;               ///< per sample
  std::size_t duplicate_samples = 0; ///< samples merged into an identical one
  std::size_t tetrahedra = 0;      ///< finite Delaunay tetrahedra (with box sites)
  double bbox_diagonal = 0;        ///< of the samples
  triangulation::TriangulationStats delaunay;  ///< the Delaunay triangulation's counts
};

/// Runs steps 1–4 (without 3 when options.label is false). Stage seconds go to `report`
/// ("delaunay", "poles", then "labels + pole distance", or "pole distance" without
/// labels) and counts to report->data()["poles"] when `report` is given.
/// \throws InvalidInput if there are fewer than 4 samples, a coordinate is not finite, all
/// samples coincide, box_scale < 2 or is not finite, or a labelling threshold is invalid
/// (checked even when the labels are left for later).
PoleAnalysis analyse_poles(std::span<const Point3> samples,
                           const PoleAnalysisOptions& options = {}, Report* report = nullptr);

/// Step 3 of an analysis made with PoleAnalysisOptions::label false, on a thread of its own,
/// started by the constructor. Until wait() returns, the analysis's labels (poles.label,
/// labeling, labelled) belong to that thread: the caller may read and write everything else
/// (D̂, the centres, the samples) but not them. wait() joins the thread, sets
/// analysis.labeling and labelled, adds the counts to report->data()["poles"] as
/// analyse_poles would have and "labels_seconds" (the labelling's own wall time), and
/// rethrows what the labelling threw; later calls return the same counts at once. The
/// destructor joins without throwing; without a wait() the analysis stays unlabelled
/// (labelled false). `samples`, `analysis` and `report` must outlive it.
///
/// The thread runs at idle priority (Linux): it takes a core when the caller's threads leave
/// one idle. wait() stops it between two poles, if it is not done, and finishes the
/// labelling itself, at the caller's priority: the same labels, never starved by other
/// programs' threads.
class PendingLabels {
 public:
  /// \throws InvalidInput if the analysis is already labelled.
  PendingLabels(PoleAnalysis& analysis, std::span<const Point3> samples,
                const LabelingParameters& parameters = {}, Report* report = nullptr);
  PendingLabels(const PendingLabels&) = delete;
  PendingLabels& operator=(const PendingLabels&) = delete;
  ~PendingLabels();

  const LabelingStats& wait();

  /// The analysis being labelled.
  const PoleAnalysis& analysis() const { return *analysis_; }

 private:
  PoleAnalysis* analysis_;
  Report* report_;
  LabelingStats stats_;
  double seconds_ = 0;
  std::exception_ptr error_;
  std::unique_ptr<detail::ResumableLabeling> labeling_;  // made by the thread
  std::atomic<bool> stop_{false};
  bool done_ = false;  // the thread finished the labelling
  std::thread thread_;
};

/// Whether a pipeline on `threads` threads (0: hardware concurrency) should leave the labels
/// to a PendingLabels beside its next work: only when a second thread can take them (one
/// thread labels first, inside analyse_poles).
bool label_beside(unsigned threads);

/// The 8 box sites used by analyse_poles (exposed for tests).
std::vector<Point3> bounding_box_sites(std::span<const Point3> samples, double box_scale);

}  // namespace rstruct::poles
