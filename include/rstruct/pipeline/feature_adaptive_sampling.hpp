#pragma once
/// \file
/// Samples of a triangle mesh whose density follows the shape's local feature size, for
/// models whose lfs is not known (the real models of the test data).
///
/// Uniform-by-area samples of a model with thin parts (ears, handles, arms) are not
/// r-samples there for any affordable count: the spacing is set by the total area, the
/// needed spacing by the thinnest part. We estimate lfs by the pipeline's own D̂ (distance
/// to the nearest pole; Lemma 5.1: lfs ≤ 1.2802·D̂ on r-samples) and resample:
///
///  1. pilot: `pilot_fraction`·count points uniform by area;
///  2. each round: poles of the current points (analyse_poles), then for every face the
///     distance ℓ_f from its centroid to the nearest pole, clamped below at
///     ℓ_max / `max_ratio`; then `count` new points with density ∝ 1/ℓ_f² per unit area,
///     so that the expected spacing is proportional to ℓ_f.
///
/// The estimate is a heuristic (it is only as good as the previous round's sample), and
/// nothing here certifies the result as an r-sample: the seed pipeline's own checks (clean
/// pole labels, Betti numbers) say whether it worked. All decisions are floating point;
/// nothing combinatorial is decided here.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "rstruct/geometry/triangle_mesh.hpp"

namespace rstruct::pipeline {

struct FeatureAdaptiveOptions {
  unsigned rounds = 2;          ///< resampling rounds (≥ 1)
  double pilot_fraction = 0.5;  ///< pilot size relative to `count` (at least 1000 points)
  double max_ratio = 100.0;     ///< ℓ_f is clamped below at ℓ_max / max_ratio
  unsigned threads = 0;         ///< for the pole stage (0: hardware concurrency)
};

struct FeatureAdaptiveSample {
  std::vector<Point3> points;
  std::vector<double> face_scale;  ///< ℓ_f of the last round, one per face
};

/// `count` feature-adaptive points on `mesh` (deterministic for `seed`).
/// \throws InvalidInput for count < 1000, bad options, or what sample_mesh_uniform and
/// analyse_poles throw.
FeatureAdaptiveSample sample_mesh_feature_adaptive(const TriangleMesh& mesh, std::size_t count,
                                                   std::uint64_t seed,
                                                   const FeatureAdaptiveOptions& options = {});

}  // namespace rstruct::pipeline
