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

/// Poles incident to each sample s (s is a vertex of the pole's tetrahedron), CSR, with the
/// unit vector from s towards each such pole: the cosine of the angle at which two polar
/// spheres through s meet is then one dot product.
struct Incidence {
  std::vector<std::uint32_t> start, poles;
  std::vector<Vec3> unit;
};

Incidence build_incidence(const PoleSet& poles, std::span<const Point3> samples) {
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
  inc.unit.resize(inc.start[n]);
  std::vector<std::uint32_t> fill(inc.start.begin(), inc.start.end() - 1);
  for (std::uint32_t p = 0; p < poles.size(); ++p) {
    for (const std::uint32_t v : poles.sites[p]) {
      if (v >= n) continue;
      const Vec3 d = poles.centre[p] - samples[v];
      const double length = norm(d);
      inc.poles[fill[v]] = p;
      // A zero vector (pole on the sample, impossible for radius > 0) gives no evidence.
      inc.unit[fill[v]++] = length > 0 ? d / length : Vec3{};
    }
  }
  return inc;
}

class Labeler {
 public:
  Labeler(PoleSet& poles, std::span<const Point3> samples, const LabelingParameters& parameters)
      : poles_(poles),
        parameters_(parameters),
        incidence_(build_incidence(poles, samples)),
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
    const double before = std::fmax(inner_[q], outer_[q]);
    evidence = weight;
    // Only a larger priority needs a new heap entry; ties and contradictions are judged
    // from inner_/outer_ when the pole is popped, whichever entry pops it.
    if (done_[q] == 0 && weight > before) heap_.emplace(weight, q);
  }

  void propagate(std::uint32_t p, LabelingStats& stats) {
    const PoleLabel same = poles_.label[p];
    const PoleLabel other = same == PoleLabel::inner ? PoleLabel::outer : PoleLabel::inner;
    for (const std::uint32_t s : poles_.sites[p]) {
      if (s >= poles_.sample_count) continue;
      const std::uint32_t begin = incidence_.start[s], end = incidence_.start[s + 1];
      std::uint32_t own = begin;
      while (incidence_.poles[own] != p) ++own;  // p is incident to s by construction
      const Vec3 up = incidence_.unit[own];
      for (std::uint32_t k = begin; k < end; ++k) {
        if (k == own) continue;
        ++stats.pairs_examined;
        const double c = dot(up, incidence_.unit[k]);
        if (c >= parameters_.same_min_cos) {
          give(incidence_.poles[k], same, c);
        } else if (-c >= parameters_.opposite_min_cos) {
          give(incidence_.poles[k], other, -c);
        }
      }
    }
  }

  PoleSet& poles_;
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
