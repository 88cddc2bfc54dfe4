#include "rstruct/medial/medial_axis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include <gmpxx.h>

#include "rstruct/complex/dual_complex.hpp"
#include "rstruct/core/assert.hpp"
#include "rstruct/core/error.hpp"
#include "rstruct/core/stopwatch.hpp"
#include "rstruct/medial/boundary_vertices.hpp"
#include "rstruct/predicates/predicates.hpp"
#include "rstruct/triangulation/regular_triangulation_3.hpp"
#include "medial/circumcentre_side.hpp"
#include "medial/exact_cospherical.hpp"
#include "medial/sphere_incidence.hpp"
#include "medial/union_triangulation.hpp"

namespace rstruct::medial {

namespace {

using triangulation::CellId;
using triangulation::RegularTriangulation3;

constexpr std::uint32_t kNone = 0xffffffffu;

// ---- keys ----------------------------------------------------------------------------

enum KeyKind : std::uint32_t { kTet = 0, kCentre = 1, kCut = 2, kOther = 3 };

struct Key {
  std::array<std::uint32_t, 7> v{kNone, kNone, kNone, kNone, kNone, kNone, kNone};
  friend bool operator==(const Key&, const Key&) = default;
};

struct KeyHash {
  std::size_t operator()(const Key& k) const {
    std::uint64_t h = 0x9E3779B97F4A7C15ull;
    for (std::uint32_t x : k.v) {
      h ^= x + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
    }
    return static_cast<std::size_t>(h);
  }
};

Key tet_key(CellId c) { return Key{{kTet, c, kNone, kNone, kNone, kNone, kNone}}; }
Key centre_key(std::uint32_t m) { return Key{{kCentre, m, kNone, kNone, kNone, kNone, kNone}}; }

/// A set of up to sixteen ball ids, increasing, padded with kNone (a point of V on more
/// than sixteen spheres is an InvalidInput).
struct IdSet {
  static constexpr int kCapacity = 16;
  std::array<std::uint32_t, kCapacity> id = [] {
    std::array<std::uint32_t, kCapacity> a{};
    a.fill(kNone);
    return a;
  }();
  int size = 0;
  bool contains(std::uint32_t x) const {
    for (int i = 0; i < size; ++i) {
      if (id[i] == x) return true;
    }
    return false;
  }
  void insert(std::uint32_t x) {
    if (contains(x)) return;
    if (size == kCapacity) {
      throw InvalidInput("medial axis: a point of the union's boundary lies on more than " +
                         std::to_string(kCapacity) + " spheres");
    }
    int i = size++;
    for (; i > 0 && id[i - 1] > x; --i) id[i] = id[i - 1];
    id[i] = x;
  }
};

IdSet intersect(const IdSet& a, const IdSet& b) {
  IdSet r;
  for (int i = 0; i < a.size; ++i) {
    if (b.contains(a.id[i])) r.insert(a.id[i]);
  }
  return r;
}

/// A face of the normal cone of a boundary vertex a: the plane (a, c_p, c_q), with the
/// cone on the side `inside` (orient3d sign of the other generators).
struct ConeFace {
  std::uint32_t p = 0;
  std::uint32_t q = 0;
  Sign inside = Sign::zero;
  /// Whether the arc of S_p ∩ S_q that leaves the site across this face reaches the next
  /// boundary vertex within a half circle (see link_arc_partners).
  bool short_arc = false;
};

/// A Delaunay vertex of V: its point and every ball it lies on. Points of V from different
/// facets that round to exactly the same coordinates (four or more spheres through one
/// point, e.g. equal balls on a grid) are one Delaunay vertex; it gets all their balls.
struct Site {
  Point3 point;
  IdSet tags;
  std::vector<ConeFace> faces;
};

/// Faces of cone(a) = a + cone(c_t − a : t ∈ tags): the pairs {p, q} whose plane through a
/// has every other generator on one side (exact orient3d).
std::vector<ConeFace> cone_faces(const Site& site, std::span<const Ball> balls) {
  std::vector<ConeFace> faces;
  const IdSet& t = site.tags;
  for (int i = 0; i < t.size; ++i) {
    for (int j = i + 1; j < t.size; ++j) {
      int positive = 0, negative = 0;
      for (int r = 0; r < t.size; ++r) {
        if (r == i || r == j) continue;
        const Sign s = predicates::orient3d(site.point, balls[t.id[i]].c, balls[t.id[j]].c,
                                            balls[t.id[r]].c);
        positive += s == Sign::positive ? 1 : 0;
        negative += s == Sign::negative ? 1 : 0;
      }
      if ((positive == 0) == (negative == 0)) continue;  // not a face, or a flat cone
      faces.push_back({t.id[i], t.id[j], positive > 0 ? Sign::positive : Sign::negative});
    }
  }
  return faces;
}

/// The filter terms of each Delaunay cell's circumcentre, computed on first use.
class CircumcentreCache {
 public:
  explicit CircumcentreCache(const RegularTriangulation3& del)
      : del_(del), cell_(del.cell_capacity()), have_(del.cell_capacity(), false) {}

  const CellCircumcentre& operator()(CellId c) {
    if (!have_[c]) {
      const auto vs = del_.vertices(c);
      cell_[c] = CellCircumcentre(del_.point(vs[0]), del_.point(vs[1]), del_.point(vs[2]),
                                  del_.point(vs[3]));
      have_[c] = true;
    }
    return cell_[c];
  }

 private:
  const RegularTriangulation3& del_;
  std::vector<CellCircumcentre> cell_;
  std::vector<bool> have_;
};

/// The side of the Voronoi vertex z of the Delaunay cell `cell` of V relative to the plane
/// of the face (s; p, q) of site s's normal cone: the sign of orient3d(site s, c_p, c_q, z),
/// decided as it is for the exact boundary vertices, of which the sites are roundings.
///
/// If the cell has another site s' on the spheres p and q, then s and s' lie on the circle
/// S_p ∩ S_q, so z (equidistant from both) lies on their bisector plane, which contains the
/// axis c_p c_q, as does the face plane. Two planes through one line: z's side of the face
/// plane is fixed by which half of the bisector plane z is on, z − axis towards s and s'
/// (then z is on the side of s') or away from them (then on the other side). With the
/// rounded sites, z's position around the axis is at the mercy of their 10⁻¹⁶ errors when z
/// is near the axis (as it is where four spheres almost meet in a point and their boundary
/// vertices come in clusters 10⁻⁶ … 10⁻¹⁴ apart), while its distance from the axis is not.
/// So the side is sign(λ) · orient3d(s, c_p, c_q, s'), λ > 0 iff z and s lie on the same side
/// of the plane through the axis with normal (c_q − c_p) × (s' − s). Two or more such s'
/// put z on the axis: zero. Without such s', the side is circumcentre_side on the cell.
/// All signs are exact on the double inputs.
Sign cone_face_side(const RegularTriangulation3& del, CircumcentreCache& circumcentre, CellId cell,
                    std::span<const Site> sites, std::uint32_t s, const ConeFace& face,
                    std::span<const Ball> balls) {
  const std::uint32_t p = face.p, q = face.q;
  const auto vs = del.vertices(cell);
  const auto nv = static_cast<std::uint32_t>(sites.size());
  std::uint32_t partner = kNone;
  int partners = 0;
  for (auto t : vs) {
    if (t != s && t < nv && sites[t].tags.contains(p) && sites[t].tags.contains(q)) {
      partner = t;
      ++partners;
    }
  }
  const Point3& a = sites[s].point;
  const Point3& cp = balls[p].c;
  const Point3& cq = balls[q].c;
  if (partners == 0) {
    const Sign side = circumcentre(cell).side(a, cp, cq);
    if (to_int(side * face.inside) >= 0 || !face.short_arc) return side;
    // z beyond the face means the Voronoi ball leaves U along the arc from s, so the arc
    // comes closer to z than s: for exact boundary vertices and a cell that is Delaunay,
    // z's nearest point on the circle lies in the first half of that arc, which (the arc
    // being shorter than a half circle) is on s's side of the axis. z on the other side
    // (as the Voronoi vertices of a whole cluster's far side are, when the rounding of V
    // decides which cluster point is nearer) is therefore within the cone for exact V.
    const Sign half = circumcentre(cell).radial_side(a, cp, cq);
    return half == Sign::positive ? side : Sign::zero;
  }
  if (partners > 1) return Sign::zero;
  const Point3& b = sites[partner].point;
  const Sign across = predicates::orient3d(a, cp, cq, b);
  if (across == Sign::zero) {
    // s' on the face plane: s and s' are antipodal on the circle (twins of a singular facet
    // whose centre lies on the axis), their bisector plane is perpendicular to the face
    // plane, and z's side is a plain, well-conditioned side test.
    return circumcentre(cell).side(a, cp, cq);
  }
  const Sign z_half = circumcentre(cell).side(cp, cp, cq, a, b);
  const Sign s_half = point_side(a, cp, cp, cq, a, b);
  return z_half * s_half * across;
}

/// For every cone face (a; p, q), the arc of ∂U on the circle S_p ∩ S_q that leaves a on
/// the face's outer side, and the site at its other end: the next site on that circle in
/// that direction (the boundary vertices on a circle are exactly where its arcs of ∂U
/// begin and end). Angles around the circle's axis are doubles, a documented
/// approximation: they order sites whose separation exceeds the rounding of V.
void link_arc_partners(std::vector<Site>& sites, const std::vector<bool>& live,
                       std::span<const Ball> balls) {
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> on_circle;
  for (std::uint32_t v = 0; v < sites.size(); ++v) {
    if (!live[v]) continue;
    const IdSet& t = sites[v].tags;
    for (int i = 0; i < t.size; ++i) {
      for (int j = i + 1; j < t.size; ++j) {
        on_circle[(std::uint64_t{t.id[i]} << 32) | t.id[j]].push_back(v);
      }
    }
  }
  for (std::uint32_t v = 0; v < sites.size(); ++v) {
    if (!live[v]) continue;
    for (ConeFace& f : sites[v].faces) {
      const auto& members = on_circle[(std::uint64_t{f.p} << 32) | f.q];
      const Point3& cp = balls[f.p].c;
      const Vec3 axis = balls[f.q].c - cp;
      const Point3& a = sites[v].point;
      // An orthonormal frame around the axis with e1 towards a.
      const Vec3 along = (dot(a - cp, axis) / dot(axis, axis)) * axis;
      Vec3 e1 = (a - cp) - along;
      const double len1 = std::sqrt(dot(e1, e1));
      if (!(len1 > 0)) continue;
      e1 = (1.0 / len1) * e1;
      Vec3 e2 = cross(axis, e1);
      e2 = (1.0 / std::sqrt(dot(e2, e2))) * e2;
      // Moving from a along +e2 (increasing angle) leaves the cone iff orient3d(a, c_p,
      // c_q, a + t e2) has the sign opposite to `inside`; e2 is normal to the face plane.
      const double turn = dot(cross(cp - a, balls[f.q].c - a), e2);
      const double dir = (turn > 0) == (f.inside == Sign::positive) ? -1.0 : 1.0;
      double best = 7.0;
      std::uint32_t partner = kNone;
      for (std::uint32_t m : members) {
        if (m == v) continue;
        const Vec3 r = sites[m].point - cp;
        double angle = dir * std::atan2(dot(r, e2), dot(r, e1));
        if (angle <= 0) angle += 2 * M_PI;
        if (angle < best) {
          best = angle;
          partner = m;
        }
      }
      f.short_arc = partner != kNone && best < M_PI;
    }
  }
}

// ---- clipping --------------------------------------------------------------------------

struct PolyVertex {
  Key key;
  Point3 p;
};

/// What a polygon side lies on: a Voronoi edge (dual to the Delaunay triangle a, b, x) or
/// a face of a normal cone (the centres among its corners).
struct SideOrigin {
  bool voronoi_edge = true;
  std::uint32_t third = kNone;  ///< x, for a Voronoi edge
  IdSet centres;                ///< for a cut side
};

struct Plane {
  std::uint32_t site = kNone;  ///< the boundary vertex whose cone face this is
  const ConeFace* face = nullptr;
  std::array<Point3, 3> corner;
  IdSet centres;
  Sign inside = Sign::zero;  ///< orient3d(corners, the third centre of the cone)
  Vec3 normal;               ///< double, for the intersection parameter only
};

class Clipper {
 public:
  Clipper(std::span<const Ball> balls, std::span<const Site> sites,
          const RegularTriangulation3& del, CircumcentreCache& circumcentre)
      : balls_(balls), sites_(sites), del_(del), circumcentre_(circumcentre) {}

  /// Clips the polygon of the Voronoi face F(a, b) by the faces of a's normal cone that
  /// contain an axis c_p c_q lying in F(a, b), i.e. whose balls p, q both a and b lie on:
  /// the half-space of the plane (a, c_p, c_q) holding the cone.
  void clip(std::uint32_t a, std::uint32_t b, std::vector<PolyVertex>& poly,
            std::vector<SideOrigin>& sides) {
    const Site& sa = sites_[a];
    const IdSet tab = intersect(sa.tags, sites_[b].tags);
    if (tab.size < 2) return;
    for (const ConeFace& face : sa.faces) {
      if (poly.empty()) return;
      if (!tab.contains(face.p) || !tab.contains(face.q)) continue;
      Plane plane;
      plane.site = a;
      plane.face = &face;
      plane.corner = {sa.point, balls_[face.p].c, balls_[face.q].c};
      plane.centres.insert(face.p);
      plane.centres.insert(face.q);
      plane.inside = face.inside;
      plane.normal = cross(plane.corner[1] - plane.corner[0], plane.corner[2] - plane.corner[0]);
      clip_by(plane, a, b, tab, poly, sides);
    }
  }

 private:
  /// A Voronoi vertex is decided on its cell (cone_face_side), a centre is an input point;
  /// a cut vertex is a rounded construction, tested as such (orient3d on the double).
  int side(const Plane& plane, const PolyVertex& x) const {
    Sign s;
    if (x.key.v[0] == kTet) {
      s = cone_face_side(del_, circumcentre_, x.key.v[1], sites_, plane.site, *plane.face,
                         balls_);
    } else {
      s = predicates::orient3d(plane.corner[0], plane.corner[1], plane.corner[2], x.p);
    }
    return to_int(s * plane.inside);
  }

  Key cut_key(const SideOrigin& o, const Plane& plane, std::uint32_t a, std::uint32_t b,
              const IdSet& tab) {
    if (o.voronoi_edge) {
      // The Voronoi edge of triangle (a, b, x) passes through every centre its three
      // points share; if the cutting face also contains that centre, they meet there.
      if (o.third < sites_.size()) {  // not a far point
        const IdSet shared = intersect(intersect(tab, sites_[o.third].tags), plane.centres);
        if (shared.size > 0) return centre_key(shared.id[0]);
      }
      std::array<std::uint32_t, 3> t{a, b, o.third};
      std::sort(t.begin(), t.end());
      return Key{{kCut, t[0], t[1], t[2], plane.centres.id[0], plane.centres.id[1],
                  plane.centres.id[2]}};
    }
    // Two cone faces through a common centre c_m meet F(a, b) at c_m when c_m ∈ F(a, b).
    const IdSet shared = intersect(intersect(o.centres, plane.centres), tab);
    if (shared.size > 0) return centre_key(shared.id[0]);
    return Key{{kOther, other_counter_++, kNone, kNone, kNone, kNone, kNone}};
  }

  void clip_by(const Plane& plane, std::uint32_t a, std::uint32_t b, const IdSet& tab, std::vector<PolyVertex>& poly, std::vector<SideOrigin>& sides) {
    const std::size_t n = poly.size();
    std::vector<int> s(n);
    bool any_out = false;
    bool any_in = false;
    for (std::size_t i = 0; i < n; ++i) {
      s[i] = side(plane, poly[i]);
      any_out |= s[i] < 0;
      any_in |= s[i] > 0;
    }
    if (!any_out) return;
    if (!any_in) {
      // Only vertices on the plane may remain: a degenerate (flat) piece.
      std::vector<PolyVertex> keep;
      std::vector<SideOrigin> keep_sides;
      for (std::size_t i = 0; i < n; ++i) {
        if (s[i] == 0) {
          keep.push_back(poly[i]);
          SideOrigin o;
          o.voronoi_edge = false;
          o.centres = plane.centres;
          keep_sides.push_back(o);
        }
      }
      poly.swap(keep);
      sides.swap(keep_sides);
      return;
    }
    std::vector<PolyVertex> out;
    std::vector<SideOrigin> out_sides;
    SideOrigin cut_side;
    cut_side.voronoi_edge = false;
    cut_side.centres = plane.centres;
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t j = (i + 1) % n;
      if (s[i] >= 0) {
        out.push_back(poly[i]);
        // The side leaving poly[i] is kept (possibly shortened) unless it runs from the
        // plane to the outside: then the cut side follows poly[i].
        out_sides.push_back((s[i] > 0 || s[j] >= 0) ? sides[i] : cut_side);
      }
      if ((s[i] > 0 && s[j] < 0) || (s[i] < 0 && s[j] > 0)) {
        const Key key = cut_key(sides[i], plane, a, b, tab);
        Point3 p;
        if (key.v[0] == kCentre) {
          p = balls_[key.v[1]].c;
        } else {
          const double di = dot(plane.normal, poly[i].p - plane.corner[0]);
          const double dj = dot(plane.normal, poly[j].p - plane.corner[0]);
          // The sides were decided exactly (a Voronoi vertex on its cell's points), the
          // distances are rounded and may disagree with them, or both be zero: keep the
          // parameter in [0, 1] (0 for 0/0).
          double t = di / (di - dj);
          t = t >= 0.0 ? std::min(t, 1.0) : 0.0;
          p = poly[i].p + t * (poly[j].p - poly[i].p);
        }
        out.push_back({key, p});
        // Entering the inside: the new vertex starts the rest of the old side; leaving it:
        // the new vertex starts the cut side.
        out_sides.push_back(s[i] < 0 ? sides[i] : cut_side);
      }
    }
    poly.swap(out);
    sides.swap(out_sides);
  }

  std::span<const Ball> balls_;
  std::span<const Site> sites_;
  const RegularTriangulation3& del_;
  CircumcentreCache& circumcentre_;
  std::uint32_t other_counter_ = 0;
};

// ---- assembly ---------------------------------------------------------------------------

class Builder {
 public:
  explicit Builder(MedialAxis& axis) : axis_(axis) {}

  std::uint32_t vertex(const Key& key, const Point3& p, double radius, MedialVertexKind kind,
                       std::uint32_t source) {
    auto [it, inserted] = index_.try_emplace(key, static_cast<std::uint32_t>(axis_.vertices.size()));
    if (inserted) {
      axis_.vertices.push_back(p);
      axis_.radius.push_back(radius);
      axis_.kind.push_back(kind);
      axis_.source.push_back(source);
    }
    return it->second;
  }

 private:
  MedialAxis& axis_;
  std::unordered_map<Key, std::uint32_t, KeyHash> index_;
};

/// The circumcentre of the Delaunay cell `cell` of V lies in the normal cone of the
/// boundary vertex `site`: on the cone's side of every face (cone_face_side), never
/// decided on the rounded circumcentre.
bool circumcentre_in_normal_cone(const RegularTriangulation3& del,
                                 CircumcentreCache& circumcentre, CellId cell,
                                 std::span<const Site> sites, std::uint32_t site,
                                 std::span<const Ball> balls) {
  for (const ConeFace& f : sites[site].faces) {
    const Sign s = cone_face_side(del, circumcentre, cell, sites, site, f, balls);
    if (to_int(s * f.inside) < 0) return false;
  }
  return true;
}

/// The Voronoi vertex x of a Delaunay cell of V is medial iff its Voronoi ball lies in U:
/// x must lie in U (exact power tests against the balls, on the rounded x) and in the
/// normal cone of each of its four sites (otherwise the ball leaves U beside that site;
/// decided exactly on the cell's points).
bool is_inner_voronoi_vertex(const Point3& x, const RegularTriangulation3& del,
                             CircumcentreCache& circumcentre, CellId cell,
                             std::span<const Site> sites, const RegularTriangulation3& rt,
                             std::span<const Ball> balls, CellId& hint) {
  if (!is_finite(x)) return false;
  const auto nearest = rt.nearest_power_vertex(x, hint);
  hint = rt.incident_cell(nearest);
  if (predicates::power_sign(x, rt.weighted_point(nearest)) == Sign::positive) return false;
  for (auto s : del.vertices(cell)) {
    if (s >= sites.size() || !circumcentre_in_normal_cone(del, circumcentre, cell, sites, s, balls)) {
      return false;
    }
  }
  return true;
}

/// Adds a clipped face: a polygon whose boundary passes a vertex twice (the rounded
/// geometry of a near-degenerate face can pinch it there) is the two polygons on either
/// side of the pinch; a two-vertex loop is an edge, a one-vertex loop adds nothing.
void add_polygon(std::vector<std::uint32_t> ids, MedialAxis& axis) {
  const std::size_t n = ids.size();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      if (ids[i] != ids[j]) continue;
      std::vector<std::uint32_t> first(ids.begin() + static_cast<std::ptrdiff_t>(i),
                                       ids.begin() + static_cast<std::ptrdiff_t>(j));
      std::vector<std::uint32_t> second(ids.begin() + static_cast<std::ptrdiff_t>(j), ids.end());
      second.insert(second.end(), ids.begin(), ids.begin() + static_cast<std::ptrdiff_t>(i));
      add_polygon(std::move(first), axis);
      add_polygon(std::move(second), axis);
      return;
    }
  }
  if (n >= 3) {
    axis.faces.push_back(std::move(ids));
  } else if (n == 2) {
    axis.edges.push_back({ids[0], ids[1]});
  }
}

MedialVertexKind kind_of(const Key& key) {
  switch (key.v[0]) {
    case kTet: return MedialVertexKind::voronoi_vertex;
    case kCentre: return MedialVertexKind::ball_centre;
    default: return MedialVertexKind::cut;
  }
}

/// Balls inside another ball (|c_i − c_j| ≤ r_j − r_i, decided exactly with rationals):
/// their spheres carry no boundary point, so they are removed before the axis is built
/// (of two equal balls the one with the larger id). Only pairs joined by an edge of K can
/// nest, so only those are tested.
std::vector<bool> nested_balls(std::span<const Ball> balls, const complex::SimplicialComplex& kc) {
  std::vector<bool> removed(balls.size(), false);
  for (const auto& e : kc.edges()) {
    for (int side = 0; side < 2; ++side) {
      const std::uint32_t i = e[side], j = e[1 - side];  // is ball i inside ball j?
      const Ball& bi = balls[i];
      const Ball& bj = balls[j];
      // Floating-point prefilter for the clear cases (relative margin 10⁻¹², far above the
      // few-ulp error of these sums of squares); the rest is decided with rationals.
      const double dr_f = bj.r - bi.r;
      const double scale = bi.r + bj.r;
      if (dr_f < -1e-12 * scale) continue;
      const Vec3 dc = bi.c - bj.c;
      const double d2_f = dot(dc, dc);
      if (d2_f > dr_f * dr_f + 1e-12 * (d2_f + scale * scale)) continue;
      const mpq_class dr = mpq_class(bj.r) - mpq_class(bi.r);
      if (sgn(dr) < 0) continue;
      const mpq_class dx = mpq_class(bi.c.x) - mpq_class(bj.c.x);
      const mpq_class dy = mpq_class(bi.c.y) - mpq_class(bj.c.y);
      const mpq_class dz = mpq_class(bi.c.z) - mpq_class(bj.c.z);
      if (dx * dx + dy * dy + dz * dz > dr * dr) continue;
      // Equal balls nest both ways: keep the smaller id.
      if (sgn(dr) == 0 && sgn(dx) == 0 && sgn(dy) == 0 && sgn(dz) == 0 && i < j) continue;
      removed[i] = true;
    }
  }
  return removed;
}

}  // namespace

// ---- MedialAxis ---------------------------------------------------------------------------

std::vector<std::array<std::uint32_t, 2>> MedialAxis::all_edges() const {
  std::vector<std::array<std::uint32_t, 2>> out;
  auto add = [&](std::uint32_t i, std::uint32_t j) {
    if (i == j) return;
    out.push_back({std::min(i, j), std::max(i, j)});
  };
  for (const auto& e : edges) add(e[0], e[1]);
  for (const auto& f : faces) {
    for (std::size_t i = 0; i < f.size(); ++i) add(f[i], f[(i + 1) % f.size()]);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<std::array<std::uint32_t, 3>> MedialAxis::triangles() const {
  std::vector<std::array<std::uint32_t, 3>> out;
  for (const auto& f : faces) {
    for (std::size_t i = 1; i + 1 < f.size(); ++i) out.push_back({f[0], f[i], f[i + 1]});
  }
  return out;
}

complex::SimplicialComplex MedialAxis::simplicial_complex() const {
  complex::SimplexLists lists;
  for (std::uint32_t v = 0; v < vertices.size(); ++v) lists.vertices.push_back(v);
  for (const auto& e : all_edges()) lists.edges.push_back({e[0], e[1]});
  for (const auto& t : triangles()) lists.triangles.push_back({t[0], t[1], t[2]});
  return complex::SimplicialComplex::closure_of(lists);
}

bool MedialAxis::is_valid(std::string* problem) const {
  auto fail = [&](const std::string& what) {
    if (problem) *problem = what;
    return false;
  };
  const std::size_t n = vertices.size();
  if (radius.size() != n || kind.size() != n || source.size() != n) {
    return fail("per-vertex arrays differ in size");
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!is_finite(vertices[i]) || !std::isfinite(radius[i]) || radius[i] < 0) {
      return fail("vertex " + std::to_string(i) + " has a non-finite position or radius");
    }
  }
  for (const auto& e : edges) {
    if (e[0] >= n || e[1] >= n || e[0] == e[1]) return fail("bad edge");
  }
  for (std::size_t f = 0; f < faces.size(); ++f) {
    std::vector<std::uint32_t> ids = faces[f];
    if (ids.size() < 3) return fail("face " + std::to_string(f) + " has fewer than 3 vertices");
    std::sort(ids.begin(), ids.end());
    if (ids.back() >= n) return fail("face " + std::to_string(f) + " names a missing vertex");
    if (std::adjacent_find(ids.begin(), ids.end()) != ids.end()) {
      return fail("face " + std::to_string(f) + " repeats a vertex");
    }
  }
  for (auto v : isolated_vertices) {
    if (v >= n) return fail("bad isolated vertex");
  }
  return true;
}

// ---- the algorithm ------------------------------------------------------------------------

complex::BettiNumbers union_betti_numbers(std::span<const Ball> balls) {
  check_balls(balls);
  if (balls.empty()) return {};
  const RegularTriangulation3 rt = ball_triangulation(balls);
  const complex::DualComplex k = complex::dual_complex(rt);
  return complex::betti_numbers(ball_complex(k, balls.size()));
}

MedialAxis medial_axis_of_union(std::span<const Ball> balls, MedialAxisStats* stats) {
  check_balls(balls);
  MedialAxis axis;
  MedialAxisStats local;
  MedialAxisStats& st = stats ? *stats : local;
  st = MedialAxisStats{};
  st.balls = balls.size();
  if (balls.empty()) return axis;
  const auto n = static_cast<std::uint32_t>(balls.size());

  Stopwatch clock;
  const RegularTriangulation3 rt = ball_triangulation(balls);
  const complex::DualComplex k = complex::dual_complex(rt);
  const complex::SimplicialComplex kc = ball_complex(k, n);
  for (int d = 0; d < 4; ++d) st.k_counts[d] = kc.size(d);
  st.betti_k = complex::betti_numbers(kc);
  for (std::uint32_t i = 0; i < n; ++i) st.hidden_balls += rt.is_vertex(i) ? 0 : 1;
  st.triangulation_seconds = clock.seconds();
  clock.reset();

  const std::vector<bool> nested = nested_balls(balls, kc);
  if (std::find(nested.begin(), nested.end(), true) != nested.end()) {
    std::vector<Ball> rest;
    std::vector<std::uint32_t> id;
    for (std::uint32_t i = 0; i < n; ++i) {
      if (!nested[i]) {
        rest.push_back(balls[i]);
        id.push_back(i);
      }
    }
    MedialAxisStats sub;
    MedialAxis reduced = medial_axis_of_union(rest, &sub);
    for (std::size_t v = 0; v < reduced.source.size(); ++v) {
      if (reduced.kind[v] == MedialVertexKind::ball_centre) reduced.source[v] = id[reduced.source[v]];
    }
    sub.balls = n;
    sub.hidden_balls += n - rest.size();
    sub.triangulation_seconds += st.triangulation_seconds;
    st = sub;
    return reduced;
  }

  Builder builder(axis);
  auto centre_vertex = [&](std::uint32_t m) {
    return builder.vertex(centre_key(m), balls[m].c, balls[m].r, MedialVertexKind::ball_centre, m);
  };

  // Singular edges and vertices of K: the pieces V does not see.
  {
    std::vector<bool> edge_has_coface(kc.size(1), false);
    std::vector<bool> vertex_has_edge(kc.size(0), false);
    for (complex::SimplexIndex t = 0; t < kc.size(2); ++t) {
      for (auto e : kc.triangle_faces(t)) edge_has_coface[e] = true;
    }
    for (complex::SimplexIndex e = 0; e < kc.size(1); ++e) {
      for (auto v : kc.edge_faces(e)) vertex_has_edge[v] = true;
      if (!edge_has_coface[e]) {
        const auto& ids = kc.edges()[e];
        axis.edges.push_back({centre_vertex(ids[0]), centre_vertex(ids[1])});
        ++st.singular_edges;
      }
    }
    for (complex::SimplexIndex v = 0; v < kc.size(0); ++v) {
      if (!vertex_has_edge[v]) {
        centre_vertex(kc.vertices()[v]);
        ++st.singular_vertices;
      }
    }
  }

  // The boundary vertices, one per exact point, with every sphere through it.
  const DistinctVertices distinct = distinct_vertices(boundary_vertices(balls, rt, k), balls, rt);
  const std::vector<BoundaryVertex>& bv = distinct.vertex;
  st.boundary_vertices = bv.size();
  if (!bv.empty()) {
    const auto nv = static_cast<std::uint32_t>(bv.size());
    std::vector<Point3> points;
    points.reserve(nv + 4);
    for (const BoundaryVertex& v : bv) points.push_back(v.point);
    for (const Point3& p : far_points(balls)) points.push_back(p);
    const RegularTriangulation3 del(std::move(points));
    st.delaunay_cells = del.number_of_finite_cells();

    std::vector<Site> site(nv);
    for (std::uint32_t v = 0; v < nv; ++v) {
      site[v].point = bv[v].point;
      for (auto b : distinct.on[v]) site[v].tags.insert(b);
    }
    for (const auto& d : del.duplicate_points()) {
      if (d.point >= nv || d.vertex >= nv) continue;
      for (auto b : distinct.on[d.point]) site[d.vertex].tags.insert(b);
    }
    std::vector<bool> live(nv);
    for (std::uint32_t v = 0; v < nv; ++v) {
      live[v] = del.is_vertex(v);
      if (live[v]) site[v].faces = cone_faces(site[v], balls);
    }
    link_arc_partners(site, live, balls);

    // Cells whose common facet has five cospherical points have the same Voronoi vertex:
    // one vertex per such group. Cospherical: the rounded points are (unperturbed
    // insphere), or the exact points are and share no ball's sphere (cells that share one
    // already share its centre). Either way neither cell may be flat for the exact points:
    // four concyclic points are cospherical with any fifth, and a flat cell would chain
    // unrelated groups together (an extra closed sheet in the axis). See
    // exact_cospherical.hpp.
    std::vector<CellId> group(del.cell_capacity());
    for (CellId c = 0; c < group.size(); ++c) group[c] = c;
    auto find = [&](CellId c) {
      while (group[c] != c) c = group[c] = group[group[c]];
      return c;
    };
    std::vector<std::int8_t> flat_cell(del.cell_capacity(), -1);  // −1: not yet decided
    auto flat = [&](CellId x) {
      if (flat_cell[x] < 0) {
        const auto w = del.vertices(x);
        IdSet common = site[w[0]].tags;
        for (int q = 1; q < 4; ++q) common = intersect(common, site[w[q]].tags);
        flat_cell[x] = common.size >= 2 ||
                       exactly_coplanar({&bv[w[0]], &bv[w[1]], &bv[w[2]], &bv[w[3]]}, balls);
      }
      return flat_cell[x] == 1;
    };
    auto exact_cospherical = [&](const std::array<std::uint32_t, 4>& vs, CellId c, CellId nb,
                                 std::uint32_t apex) {
      IdSet common = site[apex].tags;
      for (auto x : vs) common = intersect(common, site[x].tags);
      return common.size == 0 &&
             maybe_cospherical({del.point(vs[0]), del.point(vs[1]), del.point(vs[2]),
                                del.point(vs[3]), del.point(apex)}) &&
             !flat(c) && !flat(nb) &&
             exactly_cospherical({&bv[vs[0]], &bv[vs[1]], &bv[vs[2]], &bv[vs[3]], &bv[apex]},
                                 balls);
    };
    del.for_each_finite_cell([&](CellId c) {
      const auto vs = del.vertices(c);
      for (auto x : vs) {
        if (x >= nv) return;
      }
      for (int i = 0; i < 4; ++i) {
        const CellId nb = del.neighbor(c, i);
        if (nb < c || del.is_infinite(nb)) continue;
        const auto apex = del.vertex(nb, del.mirror_index(c, i));
        if (apex >= nv) continue;
        const bool rounded_cospherical =
            predicates::insphere(del.point(vs[0]), del.point(vs[1]), del.point(vs[2]),
                                 del.point(vs[3]), del.point(apex)) == Sign::zero;
        if ((rounded_cospherical && !flat(c) && !flat(nb)) ||
            exact_cospherical(vs, c, nb, apex)) {
          const CellId a = find(c), b = find(nb);
          if (a != b) group[std::max(a, b)] = std::min(a, b);
        }
      }
    });

    CircumcentreCache circumcentre(del);

    // Voronoi vertex of every finite cell: the centre its sites share, or the circumcentre.
    std::vector<PolyVertex> cell_vertex(del.cell_capacity());
    std::vector<double> cell_radius(del.cell_capacity(), 0.0);
    std::vector<char> inner(del.cell_capacity(), 0);
    CellId hint = triangulation::kNoCell;
    del.for_each_finite_cell([&](CellId c) {
      const auto vs = del.vertices(c);
      IdSet shared;
      bool has_far = false;
      for (int q = 0; q < 4; ++q) {
        if (vs[q] >= nv) {
          has_far = true;
        } else {
          shared = q == 0 ? site[vs[q]].tags : intersect(shared, site[vs[q]].tags);
        }
      }
      if (!has_far && shared.size > 0) {
        // Four points of one sphere: the Voronoi vertex is its centre, the ball itself.
        cell_vertex[c] = {centre_key(shared.id[0]), balls[shared.id[0]].c};
        cell_radius[c] = balls[shared.id[0]].r;
        inner[c] = 1;
      } else {
        cell_vertex[c] = {tet_key(c), del.circumcenter(c)};
        cell_radius[c] = std::sqrt(del.squared_circumradius(c));
        if (!has_far) {
          inner[c] = is_inner_voronoi_vertex(cell_vertex[c].p, del, circumcentre, c, site, rt,
                                             balls, hint)
                         ? 1
                         : 0;
        }
      }
    });

    // One vertex per cospherical group, a shared centre first. A Voronoi vertex of several
    // cells is inner only if it lies in the normal cones of all their sites.
    del.for_each_finite_cell([&](CellId c) {
      const CellId r = find(c);
      if (r == c) return;
      if (cell_vertex[c].key.v[0] == kCentre && cell_vertex[r].key.v[0] != kCentre) {
        cell_vertex[r] = cell_vertex[c];
        cell_radius[r] = cell_radius[c];
        inner[r] = inner[c];
      } else if (cell_vertex[r].key.v[0] != kCentre && !inner[c]) {
        inner[r] = 0;
      }
    });
    del.for_each_finite_cell([&](CellId c) {
      const CellId r = find(c);
      if (r != c) {
        cell_vertex[c] = cell_vertex[r];
        cell_radius[c] = cell_radius[r];
        inner[c] = inner[r];
      }
    });

    Clipper clipper(balls, site, del, circumcentre);
    std::unordered_set<std::uint64_t> seen;
    std::vector<PolyVertex> poly;
    std::vector<SideOrigin> sides;
    del.for_each_finite_cell([&](CellId c) {
      const auto vs = del.vertices(c);
      for (int i = 0; i < 4; ++i) {
        for (int j = i + 1; j < 4; ++j) {
          std::uint32_t a = vs[i], b = vs[j];
          if (a >= nv || b >= nv) continue;
          if (a > b) std::swap(a, b);
          if (!seen.insert((std::uint64_t{a} << 32) | b).second) continue;
          const std::vector<CellId> ring = del.cells_around_edge({c, i, j});
          poly.clear();
          sides.clear();
          bool finite = true;
          for (std::size_t r = 0; r < ring.size(); ++r) {
            const CellId t = ring[r];
            const CellId u = ring[(r + 1) % ring.size()];
            if (del.is_infinite(t)) {
              finite = false;
              break;
            }
            poly.push_back(cell_vertex[t]);
            SideOrigin o;
            for (auto x : del.vertices(t)) {
              if (x != a && x != b && del.index(u, x) >= 0) o.third = x;
            }
            RSTRUCT_ASSERT(o.third != kNone);
            sides.push_back(o);
          }
          if (!finite) continue;
          clipper.clip(a, b, poly, sides);
          bool keep = !poly.empty();
          for (const PolyVertex& pv : poly) {
            if (pv.key.v[0] == kTet && !inner[pv.key.v[1]]) keep = false;
          }
          if (!keep) continue;
          // Consecutive repeats (a side cut to nothing) go; a face that shrinks to one
          // point adds nothing (the point, if medial, comes with the faces around it).
          std::vector<const PolyVertex*> distinct_run;
          for (const PolyVertex& pv : poly) {
            if (distinct_run.empty() || !(distinct_run.back()->key == pv.key)) {
              distinct_run.push_back(&pv);
            }
          }
          while (distinct_run.size() > 1 && distinct_run.front()->key == distinct_run.back()->key) {
            distinct_run.pop_back();
          }
          if (distinct_run.size() < 2) continue;
          std::vector<std::uint32_t> ids;
          for (const PolyVertex* pv : distinct_run) {
            double radius = distance(pv->p, bv[a].point);
            std::uint32_t source = kNone;
            if (pv->key.v[0] == kCentre) {
              radius = balls[pv->key.v[1]].r;
              source = pv->key.v[1];
            }
            ids.push_back(builder.vertex(pv->key, pv->p, radius, kind_of(pv->key), source));
          }
          add_polygon(std::move(ids), axis);
        }
      }
    });
  }

  // Vertices on no edge or face.
  {
    std::vector<bool> used(axis.vertices.size(), false);
    for (const auto& e : axis.edges) used[e[0]] = used[e[1]] = true;
    for (const auto& f : axis.faces) {
      for (auto v : f) used[v] = true;
    }
    for (std::uint32_t v = 0; v < axis.vertices.size(); ++v) {
      if (!used[v]) axis.isolated_vertices.push_back(v);
    }
  }
  st.voronoi_seconds = clock.seconds();
  RSTRUCT_DEBUG_ASSERT(axis.is_valid());
  return axis;
}

}  // namespace rstruct::medial
