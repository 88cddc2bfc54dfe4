#pragma once
/// \file
/// Closed smooth surfaces F = ∂O given by an implicit function, used as ground truth for
/// r-samples (paper, Definition 1; DESIGN.md §8). A surface exposes
///  - the implicit function f (negative inside O), its gradient and the outward normal;
///  - the closest point of F to a point of space;
///  - where known, the local feature size and the nearest inner / outer medial-axis points;
///  - where available, a parametrization by rectangular charts with rigorous bounds on the
///    size of every parameter cell, which the r-sample generator and its certificate use.
///
/// Local feature size is extended from F to all of R³ as the distance to the medial axis
/// M (inner ∪ outer). On F this is the paper's lfs; everywhere it is 1-Lipschitz, which is
/// what the certification argument (r_sample.hpp) needs.

#include <optional>
#include <string>

#include "rstruct/geometry/vec3.hpp"

namespace rstruct::sampling {

/// Relative bound on the rounding error of Surface::point(): each evaluation takes fewer
/// than 40 correctly rounded operations, each off by at most 2⁻⁵³ relative, so the computed
/// point is within 2⁻⁴⁶·|P|max of the exact one (a generous bound). cell_reach() adds it.
constexpr double kPointRounding = 0x1.0p-46;

/// Supported range of lengths (radii, semi-axes): squares and products of three stay
/// finite and normal, so areas and area elements never overflow or underflow.
constexpr double kMinLength = 1e-90;
constexpr double kMaxLength = 1e90;
/// Whether `length` is finite and within [kMinLength, kMaxLength].
inline bool is_supported_length(double length) {
  return length >= kMinLength && length <= kMaxLength;
}

/// An axis-parallel rectangle [u0, u1] × [v0, v1] of parameter space in chart `chart`.
struct ParamCell {
  int chart = 0;
  double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
  double u_mid() const { return 0.5 * (u0 + u1); }
  double v_mid() const { return 0.5 * (v0 + v1); }
};

/// The two 3-D extents of a parameter cell, measured from its centre's image:
/// every point P(u, v) of the cell satisfies |P(u, v) − P(u_mid, v_mid)| ≤ u_reach + v_reach,
/// where u_reach bounds the movement along u and v_reach along v. Their sum is the cell's
/// radius; the two parts let subdivision split the longer direction.
struct CellReach {
  double u_reach = 0;
  double v_reach = 0;
  double radius() const { return u_reach + v_reach; }
};

class Surface {
 public:
  virtual ~Surface() = default;

  /// Short description, e.g. "torus(R=3, a=1)".
  virtual std::string name() const = 0;

  /// Implicit function: negative inside O, zero on F, positive outside.
  virtual double value(const Point3& x) const = 0;
  /// Gradient of value() (points outward on F).
  virtual Vec3 gradient(const Point3& x) const = 0;
  /// Outward unit normal at (or near) x: the normalised gradient.
  Vec3 normal(const Point3& x) const { return normalized(gradient(x)); }
  /// Whether x lies strictly inside O (value(x) < 0).
  bool is_inside(const Point3& x) const { return value(x) < 0.0; }

  /// A closest point of F to x. Exact formulas (up to rounding) for sphere, torus and
  /// ellipsoid; Newton projection for the double torus (see its class comment).
  virtual Point3 closest_point(const Point3& x) const = 0;

  /// An axis-parallel box containing F.
  virtual Box3 bounding_box() const = 0;

  /// Whether lfs() and the medial points are known for this surface.
  virtual bool has_known_lfs() const { return false; }
  /// A nearest point of the inner medial axis to x; nullopt when unknown.
  virtual std::optional<Point3> nearest_inner_medial_point(const Point3&) const {
    return std::nullopt;
  }
  /// A nearest point of the outer medial axis to x; nullopt when there is none (sphere,
  /// ellipsoid) or it is unknown.
  virtual std::optional<Point3> nearest_outer_medial_point(const Point3&) const {
    return std::nullopt;
  }
  /// Distance from x to the medial axis (inner ∪ outer): lfs(x) for x on F.
  /// \throws InvalidInput if !has_known_lfs().
  virtual double lfs(const Point3& x) const;
  /// A sentence describing the medial axis (for reports and documentation).
  virtual std::string medial_axis_description() const { return "unknown"; }

  /// Whether the chart interface below is implemented.
  virtual bool has_parametrization() const { return false; }
  /// Number of charts; their parameter rectangles together cover F.
  virtual int chart_count() const { return 0; }
  /// The parameter rectangle of chart `chart`.
  virtual ParamCell chart_domain(int chart) const;
  /// P(u, v): the surface point with parameters (u, v) in `chart`.
  virtual Point3 point(int chart, double u, double v) const;
  /// |P_u × P_v|: area of F per unit parameter area at (u, v).
  virtual double area_element(int chart, double u, double v) const;
  /// An upper bound of area_element over the whole chart.
  virtual double max_area_element(int chart) const;
  /// Rigorous bounds on how far P moves over `cell` from P(centre) (see CellReach),
  /// including the rounding error of point().
  virtual CellReach cell_reach(const ParamCell& cell) const;
  /// Grid step for meshing the implicit function (implicit_mesher.hpp) finely enough to
  /// resolve F: default bounding-box diagonal / 200.
  virtual double meshing_step() const { return bounding_box().diagonal() / 200.0; }
  /// Total area of F (exact formula or quadrature, see each class).
  virtual double area() const = 0;
};

/// Newton's method on f along the gradient, x ← x − f ∇f / |∇f|², until the step is below
/// 1e-16 relative (at most 100 steps): a point of F near x (not the closest in general).
Point3 project_along_gradient(const Surface& surface, Point3 x);

}  // namespace rstruct::sampling
