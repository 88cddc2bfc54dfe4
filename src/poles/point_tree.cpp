#include "point_tree.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <limits>
#include <numeric>
#include <thread>

#include "rstruct/core/error.hpp"
#include "rstruct/core/parallel.hpp"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define RSTRUCT_POINT_TREE_AVX2 1
#endif

// Splits: at the middle of the node's region along its widest side (among the sides
// within 10^-5 of the widest, the one where the points spread most), moved to the points'
// range, as nanoflann's middle split. Such cells stay fat where the points are spread
// thinly. Splitting at the median of the points instead made the cells of the poles long
// and thin: on the 10^6-sample torus a query scanned 47,000 points instead of 2,200; so
// did falling back to the median wherever a middle split left less than 1/64 of the
// points on one side (queries 1.8x slower than nanoflann). Only below depth
// kMaxMiddleDepth do the splits become median splits, to bound the recursion.
//
// Measured, one thread, queries in Morton order from the nearer own pole as pole_distance
// runs them, against nanoflann with leaves of 24 (what pole_distance used before):
// - bench_seed's 10^6-sample torus (1.7·10^6 poles), 200,000 queries: build 0.46-0.60 ->
//   0.21-0.28 s, queries 0.82-0.84 -> 0.48 s; with the portable scan 0.92 s.
// - 10^6 samples uniform on a torus R/a = 3 (1.69·10^6 poles), 200,000 queries, on a slow
//   phase of the machine: queries 1.51-1.54 -> 0.78-0.84 s (portable scan 1.61-1.67 s);
//   the build takes as long as nanoflann's. 85,000 such samples, all queries: 0.245 ->
//   0.146-0.152 s.
// - Leaf sizes (first version of this tree, uniform torus): 16/32/64/128 points 0.84-0.87 /
//   0.68-0.72 / 0.58-0.60 / 0.56 s; scanning 8 points at a time with AVX-512, leaves of 64:
//   0.55-0.58 s, not worth a third path. With leaves of 64 a query visits about 250 nodes
//   and scans about 3,300 points.
// - Two threads (the subtrees below the first split built side by side, the leaves' arrays
//   filled by both): the 1.7·10^6 poles of bench_seed's 10^6-sample torus, build 0.22-0.28
//   -> 0.12-0.18 s (3 pairs).

namespace rstruct::poles::detail {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr std::uint32_t kNoIndex = 0xffffffffu;
/// Below this depth the splits are middle splits; from it on, median splits, which bound
/// the depth (and the recursion) by about kMaxMiddleDepth + log2(n).
constexpr unsigned kMaxMiddleDepth = 96;
/// Subtrees of at least this many points are built on two threads where there are two.
constexpr std::size_t kParallelPoints = std::size_t{1} << 16;

/// Whether a subtree whose points have squared distances of at least `bound` (computed as
/// (c₀ + c₁) + c₂ from squared coordinate gaps, each rounded) can be skipped while the
/// best squared distance found is `best`. The true bound B and the computed one differ
/// by a factor within (1 ± u)⁵ plus a few subnormal units, and so do a point's true and
/// computed squared distances D ≥ B; a computed bound above best·(1 + 2⁻⁴⁰) + 2⁻¹⁰⁰⁰
/// therefore puts every point's computed distance strictly above best: none of them
/// could win or tie. (u = 2⁻⁵³; (1 + u)¹⁰ − 1 < 2⁻⁴⁹.)
bool skippable(double bound, double best) { return bound > best * (1 + 0x1p-40) + 0x1p-1000; }

/// The squared distance from q to a box, computed as a point's squared distance is: for a
/// point in the box, |fl(p − q)| ≥ fl(gap) on each axis (rounding is monotonic), and so,
/// squared and summed in the same order, the bound is at most the point's computed
/// squared distance.
template <class Box>
double box_bound(const Box& box, const double* q) {
  double gap[3];
  for (std::size_t d = 0; d < 3; ++d) {
    gap[d] = q[d] < box.lo[d] ? box.lo[d] - q[d] : q[d] > box.hi[d] ? q[d] - box.hi[d] : 0.0;
  }
  return (gap[0] * gap[0] + gap[1] * gap[1]) + gap[2] * gap[2];
}

/// Coordinates up to this magnitude (and queries') keep a capsule's squares and products
/// far from overflow; a leaf with larger ones gets no capsule bound.
constexpr double kCapsuleRange = 0x1p400;

/// Subtrees of at most this many slots get a capsule (larger ones span curved stretches of
/// an axis, where a capsule bounds little).
constexpr std::uint32_t kCapsulePoints = 4096;

/// The capsule of the points in slots [first, last) (padding skipped; see
/// PointTree::Capsule): the segment through their centroid c along the direction between
/// their extreme points on `axis` (the widest side of their box), from the least to the
/// largest of their parameters t = fl((p − c)·u), and r the largest computed distance from
/// a point p to c + t·u. Floating point; capsule_bound() allows for the rounding of all of
/// it. (Two passes over the points. The direction between the farthest point from c and
/// the farthest from that one takes two passes more: when every subtree's capsule was
/// computed from its points, that made the pole tree's build of a 10^6-sample torus 0.08 s
/// slower for no faster queries. Inner nodes now merge their children's: merged_capsule.)
template <class Capsule>
Capsule capsule_of(const double* x, const double* y, const double* z, const std::uint32_t* index,
                   std::uint32_t first, std::uint32_t last, std::size_t axis) {
  Capsule k;
  const double* along = axis == 0 ? x : axis == 1 ? y : z;
  double sum[3] = {0, 0, 0};
  double n = 0;
  std::uint32_t low = first, high = first;
  for (std::uint32_t s = first; s < last; ++s) {
    if (index[s] == kNoIndex) continue;
    const double p[3] = {x[s], y[s], z[s]};
    for (std::size_t d = 0; d < 3; ++d) {
      if (!(std::fabs(p[d]) <= kCapsuleRange)) {
        k.r = HUGE_VAL;
        return k;
      }
      sum[d] += p[d];
    }
    if (n == 0 || along[s] < along[low]) low = s;
    if (n == 0 || along[s] > along[high]) high = s;
    n += 1;
  }
  if (n == 0) {
    k.r = HUGE_VAL;
    return k;
  }
  for (std::size_t d = 0; d < 3; ++d) k.c[d] = sum[d] / n;
  const double w[3] = {x[high] - x[low], y[high] - y[low], z[high] - z[low]};
  const double length = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
  if (length > 0 && std::isfinite(length)) {
    for (std::size_t d = 0; d < 3; ++d) k.u[d] = w[d] / length;
  }
  k.t0 = HUGE_VAL;
  k.t1 = -HUGE_VAL;
  double r2 = 0;
  for (std::uint32_t s = first; s < last; ++s) {
    if (index[s] == kNoIndex) continue;
    const double v[3] = {x[s] - k.c[0], y[s] - k.c[1], z[s] - k.c[2]};
    const double t = v[0] * k.u[0] + v[1] * k.u[1] + v[2] * k.u[2];
    k.t0 = std::min(k.t0, t);
    k.t1 = std::max(k.t1, t);
    const double e[3] = {v[0] - t * k.u[0], v[1] - t * k.u[1], v[2] - t * k.u[2]};
    r2 = std::max(r2, e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
  }
  k.r = std::sqrt(r2);
  k.scale = std::max(std::fabs(k.t0), std::fabs(k.t1)) + k.r;
  if (!std::isfinite(k.scale)) k.r = HUGE_VAL;
  return k;
}

/// A capsule holding capsules a and b (an inner node's, from its children's). The new axis
/// runs through the two farthest apart of the four ends, and the new segment spans their
/// projections: so it holds the projection of every point s of a's segment, whose distance
/// to the new line is at most that of one of a's ends (distances to a line are convex
/// along a segment). A point within a.r of such an s is therefore within (distance of that
/// end) + a.r of the new segment: the new r is the largest of these over the four ends.
/// Floating point, every difference taken between nearby values (the ends relative to the
/// new centre, the midpoint of the old ones), so that the rounding follows the capsules'
/// sizes, not their coordinates; with at most log2(kCapsulePoints) merges above a leaf the
/// errors stay within capsule_bound()'s margin.
template <class Capsule>
Capsule merged_capsule(const Capsule& a, const Capsule& b) {
  Capsule k;
  if (a.r == HUGE_VAL || b.r == HUGE_VAL) {
    k.r = HUGE_VAL;
    return k;
  }
  for (std::size_t d = 0; d < 3; ++d) k.c[d] = 0.5 * (a.c[d] + b.c[d]);
  double end[4][3];
  double radius[4];
  const Capsule* child[2] = {&a, &b};
  for (std::size_t i = 0; i < 4; ++i) {
    const Capsule& x = *child[i / 2];
    const double t = i % 2 == 0 ? x.t0 : x.t1;
    for (std::size_t d = 0; d < 3; ++d) end[i][d] = (x.c[d] - k.c[d]) + t * x.u[d];
    radius[i] = x.r;
  }
  double widest = -1;
  std::size_t from = 0, to = 1;
  for (std::size_t i = 0; i < 4; ++i) {
    for (std::size_t j = i + 1; j < 4; ++j) {
      const double w[3] = {end[j][0] - end[i][0], end[j][1] - end[i][1], end[j][2] - end[i][2]};
      const double w2 = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
      if (w2 > widest) {
        widest = w2;
        from = i;
        to = j;
      }
    }
  }
  const double w[3] = {end[to][0] - end[from][0], end[to][1] - end[from][1],
                       end[to][2] - end[from][2]};
  const double length = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
  if (length > 0 && std::isfinite(length)) {
    for (std::size_t d = 0; d < 3; ++d) k.u[d] = w[d] / length;
  }
  k.t0 = HUGE_VAL;
  k.t1 = -HUGE_VAL;
  k.r = 0;
  for (std::size_t i = 0; i < 4; ++i) {
    const double* e = end[i];
    const double t = e[0] * k.u[0] + e[1] * k.u[1] + e[2] * k.u[2];
    k.t0 = std::min(k.t0, t);
    k.t1 = std::max(k.t1, t);
    const double f[3] = {e[0] - t * k.u[0], e[1] - t * k.u[1], e[2] - t * k.u[2]};
    k.r = std::max(k.r, std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]) + radius[i]);
  }
  k.scale = std::max(std::fabs(k.t0), std::fabs(k.t1)) + k.r;
  if (!std::isfinite(k.scale)) k.r = HUGE_VAL;
  return k;
}

/// A lower bound on the squared distances, as scans compute them, from q to the points of
/// a node with capsule k, or 0. Every point p of the node lies within r of the segment, up
/// to rounding (a leaf: c + t_p·u, with t_p as capsule_of computed it, lies on the segment
/// and within r of p; an inner node: see merged_capsule), so |q − p| ≥ dist(q, segment) − r
/// by the triangle inequality. The distance computed here, from q to
/// c + clamp(fl((q − c)·u))·u, exceeds dist(q, segment) by second-order terms only. Every
/// rounded operation (differences from c, products with u, sums of squares, square roots)
/// errs by at most 2⁻⁵³ of its result, so the errors of r and of that distance stay within
/// a few hundred units of 2⁻⁵³ of |q − c| + max(|t0|, |t1|) + r (the magnitudes of every
/// intermediate), and below 2⁻⁵⁰⁰ where squares underflow: the margin of 2⁻⁴⁰ of that sum
/// plus 2⁻⁵⁰⁰ covers them. (Coordinates up to kCapsuleRange: nothing overflows.) The bound,
/// squared, then stands against the points' computed squared distances as the box bound
/// does (skippable() allows a relative 2⁻⁴⁰ for the rounding of both).
/// \pre q's coordinates are at most kCapsuleRange in magnitude (nearest_from checks once
/// per query).
template <class Capsule>
double capsule_bound(const Capsule& k, const double* q) {
  if (k.r == HUGE_VAL) return 0.0;
  const double v[3] = {q[0] - k.c[0], q[1] - k.c[1], q[2] - k.c[2]};
  const double t = std::clamp(v[0] * k.u[0] + v[1] * k.u[1] + v[2] * k.u[2], k.t0, k.t1);
  const double e[3] = {v[0] - t * k.u[0], v[1] - t * k.u[1], v[2] - t * k.u[2]};
  const double distance = std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
  const double magnitude = std::fabs(v[0]) + std::fabs(v[1]) + std::fabs(v[2]) + k.scale;
  const double bound = distance - k.r - (0x1p-40 * magnitude + 0x1p-500);
  return bound > 0 ? bound * bound : 0.0;
}

Box3 box_of(const std::uint32_t* first, const std::uint32_t* last, std::span<const Point3> points) {
  Box3 box;
  for (const std::uint32_t* it = first; it != last; ++it) box.add(points[*it]);
  return box;
}

bool avx2_available() {
#if defined(RSTRUCT_POINT_TREE_AVX2)
  static const bool available = __builtin_cpu_supports("avx2") != 0;
  return available;
#else
  return false;
#endif
}

}  // namespace

PointTree::PointTree(std::span<const Point3> points, std::uint32_t leaf_size, Scan scan,
                     unsigned threads, Bounds bounds)
    : size_(points.size()),
      leaf_size_(std::max<std::uint32_t>(1, leaf_size)),
      vectorized_(scan == Scan::best && avx2_available()) {
  if (points.size() >= kNoIndex) {
    throw InvalidInput("point tree: " + std::to_string(points.size()) +
                       " points exceed the supported maximum");
  }
  if (points.empty()) return;
  const unsigned workers = thread_count(threads, points.size(), kParallelPoints);
  std::vector<std::uint32_t> ids(points.size());
  std::iota(ids.begin(), ids.end(), 0u);
  ids_base_ = ids.data();
  const Box3 root_box = box_of(ids.data(), ids.data() + ids.size(), points);
  nodes_.reserve(4 * (points.size() / leaf_size_) + 1);
  build(nodes_, ids.data(), ids.data() + ids.size(), root_box, root_box, points, 0, workers);
  ids_base_ = nullptr;
  // The leaves' points, leaf after leaf, by coordinate, each leaf from a multiple of 4.
  std::vector<std::uint32_t> leaves;
  std::vector<std::uint32_t> slot;
  std::size_t slots = 0;
  for (std::uint32_t k = 0; k < nodes_.size(); ++k) {
    if (!nodes_[k].leaf) continue;
    leaves.push_back(k);
    slot.push_back(static_cast<std::uint32_t>(slots));
    slots += (nodes_[k].last - nodes_[k].first + 3) / 4 * 4;
  }
  if (slots >= kNoIndex) {
    throw InvalidInput("point tree: " + std::to_string(points.size()) +
                       " points exceed the supported maximum");
  }
  x_.reset(new double[slots]);
  y_.reset(new double[slots]);
  z_.reset(new double[slots]);
  index_.reset(new std::uint32_t[slots]);
  parallel_chunks(leaves.size(), workers, 256, [&](std::size_t begin, std::size_t end, unsigned) {
    for (std::size_t l = begin; l < end; ++l) {
      Node& node = nodes_[leaves[l]];
      std::uint32_t at = slot[l];
      for (std::uint32_t k = node.first; k < node.last; ++k, ++at) {
        const Point3& p = points[ids[k]];
        x_[at] = p.x;
        y_[at] = p.y;
        z_[at] = p.z;
        index_[at] = ids[k];
      }
      for (; at % 4 != 0; ++at) {
        x_[at] = kNaN;
        y_[at] = kNaN;
        z_[at] = kNaN;
        index_[at] = kNoIndex;
      }
      node.first = slot[l];
      node.last = at;
    }
  });
  if (bounds == Bounds::boxes) return;
  // Each node's slots: a subtree's nodes, and so its leaves' slots, are contiguous (the
  // build appends a node's lower subtree, then its upper one), and children follow their
  // parent.
  std::vector<std::array<std::uint32_t, 2>> span(nodes_.size());
  for (std::size_t k = nodes_.size(); k-- > 0;) {
    const Node& node = nodes_[k];
    span[k] = node.leaf ? std::array<std::uint32_t, 2>{node.first, node.last}
                        : std::array<std::uint32_t, 2>{span[node.first][0], span[node.last][1]};
  }
  capsules_.resize(nodes_.size());
  parallel_chunks(leaves.size(), workers, 256, [&](std::size_t begin, std::size_t end, unsigned) {
    for (std::size_t l = begin; l < end; ++l) {
      const Node& node = nodes_[leaves[l]];
      std::size_t axis = 0;
      for (std::size_t d = 1; d < 3; ++d) {
        if (node.hi[d] - node.lo[d] > node.hi[axis] - node.lo[axis]) axis = d;
      }
      capsules_[leaves[l]] = capsule_of<Capsule>(x_.get(), y_.get(), z_.get(), index_.get(),
                                                 node.first, node.last, axis);
    }
  });
  for (std::size_t k = nodes_.size(); k-- > 0;) {
    const Node& node = nodes_[k];
    if (node.leaf) continue;
    if (span[k][1] - span[k][0] > kCapsulePoints) {
      capsules_[k].r = HUGE_VAL;
    } else {
      capsules_[k] = merged_capsule(capsules_[node.first], capsules_[node.last]);
    }
  }
}

/// Builds the subtree of the ids [first, last), whose points lie in `region` (the cell the
/// splits above cut out) and span `tight`; returns its node.
std::uint32_t PointTree::build(std::vector<Node>& nodes, std::uint32_t* first,
                               std::uint32_t* last, const Box3& region, const Box3& tight,
                               std::span<const Point3> points, unsigned depth,
                               unsigned threads) const {
  const auto id = static_cast<std::uint32_t>(nodes.size());
  nodes.emplace_back();
  for (std::size_t d = 0; d < 3; ++d) {
    nodes[id].lo[d] = tight.lo[d];
    nodes[id].hi[d] = tight.hi[d];
  }
  const auto n = static_cast<std::size_t>(last - first);
  if (n <= leaf_size_) {
    Node& leaf = nodes[id];
    leaf.leaf = true;
    leaf.first = static_cast<std::uint32_t>(first - ids_base_);
    leaf.last = static_cast<std::uint32_t>(last - ids_base_);
    return id;
  }
  const double widest = region.max_extent();
  std::size_t axis = 0;
  double spread = -1;
  for (std::size_t d = 0; d < 3; ++d) {
    if (region.hi[d] - region.lo[d] >= (1 - 1e-5) * widest && tight.hi[d] - tight.lo[d] > spread) {
      spread = tight.hi[d] - tight.lo[d];
      axis = d;
    }
  }
  const auto coordinate = [&](std::uint32_t i) { return points[i][axis]; };
  const double split =
      std::clamp(0.5 * (region.lo[axis] + region.hi[axis]), tight.lo[axis], tight.hi[axis]);
  std::uint32_t* below =
      std::partition(first, last, [&](std::uint32_t i) { return coordinate(i) < split; });
  std::uint32_t* mid = below;
  if (static_cast<std::size_t>(below - first) <= n / 2) {
    std::uint32_t* at_most =
        std::partition(below, last, [&](std::uint32_t i) { return coordinate(i) <= split; });
    mid = static_cast<std::size_t>(at_most - first) < n / 2 ? at_most : first + n / 2;
  }
  double cut = split;
  if (depth >= kMaxMiddleDepth || mid == first || mid == last) {
    mid = first + n / 2;
    std::nth_element(first, mid, last, [&](std::uint32_t a, std::uint32_t b) {
      return coordinate(a) < coordinate(b);
    });
    cut = coordinate(*mid);
  }
  const Box3 lower_tight = box_of(first, mid, points);
  const Box3 upper_tight = box_of(mid, last, points);
  Box3 lower_region = region, upper_region = region;
  lower_region.hi[axis] = cut;
  upper_region.lo[axis] = cut;
  std::uint32_t lower = 0;
  std::uint32_t upper = 0;
  if (threads > 1 && n >= kParallelPoints) {
    // The upper subtree on threads / 2 threads of its own, into nodes of its own, appended
    // after the lower subtree's with its child indices shifted.
    std::vector<Node> upper_nodes;
    upper_nodes.reserve(4 * (static_cast<std::size_t>(last - mid) / leaf_size_) + 1);
    std::exception_ptr error;
    {
      std::jthread side([&] {
        try {
          build(upper_nodes, mid, last, upper_region, upper_tight, points, depth + 1, threads / 2);
        } catch (...) {
          error = std::current_exception();
        }
      });
      lower = build(nodes, first, mid, lower_region, lower_tight, points, depth + 1,
                    threads - threads / 2);
    }
    if (error) std::rethrow_exception(error);
    const auto shift = static_cast<std::uint32_t>(nodes.size());
    for (Node& x : upper_nodes) {
      if (!x.leaf) {
        x.first += shift;
        x.last += shift;
      }
    }
    nodes.insert(nodes.end(), upper_nodes.begin(), upper_nodes.end());
    upper = shift;  // the upper subtree's root came first in upper_nodes
  } else {
    lower = build(nodes, first, mid, lower_region, lower_tight, points, depth + 1, 1);
    upper = build(nodes, mid, last, upper_region, upper_tight, points, depth + 1, 1);
  }
  Node& node = nodes[id];
  node.first = lower;
  node.last = upper;
  return id;
}

std::uint32_t PointTree::nearest(const Point3& q) const {
  return nearest_from(q, kNoIndex, HUGE_VAL);
}

std::uint32_t PointTree::nearest_from(const Point3& q, std::uint32_t index,
                                      double squared_distance) const {
  Best best{squared_distance, index};
  // A query beyond kCapsuleRange tests no capsule (see capsule_bound).
  best.capsules = !capsules_.empty() &&
                  std::max({std::fabs(q.x), std::fabs(q.y), std::fabs(q.z)}) <= kCapsuleRange;
  if (nodes_.empty()) return index;
  const double query[3] = {q.x, q.y, q.z};
  if (!can_skip(0, box_bound(nodes_[0], query), query, best)) search(0, query, best);
  return best.index;
}

/// Visits the child whose box is nearer first, each only if the bound from its box can
/// still beat the best. (The bound from the split planes above a node, which this tree
/// used before, is loose where the points lie along a curve, as the poles near a medial
/// axis: a leaf's own box is thin across the curve. 10^6 torus samples, bench_poles, D̂
/// on two threads: a query scanned about 3,200 slots of 111 leaves, two thirds of which
/// their boxes skip.)
void PointTree::search(std::uint32_t id, const double* q, Best& best) const {
  const Node& node = nodes_[id];
  if (node.leaf) {
    if (vectorized_) {
      scan_leaf_avx2(node, q, best);
    } else {
      scan_leaf(node, q, best);
    }
    return;
  }
  const double b0 = box_bound(nodes_[node.first], q);
  const double b1 = box_bound(nodes_[node.last], q);
  const bool lower_first = b0 <= b1;
  const std::uint32_t near = lower_first ? node.first : node.last;
  const std::uint32_t far = lower_first ? node.last : node.first;
  if (!can_skip(near, lower_first ? b0 : b1, q, best)) search(near, q, best);
  if (!can_skip(far, lower_first ? b1 : b0, q, best)) search(far, q, best);
}

bool PointTree::can_skip(std::uint32_t id, double box, const double* q, const Best& best) const {
  return skippable(box, best.d2) ||
         (best.capsules && skippable(capsule_bound(capsules_[id], q), best.d2));
}

void PointTree::scan_leaf(const Node& node, const double* q, Best& best) const {
  for (std::uint32_t k = node.first; k < node.last; ++k) {
    const double dx = x_[k] - q[0];
    const double dy = y_[k] - q[1];
    const double dz = z_[k] - q[2];
    const double d2 = (dx * dx + dy * dy) + dz * dz;
    if (d2 < best.d2 || (d2 == best.d2 && index_[k] < best.index)) {
      best.d2 = d2;
      best.index = index_[k];
    }
  }
}

#if defined(RSTRUCT_POINT_TREE_AVX2)
namespace {

/// The squared distances of the four points whose coordinates start at x, y, z from q
/// (broadcast in qx, qy, qz), computed as the portable scans compute them:
/// ((dx·dx + dy·dy) + dz·dz), no fused multiply-add (the target enables AVX2 only).
__attribute__((target("avx2"))) inline __m256d squared_distances4(const double* x,
                                                                  const double* y,
                                                                  const double* z, __m256d qx,
                                                                  __m256d qy, __m256d qz) {
  const __m256d dx = _mm256_sub_pd(_mm256_loadu_pd(x), qx);
  const __m256d dy = _mm256_sub_pd(_mm256_loadu_pd(y), qy);
  const __m256d dz = _mm256_sub_pd(_mm256_loadu_pd(z), qz);
  return _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)),
                       _mm256_mul_pd(dz, dz));
}

}  // namespace
#endif

void PointTree::candidates_within(const Point3& q, double r,
                                  std::vector<std::uint32_t>& out) const {
  if (nodes_.empty()) return;
  const double query[3] = {q.x, q.y, q.z};
  // A subtree is skipped when skippable() puts all its points' squared distances above
  // the rounded r·r (the argument of skippable() holds with r·r for the minimum: a
  // relative error of 2⁻⁵³ more); a point is a candidate when its computed squared
  // distance is at most the inflated radius, which no rounding can push a point at
  // distance ≤ r past.
  const double r2 = r * r;
  if (!skippable(box_bound(nodes_[0], query), r2)) {
    collect(0, query, r2, inflated_squared_radius(r), out);
  }
}

/// Both children whose box bound can be within r (as in search()).
void PointTree::collect(std::uint32_t id, const double* q, double r2, double limit,
                        std::vector<std::uint32_t>& out) const {
  const Node& node = nodes_[id];
  if (node.leaf) {
    if (vectorized_) {
      collect_leaf_avx2(node, q, limit, out);
    } else {
      collect_leaf(node, q, limit, out);
    }
    return;
  }
  if (!skippable(box_bound(nodes_[node.first], q), r2)) collect(node.first, q, r2, limit, out);
  if (!skippable(box_bound(nodes_[node.last], q), r2)) collect(node.last, q, r2, limit, out);
}

void PointTree::collect_leaf(const Node& node, const double* q, double limit,
                             std::vector<std::uint32_t>& out) const {
  for (std::uint32_t k = node.first; k < node.last; ++k) {
    const double dx = x_[k] - q[0];
    const double dy = y_[k] - q[1];
    const double dz = z_[k] - q[2];
    if ((dx * dx + dy * dy) + dz * dz <= limit) out.push_back(index_[k]);  // NaN padding: false
  }
}

#if defined(RSTRUCT_POINT_TREE_AVX2)
__attribute__((target("avx2"))) void PointTree::collect_leaf_avx2(
    const Node& node, const double* q, double limit, std::vector<std::uint32_t>& out) const {
  // The same operations as collect_leaf, four points at a time.
  const __m256d qx = _mm256_set1_pd(q[0]);
  const __m256d qy = _mm256_set1_pd(q[1]);
  const __m256d qz = _mm256_set1_pd(q[2]);
  const __m256d bound = _mm256_set1_pd(limit);
  for (std::uint32_t k = node.first; k < node.last; k += 4) {
    const __m256d d2 = squared_distances4(x_.get() + k, y_.get() + k, z_.get() + k, qx, qy, qz);
    auto inside = static_cast<unsigned>(_mm256_movemask_pd(_mm256_cmp_pd(d2, bound, _CMP_LE_OQ)));
    for (; inside != 0; inside &= inside - 1) {
      out.push_back(index_[k + static_cast<std::uint32_t>(__builtin_ctz(inside))]);
    }
  }
}
#else
void PointTree::collect_leaf_avx2(const Node& node, const double* q, double limit,
                                  std::vector<std::uint32_t>& out) const {
  collect_leaf(node, q, limit, out);
}
#endif

#if defined(RSTRUCT_POINT_TREE_AVX2)
__attribute__((target("avx2"))) void PointTree::scan_leaf_avx2(const Node& node,
                                                               const double* q,
                                                               Best& best) const {
  // The same operations as scan_leaf, four points at a time (no fused multiply-add: the
  // target enables AVX2 only), so the same values.
  const __m256d qx = _mm256_set1_pd(q[0]);
  const __m256d qy = _mm256_set1_pd(q[1]);
  const __m256d qz = _mm256_set1_pd(q[2]);
  for (std::uint32_t k = node.first; k < node.last; k += 4) {
    const __m256d d2 = squared_distances4(x_.get() + k, y_.get() + k, z_.get() + k, qx, qy, qz);
    // Candidates: d2 ≤ best (NaN padding compares false); the rare ones are resolved in
    // order, ties by index.
    if (_mm256_movemask_pd(_mm256_cmp_pd(d2, _mm256_set1_pd(best.d2), _CMP_LE_OQ)) == 0) continue;
    alignas(32) double value[4];
    _mm256_store_pd(value, d2);
    for (std::uint32_t j = 0; j < 4; ++j) {
      const std::uint32_t i = index_[k + j];
      if (value[j] < best.d2 || (value[j] == best.d2 && i < best.index)) {
        best.d2 = value[j];
        best.index = i;
      }
    }
  }
}
#else
void PointTree::scan_leaf_avx2(const Node& node, const double* q, Best& best) const {
  scan_leaf(node, q, best);
}
#endif

}  // namespace rstruct::poles::detail
