#pragma once
/// \file
/// Poles of an r-sample (Amenta–Bern 1999; paper §2; DESIGN.md §1) computed from a Delaunay
/// tetrahedralisation of the samples plus bounding-box sites.
///
/// For every sample s (a vertex whose Voronoi cell is bounded thanks to the box sites):
///  - first pole p⁺(s): the Voronoi vertex of s's cell farthest from s, i.e. the circumcentre
///    of the incident tetrahedron with the largest circumradius;
///  - second pole p⁻(s): the farthest Voronoi vertex v of the cell with (v − s)·(p⁺ − s) < 0.
/// A pole is a Voronoi vertex, i.e. a Delaunay tetrahedron: poles shared by several samples
/// are stored once, identified by their tetrahedron (a combinatorial identity, never by
/// comparing coordinates). The polar ball of a pole is the tetrahedron's circumball.
///
/// Approximations (documented, DESIGN.md §0): circumcentres are rounded doubles
/// (see src/poles/circumsphere.hpp); the choice of the farthest vertex and the sign of
/// (v − s)·(p⁺ − s) are evaluated on those doubles. Ties in the circumradius go to the
/// tetrahedron whose sorted vertex ids come first lexicographically, and poles are
/// numbered in the order of their owners (p⁺ before p⁻), so the poles do not depend on
/// the order in which the soup lists the tetrahedra. The circumcentre is computed from a
/// tetrahedron's vertices in the order listed: analyse_poles lists them sorted, so that
/// nothing depends on the triangulation's cell numbering.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "rstruct/geometry/vec3.hpp"

namespace rstruct::poles {

inline constexpr std::uint32_t kNoPole = 0xffffffffU;

/// Inner/outer label of a pole (power crust labeling, see pole_labeling.hpp).
enum class PoleLabel : std::uint8_t { unlabelled = 0, inner = 1, outer = 2 };

/// A Delaunay tetrahedralisation as flat arrays: vertices [0, sample_count) are the samples,
/// the rest are extra sites (the bounding-box corners), which get no poles.
/// `tets` lists every finite tetrahedron once (any orientation). A sample that is not a
/// vertex (an exact duplicate merged by the triangulation) names in `representative` the
/// vertex it was merged into; an empty `representative` means every sample is a vertex.
struct TetrahedronSoup {
  std::span<const Point3> vertices;
  std::size_t sample_count = 0;
  std::span<const std::array<std::uint32_t, 4>> tets;
  std::span<const std::uint32_t> representative;
};

struct PoleSet {
  std::size_t sample_count = 0;

  // One entry per (distinct) pole.
  std::vector<Point3> centre;                       ///< circumcentre (Voronoi vertex)
  std::vector<double> radius;                       ///< polar radius = circumradius
  std::vector<std::uint32_t> tet;                   ///< index of its tetrahedron in the soup
  std::vector<std::array<std::uint32_t, 4>> sites;  ///< the tetrahedron's vertices
  std::vector<std::uint32_t> owner;                 ///< smallest vertex having it as a pole
  std::vector<PoleLabel> label;                     ///< all unlabelled until label_poles()

  /// Per sample: {first pole p⁺, second pole p⁻} as pole indices (kNoPole if the sample
  /// has no vertex on the far side of p⁺). A duplicate shares its representative's poles.
  std::vector<std::array<std::uint32_t, 2>> sample_poles;
  /// Per sample: the vertex whose Voronoi cell it has (itself, or the sample it duplicates).
  std::vector<std::uint32_t> representative;

  std::size_t size() const { return centre.size(); }
  /// True if the pole's tetrahedron has a bounding-box site: such poles are outer.
  bool is_box_pole(std::uint32_t p) const {
    for (const std::uint32_t v : sites[p]) {
      if (v >= sample_count) return true;
    }
    return false;
  }
  /// The pole of sample s labelled `which` among its two poles, or kNoPole.
  std::uint32_t pole_of(std::uint32_t s, PoleLabel which) const {
    for (const std::uint32_t p : sample_poles[s]) {
      if (p != kNoPole && label[p] == which) return p;
    }
    return kNoPole;
  }
  /// Sizes agree, no tetrahedron is two poles, indices in range, radii finite and
  /// positive, every sample's poles are tetrahedra incident to it, owners are the smallest
  /// such samples, p⁻ ≠ p⁺ and p⁻ is not larger than p⁺.
  bool is_valid() const;
};

/// Poles of the samples from a Delaunay tetrahedralisation, in `threads` threads (0:
/// hardware concurrency) but at most one per `tetrahedra_per_thread` tetrahedra; each takes
/// chunks of the tetrahedra as it finishes the last (their circumspheres, and the poles
/// among them of every sample), and the threads' choices are merged. The result does not
/// depend on either parameter, nor on which thread took which chunk.
/// \throws InvalidInput if a tetrahedron has a vertex index out of range, or a representative
/// is out of range or is itself not its own representative.
/// \throws InternalError if a tetrahedron is flat.
PoleSet compute_poles(const TetrahedronSoup& soup, unsigned threads = 0,
                      std::size_t tetrahedra_per_thread = std::size_t{1} << 16);

}  // namespace rstruct::poles
