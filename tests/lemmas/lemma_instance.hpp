#pragma once
// Random instances of the lemma property tests: a sphere, ellipsoid or torus with random
// parameters, rotation and translation; a certified r-sample of it with r drawn in
// [r_min, 0.08]; its poles, labels and D̂ (poles module); and the Delaunay triangulation
// with the same bounding-box sites, for the Voronoi vertices of Lemma 5.2.
//
// Environment (defaults keep the whole executable within the CI budget):
//   RSTRUCT_LEMMAS_SEED        base seed (instance i uses derive_seed(seed, i))
//   RSTRUCT_LEMMAS_INSTANCES   number of instances (shapes cycle sphere, ellipsoid, torus)
//   RSTRUCT_LEMMAS_RMIN        smallest r drawn (r is log-uniform in [RMIN, 0.08])
//   RSTRUCT_LEMMAS_MAX_POINTS  per-instance sample cap: when the r drawn would need more
//                              points, r is moved towards 0.08 until it fits

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "rstruct/complex/homology.hpp"
#include "rstruct/poles/pole_analysis.hpp"
#include "rstruct/sampling/surface.hpp"
#include "rstruct/triangulation/regular_triangulation_3.hpp"

namespace rstruct::lemmas {

inline constexpr double kPaperR = 0.08;  // the paper's sampling constant

struct LemmaSettings {
  std::uint64_t seed = 20090715;
  int instances = 5;
  double r_min = 0.05;
  std::size_t max_points = 6000;
};

/// The settings from the environment (see the file comment); throws InvalidInput for an
/// unparsable value.
LemmaSettings settings_from_environment();

struct Instance {
  int id = 0;
  std::string shape;                                 ///< "sphere", "ellipsoid", "torus"
  std::shared_ptr<const sampling::Surface> surface;  ///< placed (rotated, translated)
  complex::BettiNumbers surface_betti;               ///< F's Betti numbers
  double r_drawn = 0;
  double r_certified = 0;  ///< certificate upper bound: S is an r_certified-sample
  std::vector<Point3> samples;
  poles::PoleAnalysis analysis;
  std::vector<bool> pole_inside;  ///< ground truth: the pole's centre is inside O
  /// Delaunay triangulation of samples + bounding-box sites (the same sites as the pole
  /// analysis, so its circumcentres are the same Voronoi vertices).
  std::unique_ptr<triangulation::RegularTriangulation3> delaunay;
  double rho = 0;  ///< ρ drawn in [0.24, 0.56] for Lemma 5.6 / Theorem 6.1
  std::string describe() const;
};

/// Instance `id` of a run with these settings (deterministic).
Instance make_instance(const LemmaSettings& settings, int id);

}  // namespace rstruct::lemmas
