#pragma once
/// \file
/// From an r-sample to its poles, their inner/outer labels and the pole distance D̂: the
/// first stage of every pipeline of the paper (§3, Figure 1; DESIGN.md §1).
///
/// 1. Delaunay triangulation of the samples plus the 8 corners of a box centred at the
///    centre (min + max)/2 of the samples' bounding box, half-width `box_scale` times the
///    largest extent, so every sample's Voronoi cell is bounded (inputs far from the origin
///    work because the box follows the data). The box sites get no poles.
/// 2. Poles (pole_set.hpp). Samples merged with an identical sample share its poles.
/// 3. Labels (pole_labeling.hpp).
/// 4. D̂(s) for every sample (pole_distance.hpp), over all poles.

#include <cstddef>
#include <span>
#include <vector>

#include "rstruct/core/report.hpp"
#include "rstruct/poles/pole_distance.hpp"
#include "rstruct/poles/pole_labeling.hpp"
#include "rstruct/poles/pole_set.hpp"

namespace rstruct::poles {

struct PoleAnalysisOptions {
  /// Half-width of the bounding-box sites' box, in units of the samples' largest extent.
  /// Must be ≥ 2: then a circumball through a box site and empty of samples has its centre
  /// outside the samples' bounding box (so box poles are outer).
  double box_scale = 3.0;
  LabelingParameters labeling;
  /// Threads for circumspheres and D̂ (0: hardware concurrency).
  unsigned threads = 0;
};

struct PoleAnalysis {
  PoleSet poles;
  LabelingStats labeling;
  PoleDistance dhat;               ///< per sample
  std::size_t duplicate_samples = 0; ///< samples merged into an identical one
  std::size_t tetrahedra = 0;      ///< finite Delaunay tetrahedra (with box sites)
  double bbox_diagonal = 0;        ///< of the samples
};

/// Runs steps 1–4. Stage seconds go to `report` ("delaunay", "poles", "labels",
/// "pole distance") and counts to report->data()["poles"] when `report` is given.
/// \throws InvalidInput if there are fewer than 4 samples, a coordinate is not finite, all
/// samples coincide, or box_scale < 2 or is not finite.
PoleAnalysis analyse_poles(std::span<const Point3> samples,
                           const PoleAnalysisOptions& options = {}, Report* report = nullptr);

/// The 8 box sites used by analyse_poles (exposed for tests).
std::vector<Point3> bounding_box_sites(std::span<const Point3> samples, double box_scale);

}  // namespace rstruct::poles
