#include "rstruct/poles/pole_labeling.hpp"

#include <cmath>
#include <queue>
#include <sstream>
#include <utility>
#include <vector>

#include "rstruct/core/error.hpp"

namespace rstruct::poles {
namespace {

constexpr double kNone = -HUGE_VAL;
constexpr double kSeedWeight = 2.0;  // above any cosine

void check_threshold(double value, const char* name) {
  if (!(value >= -1.0 && value <= 1.0)) {
    std::ostringstream message;
    message << "pole labeling: " << name << " = " << value << " must lie in [-1, 1]";
    throw InvalidInput(message.str());
  }
}

/// Poles incident to each sample (the sample is a vertex of the pole's tetrahedron), CSR.
struct Incidence {
  std::vector<std::uint32_t> start, poles;
  std::span<const std::uint32_t> of(std::uint32_t s) const {
    return {poles.data() + start[s], poles.data() + start[s + 1]};
  }
};

Incidence build_incidence(const PoleSet& poles) {
  const std::size_t n = poles.sample_count;
  Incidence inc;
  inc.start.assign(n + 1, 0);
  for (const auto& q : poles.sites) {
    for (const std::uint32_t v : q) {
      if (v < n) ++inc.start[v + 1];
    }
  }
  for (std::size_t s = 0; s < n; ++s) inc.start[s + 1] += inc.start[s];
  inc.poles.resize(inc.start[n]);
  std::vector<std::uint32_t> fill(inc.start.begin(), inc.start.end() - 1);
  for (std::uint32_t p = 0; p < poles.size(); ++p) {
    for (const std::uint32_t v : poles.sites[p]) {
      if (v < n) inc.poles[fill[v]++] = p;
    }
  }
  return inc;
}

class Labeler {
 public:
  Labeler(PoleSet& poles, std::span<const Point3> samples, const LabelingParameters& parameters)
      : poles_(poles),
        samples_(samples),
        parameters_(parameters),
        incidence_(build_incidence(poles)),
        inner_(poles.size(), kNone),
        outer_(poles.size(), kNone),
        done_(poles.size(), 0) {}

  void run(LabelingStats& stats) {
    for (std::uint32_t p = 0; p < poles_.size(); ++p) {
      if (poles_.is_box_pole(p)) {
        outer_[p] = kSeedWeight;
        heap_.emplace(kSeedWeight, p);
      }
    }
    while (!heap_.empty()) {
      const auto [weight, p] = heap_.top();
      heap_.pop();
      if (done_[p] != 0 || weight != std::fmax(inner_[p], outer_[p])) continue;  // stale
      done_[p] = 1;
      if (inner_[p] == outer_[p]) {
        ++stats.ties;
        continue;
      }
      poles_.label[p] = inner_[p] > outer_[p] ? PoleLabel::inner : PoleLabel::outer;
      propagate(p, stats);
    }
  }

  /// Evidence for the side other than the pole's label.
  bool has_contrary_evidence(std::uint32_t p) const {
    if (poles_.label[p] == PoleLabel::inner) return outer_[p] != kNone;
    if (poles_.label[p] == PoleLabel::outer) return inner_[p] != kNone;
    return false;
  }

 private:
  void give(std::uint32_t q, PoleLabel side, double weight) {
    double& evidence = side == PoleLabel::inner ? inner_[q] : outer_[q];
    if (weight <= evidence) return;
    evidence = weight;
    if (done_[q] == 0) heap_.emplace(std::fmax(inner_[q], outer_[q]), q);
  }

  void propagate(std::uint32_t p, LabelingStats& stats) {
    const PoleLabel same = poles_.label[p];
    const PoleLabel other = same == PoleLabel::inner ? PoleLabel::outer : PoleLabel::inner;
    for (const std::uint32_t s : poles_.sites[p]) {
      if (s >= poles_.sample_count) continue;
      const Vec3 dp = poles_.centre[p] - samples_[s];
      const double np = norm(dp);
      for (const std::uint32_t q : incidence_.of(s)) {
        if (q == p) continue;
        const Vec3 dq = poles_.centre[q] - samples_[s];
        const double denominator = np * norm(dq);
        if (!(denominator > 0)) continue;
        ++stats.pairs_examined;
        const double c = dot(dp, dq) / denominator;
        if (c >= parameters_.same_min_cos) {
          give(q, same, c);
        } else if (-c >= parameters_.opposite_min_cos) {
          give(q, other, -c);
        }
      }
    }
  }

  PoleSet& poles_;
  std::span<const Point3> samples_;
  LabelingParameters parameters_;
  Incidence incidence_;
  std::vector<double> inner_, outer_;
  std::vector<char> done_;
  std::priority_queue<std::pair<double, std::uint32_t>> heap_;
};

void count(const PoleSet& poles, const Labeler& labeler, LabelingStats& stats) {
  for (std::uint32_t p = 0; p < poles.size(); ++p) {
    switch (poles.label[p]) {
      case PoleLabel::inner: ++stats.inner; break;
      case PoleLabel::outer: ++stats.outer; break;
      case PoleLabel::unlabelled: ++stats.unlabelled; break;
    }
    if (labeler.has_contrary_evidence(p)) ++stats.contradictory;
  }
  for (std::uint32_t s = 0; s < poles.sample_count; ++s) {
    const auto [a, b] = poles.sample_poles[s];
    if (a != kNoPole && b != kNoPole && poles.label[a] != PoleLabel::unlabelled &&
        poles.label[a] == poles.label[b]) {
      ++stats.inconsistent_samples;
    }
    if (poles.pole_of(s, PoleLabel::inner) == kNoPole) ++stats.samples_without_inner;
  }
}

}  // namespace

LabelingStats label_poles(PoleSet& poles, std::span<const Point3> samples,
                          const LabelingParameters& parameters) {
  check_threshold(parameters.same_min_cos, "same_min_cos");
  check_threshold(parameters.opposite_min_cos, "opposite_min_cos");
  if (samples.size() != poles.sample_count) {
    throw InvalidInput("pole labeling: " + std::to_string(samples.size()) +
                       " samples given for a pole set of " +
                       std::to_string(poles.sample_count));
  }
  poles.label.assign(poles.size(), PoleLabel::unlabelled);
  LabelingStats stats;
  Labeler labeler(poles, samples, parameters);
  labeler.run(stats);
  count(poles, labeler, stats);
  return stats;
}

}  // namespace rstruct::poles
