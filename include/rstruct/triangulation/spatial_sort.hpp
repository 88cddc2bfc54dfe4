#pragma once
/// \file
/// Spatial sorting for incremental constructions: BRIO (Amenta, Choi & Rote, "Incremental
/// constructions con BRIO", SoCG 2003) with every round ordered along a 3D Hilbert curve
/// (Hilbert index computed with Skilling's transpose algorithm, "Programming the Hilbert
/// curve", AIP Conf. Proc. 707, 2004). The order only affects speed, never a result, so the
/// quantisation of coordinates to the curve's grid is plain double arithmetic.

#include <cstdint>
#include <span>
#include <vector>

#include "rstruct/geometry/vec3.hpp"

namespace rstruct::triangulation {

/// Hilbert index (63 bits, 21 per axis) of grid cell (x, y, z), each coordinate < 2^21.
std::uint64_t hilbert_index_3d(std::uint32_t x, std::uint32_t y, std::uint32_t z);

/// hilbert_index_3d of the cells (x[i], y[i], z[i]) into out[i] for i < x.size(), several
/// at a time (the orders compute their keys this way).
/// \throws InvalidInput when x, y, z and out differ in size.
void hilbert_indices_3d(std::span<const std::uint32_t> x, std::span<const std::uint32_t> y,
                        std::span<const std::uint32_t> z, std::span<std::uint64_t> out);

/// The indices 0..n−1 of `points` in Hilbert order (ties broken by index), computed on
/// `threads` threads (0: hardware concurrency); the order does not depend on them.
/// \pre every coordinate finite.
std::vector<std::uint32_t> hilbert_order(std::span<const Point3> points, unsigned threads = 1);

/// BRIO order: every index drawn into a random round (a function of `seed` and the index)
/// with rounds of geometrically growing expected size (the last round holds each index with
/// probability 1 − 1/ratio_divisor, the round before it the same share of the rest, and so
/// on down to a first round of expected size at most `min_round`); rounds in order, each
/// sorted along the Hilbert curve. Computed on `threads` threads (0: hardware
/// concurrency); the order does not depend on them. With `keys`, also hilbert_keys(points)
/// into *keys (the same keys: no second pass over the points).
/// \pre every coordinate finite; ratio_divisor >= 2.
std::vector<std::uint32_t> brio_order(std::span<const Point3> points, std::uint64_t seed,
                                      std::uint32_t ratio_divisor = 4,
                                      std::size_t min_round = 256, unsigned threads = 1,
                                      std::vector<std::uint32_t>* keys = nullptr);

/// The top 32 bits of the Hilbert keys brio_order() sorts each round by (12 bits per axis
/// over the bounding box of `points`), one per point: points in the same order along the
/// curve have non-decreasing keys. The parallel construction partitions space with them.
/// \pre every coordinate finite.
std::vector<std::uint32_t> hilbert_keys(std::span<const Point3> points);

}  // namespace rstruct::triangulation
