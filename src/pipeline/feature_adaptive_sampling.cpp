#include "rstruct/pipeline/feature_adaptive_sampling.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "rstruct/core/error.hpp"
#include "rstruct/poles/pole_analysis.hpp"
#include "rstruct/poles/pole_distance.hpp"
#include "rstruct/sampling/random.hpp"
#include "rstruct/sampling/uniform_sampling.hpp"

namespace rstruct::pipeline {

namespace {

constexpr std::size_t kMinCount = 1000;

void check_options(std::size_t count, const FeatureAdaptiveOptions& options) {
  std::ostringstream msg;
  if (count < kMinCount) {
    msg << "feature-adaptive sampling needs at least " << kMinCount << " points (got " << count
        << ")";
  } else if (options.rounds < 1 || options.rounds > 10) {
    msg << "feature-adaptive sampling: rounds must be in [1, 10] (got " << options.rounds << ")";
  } else if (!(options.pilot_fraction > 0.0 && options.pilot_fraction <= 1.0)) {
    msg << "feature-adaptive sampling: pilot fraction must be in (0, 1]";
  } else if (!(options.max_ratio >= 1.0) || !std::isfinite(options.max_ratio)) {
    msg << "feature-adaptive sampling: max ratio must be a finite number >= 1";
  } else {
    return;
  }
  throw InvalidInput(msg.str());
}

}  // namespace

FeatureAdaptiveSample sample_mesh_feature_adaptive(const TriangleMesh& mesh, std::size_t count,
                                                   std::uint64_t seed,
                                                   const FeatureAdaptiveOptions& options) {
  check_options(count, options);
  const auto pilot = std::max<std::size_t>(
      kMinCount, static_cast<std::size_t>(options.pilot_fraction * static_cast<double>(count)));
  FeatureAdaptiveSample result;
  result.points = sampling::sample_mesh_uniform(mesh, pilot, sampling::derive_seed(seed, 0));

  // Face centroids (floating point; only used to place the density).
  std::vector<Point3> centroids;
  centroids.reserve(mesh.faces.size());
  for (const auto& f : mesh.faces) {
    const Point3& a = mesh.vertices[f[0]];
    const Point3& b = mesh.vertices[f[1]];
    const Point3& c = mesh.vertices[f[2]];
    centroids.push_back((a + b + c) / 3.0);
  }

  poles::PoleAnalysisOptions pole_options;
  pole_options.threads = options.threads;
  for (unsigned round = 1; round <= options.rounds; ++round) {
    const poles::PoleAnalysis analysis = poles::analyse_poles(result.points, pole_options);
    result.face_scale =
        poles::pole_distance(centroids, analysis.poles.centre, options.threads).distance;
    const double largest =
        *std::max_element(result.face_scale.begin(), result.face_scale.end());
    const double floor = largest / options.max_ratio;
    std::vector<double> density(result.face_scale.size());
    for (std::size_t f = 0; f < density.size(); ++f) {
      const double l = std::max(result.face_scale[f], floor);
      result.face_scale[f] = l;
      density[f] = 1.0 / (l * l);
    }
    result.points =
        sampling::sample_mesh_weighted(mesh, density, count, sampling::derive_seed(seed, round));
  }
  return result;
}

}  // namespace rstruct::pipeline
