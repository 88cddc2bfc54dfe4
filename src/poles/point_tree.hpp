#pragma once
// A kd-tree over points, for two queries:
//  - nearest point (the pole distance D̂): the point that minimises (squared distance,
//    index), the same point as a scan of all points in index order with a strict
//    comparison (pole_distance_brute_force), whatever the tree;
//  - candidates within a radius (the covering sets, the lemma tests): a superset of the
//    points at distance at most r, which the caller decides exactly
//    (predicates::side_of_ball).
//
// The squared distance of a point is computed as rstruct::squared_distance computes it,
// ((dx·dx + dy·dy) + dz·dz) with the differences rounded once (the project compiles with
// -ffp-contract=off; the vector path below uses no fused multiply-add), so the minimum is
// that of the values a scan computes, bit for bit. A subtree is skipped only when the lower
// bound on its points' squared distances exceeds the current minimum (or r²) by more than
// the rounding of either side could explain (see skippable()), so no point that could win,
// or tie and win on index, or lie within r, is ever skipped.
//
// Why not nanoflann (which the sampling's point index uses): the inner poles of a
// surface crowd its medial axis, and on a 10^6-sample torus about 3,000 poles lie within
// 0.1 % of each sample's nearest one, so a query spends its time scanning leaves. Here the
// leaves are stored as coordinate arrays and scanned four points at a time with AVX2 where
// the processor has it (chosen at run time), in larger leaves (see the .cpp for figures).
// The same layout serves the radius queries (see covering_sets.cpp for figures).
//
// Nearest-point searches also skip a subtree of up to 4,096 points by its capsule (the
// segment its points lie along, and their largest distance from it; see Capsule), where
// its box cannot: a subtree of poles along a piece of medial axis is a thin tube, lying
// diagonally in its box. 10^6-sample torus, D̂ (bench_seed): of the 36 leaves per query that
// the boxes let through, the capsules skip 33, and the stage takes 0.93-0.94 s instead of
// 1.30-1.59 s (3 interleaved pairs, the same output). Where the poles do not crowd that
// much they cost a little: the 85,237-sample double torus's D̂ 0.047-0.057 -> 0.055-0.064 s
// (5 pairs), of which 1 ms is building them.

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "rstruct/geometry/vec3.hpp"

namespace rstruct::poles::detail {

class PointTree {
 public:
  /// The default leaf size, in points (see point_tree.cpp for the measurements).
  static constexpr std::uint32_t kDefaultLeafSize = 64;
  /// How leaves are scanned: the best the processor supports, or plain C++.
  enum class Scan { best, portable };
  /// What nearest() skips subtrees by: their boxes, or their boxes and capsules (built
  /// with the tree: two passes over each leaf's points, then one merge per subtree of up
  /// to 4,096 points). candidates_within() uses the boxes only.
  enum class Bounds { boxes, capsules };

  /// Builds the tree over a copy of `points` (finite coordinates; the caller checks), on
  /// up to `threads` threads (0: hardware concurrency): subtrees below the first splits are
  /// built side by side. The tree does not depend on the thread count.
  /// \pre points.size() < 2^32 − 1.
  explicit PointTree(std::span<const Point3> points,
                            std::uint32_t leaf_size = kDefaultLeafSize, Scan scan = Scan::best,
                            unsigned threads = 1, Bounds bounds = Bounds::capsules);

  std::size_t size() const { return size_; }
  /// Whether queries use the vector (AVX2) scan.
  bool vectorized() const { return vectorized_; }

  /// The index i of the point that minimises (squared_distance(q, p_i), i). \pre size() > 0.
  std::uint32_t nearest(const Point3& q) const;

  /// The same, starting from a known point: `index` with `squared_distance` =
  /// rstruct::squared_distance(q, p_index) (any other value only costs time if it is too
  /// large; it must not be smaller). Subtrees that cannot beat it are not visited.
  std::uint32_t nearest_from(const Point3& q, std::uint32_t index, double squared_distance) const;

  /// Appends to `out`, in no particular order, the index of every point p with |p − q| ≤ r
  /// and possibly of a few more: those whose computed squared distance is at most
  /// inflated_squared_radius(r). The caller decides membership with an exact predicate.
  /// \pre r ≥ 0 and finite, q finite.
  void candidates_within(const Point3& q, double r, std::vector<std::uint32_t>& out) const;

  /// r² enlarged by a relative 2⁻²⁰ plus the smallest normal double: far above the
  /// few-ulp rounding of the computed squared distances (and of r·r), far below any
  /// geometric scale.
  static double inflated_squared_radius(double r) { return r * r * (1.0 + 0x1p-20) + 0x1p-1022; }

 private:
  /// One cache line: the box of the node's points, which bounds its points' distances
  /// (see box_bound() in the .cpp), and the children or the leaf's slots.
  struct alignas(64) Node {
    double lo[3] = {0, 0, 0};
    double hi[3] = {0, 0, 0};
    std::uint32_t first = 0;  // inner: lower child; leaf: first slot in the coordinate arrays
    std::uint32_t last = 0;   // inner: upper child; leaf: one past its last slot
    bool leaf = false;
  };
  /// A node's points lie within distance r of the segment {c + t·u : t0 ≤ t ≤ t1} (u a
  /// unit vector up to rounding), which bounds their distances to a query from below (see
  /// capsule_bound() in the .cpp). Where the poles crowd a medial axis, a small subtree's
  /// points lie along a short piece of it, and the bound is much tighter than its box.
  struct Capsule {
    double c[3] = {0, 0, 0};
    double u[3] = {1, 0, 0};
    double t0 = 0, t1 = 0;
    double r = 0;      // +inf: the capsule bounds nothing (coordinates out of its range)
    double scale = 0;  // max(|t0|, |t1|) + r: with |q − c|, the magnitudes its rounding follows
  };
  struct Best {
    double d2;
    std::uint32_t index;
    bool capsules = false;  // whether this query tests capsules (see nearest_from)
  };

  /// Appends the subtree of the ids [first, last) to `nodes`; returns its root's index.
  /// Up to `threads` threads build its subtrees.
  std::uint32_t build(std::vector<Node>& nodes, std::uint32_t* first, std::uint32_t* last,
                      const Box3& region, const Box3& tight, std::span<const Point3> points,
                      unsigned depth, unsigned threads) const;
  void search(std::uint32_t node, const double* q, Best& best) const;
  void collect(std::uint32_t node, const double* q, double r2, double limit,
               std::vector<std::uint32_t>& out) const;
  void collect_leaf(const Node& node, const double* q, double limit,
                    std::vector<std::uint32_t>& out) const;
  void collect_leaf_avx2(const Node& node, const double* q, double limit,
                         std::vector<std::uint32_t>& out) const;
  void scan_leaf(const Node& node, const double* q, Best& best) const;
  void scan_leaf_avx2(const Node& node, const double* q, Best& best) const;

  std::size_t size_ = 0;
  std::uint32_t leaf_size_;
  bool vectorized_ = false;
  std::uint32_t* ids_base_ = nullptr;  // during construction: the ids being partitioned
  std::vector<Node> nodes_;
  // The points in leaf order, by coordinate, each leaf padded with NaN to a multiple of 4
  // (a NaN distance never compares as small); index_ maps a slot to the point's index.
  // (Arrays without value-initialisation: the threads that fill them touch their pages
  // first, instead of one thread zeroing them all.)
  std::unique_ptr<double[]> x_, y_, z_;
  std::unique_ptr<std::uint32_t[]> index_;
  std::vector<Capsule> capsules_;  // one per node (r = +inf above kCapsulePoints points),
                                   // or none (Bounds::boxes)
  /// Whether the subtree `id` can be skipped: its box or its capsule bound exceeds the best.
  bool can_skip(std::uint32_t id, double box, const double* q, const Best& best) const;
};

}  // namespace rstruct::poles::detail
