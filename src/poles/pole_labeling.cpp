#include "rstruct/poles/pole_labeling.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <memory>
#include <sstream>
#include <utility>
#include <vector>

#include "indexed_max_heap.hpp"
#include "resumable_labeling.hpp"
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
///
/// Popping a pole reads the lists of its four sites. Each pole keeps where it is in them
/// (`own`), and the entries mark the first and last of each list: one random load, then
/// four independent ones, where the pole's sites, the lists' starts and a search for the
/// pole in each list were three dependent loads (10⁶ torus samples: half the labelling's
/// time went to waiting for them).
struct Incidence {
  struct Entry {
    Vec3 unit;
    std::uint32_t tagged_pole;  // the pole, with kFirst / kLast on a list's ends
    std::uint32_t pole() const { return tagged_pole & kPoleMask; }
  };
  static constexpr std::uint32_t kFirst = 1u << 31, kLast = 1u << 30;
  static constexpr std::uint32_t kPoleMask = kLast - 1;
  static constexpr std::uint32_t kNoList = 0xffffffffU;  // a bounding-box site
  std::vector<Entry> entries;  // a sample's poles side by side: one or two cache lines
  std::vector<std::array<std::uint32_t, 4>> own;  // per pole and site: its entry, or kNoList
};

Incidence build_incidence(const PoleSet& poles, std::span<const Point3> samples) {
  const std::size_t n = poles.sample_count;
  if (poles.size() > Incidence::kPoleMask) {
    throw InvalidInput("pole labeling: " + std::to_string(poles.size()) + " poles (at most " +
                       std::to_string(Incidence::kPoleMask) + ")");
  }
  std::vector<std::uint32_t> start(n + 1, 0);
  for (const auto& q : poles.sites) {
    for (const std::uint32_t v : q) {
      if (v < n) ++start[v + 1];
    }
  }
  for (std::size_t s = 0; s < n; ++s) start[s + 1] += start[s];
  Incidence inc;
  inc.entries.resize(start[n]);
  inc.own.resize(poles.size());
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (std::uint32_t p = 0; p < poles.size(); ++p) {
    for (std::size_t t = 0; t < 4; ++t) {
      const std::uint32_t v = poles.sites[p][t];
      inc.own[p][t] = Incidence::kNoList;
      if (v >= n) continue;
      const Vec3 d = poles.centre[p] - samples[v];
      const double length = norm(d);
      const std::uint32_t k = fill[v]++;
      inc.own[p][t] = k;
      // A zero vector (pole on the sample, impossible for radius > 0) gives no evidence.
      inc.entries[k] = {length > 0 ? d / length : Vec3{},
                        p | (k == start[v] ? Incidence::kFirst : 0u) |
                            (k + 1 == start[v + 1] ? Incidence::kLast : 0u)};
    }
  }
  return inc;
}

}  // namespace

namespace detail {

/// Power crust's greedy labelling (see pole_labeling.hpp), with a faster path that gives
/// the same labels and counts whenever the evidence never contradicts itself.
///
/// The evidence is symmetric (the same cosine, by the same dot product, from p to q as from
/// q to p), so it forms a graph whose edges say "same side" or "opposite sides". If some
/// colouring of the poles reached from the bounding-box poles (outer) satisfies every edge
/// between them, it is the only one, and the greedy finds it too: each pole it pops has
/// evidence for its colour only, so no ties and no contradictions, and the poles it labels
/// are those reached. The fast path colours the poles breadth first, checking every edge
/// from both ends, and needs no priority queue (on 10⁶ torus samples the queue's raises
/// and pops were most of the labelling's time); at the first edge its colouring violates,
/// it clears its labels and counts and the greedy starts from scratch. Inputs that are
/// r-samples take the fast path; the others pay for both.
class Labeler {
 public:
  Labeler(PoleSet& poles, std::span<const Point3> samples, const LabelingParameters& parameters,
          LabelingMethod method)
      : poles_(poles), parameters_(parameters), incidence_(build_incidence(poles, samples)) {
    if (method == LabelingMethod::greedy) {
      start_greedy();
    } else {
      start_colouring();
    }
  }

  /// Labels until done (true) or until `stop` is seen set (false; checked every 1024
  /// poles). A later call goes on where this one stopped.
  bool run(LabelingStats& stats, const std::atomic<bool>& stop) {
    if (!greedy_) {
      if (run_colouring(stats, stop)) {
        // Nothing reads the lists any more (a colouring that ended has no contrary
        // evidence to report): their memory goes back while the caller goes on.
        incidence_ = Incidence{};
        queue_ = {};
        return true;
      }
      if (!contradicted_) return false;  // stopped
      std::fill(poles_.label.begin(), poles_.label.end(), PoleLabel::unlabelled);
      stats = LabelingStats{};
      queue_ = {};
      start_greedy();
    }
    return run_greedy(stats, stop);
  }

  /// Whether the fast path's colouring met an edge it violates (the greedy then ran).
  bool fell_back() const { return contradicted_; }

  /// Evidence for the side other than the pole's label.
  bool has_contrary_evidence(std::uint32_t p) const {
    if (!greedy_) return false;  // a colouring that ended satisfies every edge
    if (poles_.label[p] == PoleLabel::inner) return evidence_[p].outer != kNone;
    if (poles_.label[p] == PoleLabel::outer) return evidence_[p].inner != kNone;
    return false;
  }

 private:
  void start_colouring() {
    for (std::uint32_t p = 0; p < poles_.size(); ++p) {
      if (poles_.is_box_pole(p)) {
        poles_.label[p] = PoleLabel::outer;
        queue_.push_back(p);
      }
    }
  }

  /// Breadth first from the box poles; false when stopped or (contradicted_) at the first
  /// violated edge.
  bool run_colouring(LabelingStats& stats, const std::atomic<bool>& stop) {
    for (std::uint32_t taken = 0; head_ < queue_.size(); ++taken) {
      if ((taken & 1023u) == 1023u && stop.load(std::memory_order_relaxed)) return false;
      const std::uint32_t p = queue_[head_++];
      if (head_ < queue_.size()) __builtin_prefetch(&incidence_.own[queue_[head_]]);
      if (!colour_from(p, stats)) {
        contradicted_ = true;
        return false;
      }
    }
    return true;
  }

  /// Gives p's colour, or the other, to every pole the evidence from p reaches (the
  /// greedy's propagate() without the queue); false if one already has the other colour.
  bool colour_from(std::uint32_t p, LabelingStats& stats) {
    return for_each_evidence(p, stats, [&](std::uint32_t q, PoleLabel side, double) {
      PoleLabel& label = poles_.label[q];
      if (label == PoleLabel::unlabelled) {
        label = side;
        queue_.push_back(q);
      }
      return label == side;
    });
  }

  /// Calls give(q, side, weight) for every piece of evidence from labelled pole p (see
  /// pole_labeling.hpp), pole by pole through p's four lists, until it returns false;
  /// false then, true otherwise.
  template <class Give>
  bool for_each_evidence(std::uint32_t p, LabelingStats& stats, Give&& give) {
    const PoleLabel same = poles_.label[p];
    const PoleLabel other = same == PoleLabel::inner ? PoleLabel::outer : PoleLabel::inner;
    const Incidence::Entry* entries = incidence_.entries.data();
    // The four lists are scattered: ask for all of them before working through the first.
    for (const std::uint32_t own : incidence_.own[p]) {
      if (own != Incidence::kNoList) __builtin_prefetch(&entries[own]);
    }
    for (const std::uint32_t own : incidence_.own[p]) {
      if (own == Incidence::kNoList) continue;
      std::uint32_t k = own;
      while ((entries[k].tagged_pole & Incidence::kFirst) == 0) --k;
      const Vec3 up = entries[own].unit;
      for (;; ++k) {
        const Incidence::Entry& e = entries[k];
        if (k != own) {
          ++stats.pairs_examined;
          const double c = dot(up, e.unit);
          if (c >= parameters_.same_min_cos) {
            if (!give(e.pole(), same, c)) return false;
          } else if (-c >= parameters_.opposite_min_cos) {
            if (!give(e.pole(), other, -c)) return false;
          }
        }
        if ((e.tagged_pole & Incidence::kLast) != 0) break;
      }
    }
    return true;
  }

  void start_greedy() {
    greedy_ = true;
    evidence_.assign(poles_.size(), Evidence{});
    done_.assign(poles_.size(), 0);
    heap_ = std::make_unique<detail::IndexedMaxHeap>(poles_.size());
    for (std::uint32_t p = 0; p < poles_.size(); ++p) {
      if (poles_.is_box_pole(p)) {
        evidence_[p].outer = kSeedWeight;
        heap_->raise(p, kSeedWeight);
      }
    }
  }

  /// Pops poles until the queue is empty (true) or `stop` is seen set (false; checked
  /// every 1024 poles).
  bool run_greedy(LabelingStats& stats, const std::atomic<bool>& stop) {
    detail::IndexedMaxHeap& heap = *heap_;
    for (std::uint32_t popped = 0; !heap.empty(); ++popped) {
      if ((popped & 1023u) == 1023u && stop.load(std::memory_order_relaxed)) return false;
      const std::uint32_t p = heap.pop().second;  // its priority: the larger evidence
      // Likely the next pole popped (unless p's neighbours overtake it): its lists' places.
      if (!heap.empty()) __builtin_prefetch(&incidence_.own[heap.top_id()]);
      done_[p] = 1;
      const Evidence& e = evidence_[p];
      if (e.inner == e.outer) {
        ++stats.ties;
        continue;
      }
      poles_.label[p] = e.inner > e.outer ? PoleLabel::inner : PoleLabel::outer;
      propagate(p, stats);
    }
    return true;
  }

  void give(std::uint32_t q, PoleLabel side, double weight) {
    Evidence& e = evidence_[q];
    double& evidence = side == PoleLabel::inner ? e.inner : e.outer;
    if (weight <= evidence) return;
    const double before = std::fmax(e.inner, e.outer);
    evidence = weight;
    // Only a larger priority moves the pole up the queue; ties and contradictions are
    // judged from the evidence when the pole is popped.
    if (weight > before && done_[q] == 0) heap_->raise(q, weight);
  }

  void propagate(std::uint32_t p, LabelingStats& stats) {
    // The evidence first, the (scattered) evidence records it goes to asked for meanwhile;
    // then given in the same order.
    gifts_.clear();
    for_each_evidence(p, stats, [&](std::uint32_t q, PoleLabel side, double weight) {
      __builtin_prefetch(&evidence_[q]);
      gifts_.push_back({q, side, weight});
      return true;
    });
    for (const Gift& g : gifts_) give(g.pole, g.side, g.weight);
  }

  struct Gift {
    std::uint32_t pole;
    PoleLabel side;
    double weight;
  };
  std::vector<Gift> gifts_;  // propagate()'s, reused
  PoleSet& poles_;
  LabelingParameters parameters_;
  Incidence incidence_;
  struct Evidence {
    double inner = kNone;  // the strongest evidence for each side
    double outer = kNone;
  };
  // The fast path's: the poles coloured, in order, and the next to spread its colour.
  std::vector<std::uint32_t> queue_;
  std::size_t head_ = 0;
  bool contradicted_ = false;
  // The greedy's (allocated when it starts).
  bool greedy_ = false;
  std::vector<Evidence> evidence_;
  std::vector<char> done_;
  std::unique_ptr<detail::IndexedMaxHeap> heap_;
};

}  // namespace detail

namespace {

void count(const PoleSet& poles, const detail::Labeler& labeler, LabelingStats& stats) {
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

void check_labeling_parameters(const LabelingParameters& parameters) {
  check_threshold(parameters.same_min_cos, "same_min_cos");
  check_threshold(parameters.opposite_min_cos, "opposite_min_cos");
}

LabelingStats label_poles(PoleSet& poles, std::span<const Point3> samples,
                          const LabelingParameters& parameters) {
  detail::ResumableLabeling labeling(poles, samples, parameters);
  const std::atomic<bool> never{false};
  labeling.run(never);
  return labeling.finish();
}

namespace detail {

ResumableLabeling::ResumableLabeling(PoleSet& poles, std::span<const Point3> samples,
                                     const LabelingParameters& parameters, LabelingMethod method)
    : poles_(poles) {
  check_labeling_parameters(parameters);
  if (samples.size() != poles.sample_count) {
    throw InvalidInput("pole labeling: " + std::to_string(samples.size()) +
                       " samples given for a pole set of " +
                       std::to_string(poles.sample_count));
  }
  poles.label.assign(poles.size(), PoleLabel::unlabelled);
  labeler_ = std::make_unique<Labeler>(poles, samples, parameters, method);
}

bool ResumableLabeling::fell_back() const { return labeler_->fell_back(); }

ResumableLabeling::~ResumableLabeling() = default;

bool ResumableLabeling::run(const std::atomic<bool>& stop) {
  done_ = done_ || labeler_->run(stats_, stop);
  return done_;
}

LabelingStats ResumableLabeling::finish() {
  if (!done_) throw InternalError("pole labeling: finish() before the labelling is done");
  LabelingStats stats = stats_;
  count(poles_, *labeler_, stats);
  return stats;
}

}  // namespace detail

}  // namespace rstruct::poles
