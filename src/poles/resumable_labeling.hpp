#pragma once
// A pole labelling (label_poles) that can stop between two poles and go on later, possibly
// on another thread: PendingLabels runs it at idle priority and, if the level is done
// first, finishes it on the waiting thread. Private to src/poles.

#include <atomic>
#include <memory>
#include <span>

#include "rstruct/poles/pole_labeling.hpp"

namespace rstruct::poles::detail {

class Labeler;

/// automatic: a breadth-first two-colouring, which gives the greedy's labels and counts
/// when no evidence contradicts it, and otherwise the greedy from scratch (see Labeler in
/// pole_labeling.cpp); greedy: the greedy only (for tests and comparisons).
enum class LabelingMethod { automatic, greedy };

class ResumableLabeling {
 public:
  /// Checks the inputs (as label_poles), clears the labels, seeds the queue.
  ResumableLabeling(PoleSet& poles, std::span<const Point3> samples,
                    const LabelingParameters& parameters,
                    LabelingMethod method = LabelingMethod::automatic);
  ResumableLabeling(const ResumableLabeling&) = delete;
  ResumableLabeling& operator=(const ResumableLabeling&) = delete;
  ~ResumableLabeling();

  /// Labels until done (true) or until `stop` is seen set (false). The poles are labelled
  /// in the same order whatever the stops: the result is label_poles'.
  bool run(const std::atomic<bool>& stop);
  /// The statistics, as label_poles returns them. \pre run() returned true.
  LabelingStats finish();
  /// Whether the automatic method met contradicting evidence and ran the greedy.
  bool fell_back() const;

 private:
  PoleSet& poles_;
  std::unique_ptr<Labeler> labeler_;
  LabelingStats stats_;
  bool done_ = false;
};

}  // namespace rstruct::poles::detail
