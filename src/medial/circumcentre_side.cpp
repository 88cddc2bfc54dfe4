#include "medial/circumcentre_side.hpp"

#include <gmpxx.h>

#include <array>
#include <atomic>
#include <tuple>
#include <utility>

#include "complex/filtered_number.hpp"
#include "rstruct/core/error.hpp"

namespace rstruct::medial {
namespace {

using complex::detail::FilteredNumber;

std::atomic<std::uint64_t> g_exact{0};

template <class N>
using V3 = std::array<N, 3>;

template <class N>
N difference(double x, double y) {
  return N(x) - N(y);
}
template <>
FilteredNumber difference<FilteredNumber>(double x, double y) {
  return FilteredNumber::difference(x, y);
}

template <class N>
V3<N> minus(const Point3& x, const Point3& y) {
  return {difference<N>(x.x, y.x), difference<N>(x.y, y.y), difference<N>(x.z, y.z)};
}

template <class N>
N dot(const V3<N>& x, const V3<N>& y) {
  N r = x[0] * y[0];
  r += x[1] * y[1];
  r += x[2] * y[2];
  return r;
}

template <class N>
V3<N> cross(const V3<N>& x, const V3<N>& y) {
  return {x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
}

/// n = (e1_to − e1_from) × (e2_to − e2_from).
template <class N>
V3<N> plane_normal(const Point3& e1_from, const Point3& e1_to, const Point3& e2_from,
                   const Point3& e2_to) {
  return cross(minus<N>(e1_to, e1_from), minus<N>(e2_to, e2_from));
}

/// v and Δ of the header for the cell a, b, c, d, in number type N.
template <class N>
std::pair<V3<N>, N> cell_terms(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  const V3<N> u1 = minus<N>(b, a), u2 = minus<N>(c, a), u3 = minus<N>(d, a);
  const V3<N> x1 = cross(u2, u3), x2 = cross(u3, u1), x3 = cross(u1, u2);
  const N l1 = dot(u1, u1), l2 = dot(u2, u2), l3 = dot(u3, u3);
  V3<N> v;
  for (int j = 0; j < 3; ++j) v[j] = l1 * x1[j] + l2 * x2[j] + l3 * x3[j];
  return {v, dot(u1, x1)};
}

/// 2Δ n·(a − o) + n·v.
template <class N>
N side_term(const V3<N>& v, const N& delta, const Point3& a, const V3<N>& n, const Point3& o) {
  const N two(2.0);
  return two * delta * dot(n, minus<N>(a, o)) + dot(n, v);
}

/// w = |e|² (s − p) − ((s − p)·e) e, e = q − p: |e|² times the component of s − p
/// perpendicular to the line pq (degree 3 in the inputs).
template <class N>
V3<N> radial(const Point3& s, const Point3& p, const Point3& q) {
  const V3<N> e = minus<N>(q, p), sp = minus<N>(s, p);
  const N ee = dot(e, e), se = dot(sp, e);
  return V3<N>{ee * sp[0] - se * e[0], ee * sp[1] - se * e[1], ee * sp[2] - se * e[2]};
}

/// The exact stage: the sign of n·(z − o) from rationals.
Sign exact_side(const std::array<Point3, 4>& pt, const V3<mpq_class>& n, const Point3& o) {
  g_exact.fetch_add(1, std::memory_order_relaxed);
  const auto [v, delta] = cell_terms<mpq_class>(pt[0], pt[1], pt[2], pt[3]);
  if (sgn(delta) == 0) throw InternalError("circumcentre_side: the four points are coplanar");
  return static_cast<Sign>(sgn(delta) * sgn(side_term(v, delta, pt[0], n, o)));
}

}  // namespace

CellCircumcentre::CellCircumcentre(const Point3& a, const Point3& b, const Point3& c,
                                   const Point3& d)
    : point_{a, b, c, d} {
  std::tie(v_, delta_) = cell_terms<FilteredNumber>(a, b, c, d);
}

Sign CellCircumcentre::side(const Point3& o, const Point3& e1_from, const Point3& e1_to,
                            const Point3& e2_from, const Point3& e2_to) const {
  const int sd = delta_.certified_sign();
  if (sd == 1 || sd == -1) {
    const auto n = plane_normal<FilteredNumber>(e1_from, e1_to, e2_from, e2_to);
    const int sv = side_term(v_, delta_, point_[0], n, o).certified_sign();
    if (sv != 2) return static_cast<Sign>(sd * sv);
  }
  return exact_side(point_, plane_normal<mpq_class>(e1_from, e1_to, e2_from, e2_to), o);
}

Sign CellCircumcentre::radial_side(const Point3& s, const Point3& p, const Point3& q) const {
  const int sd = delta_.certified_sign();
  if (sd == 1 || sd == -1) {
    const int sv = side_term(v_, delta_, point_[0], radial<FilteredNumber>(s, p, q), p).certified_sign();
    if (sv != 2) return static_cast<Sign>(sd * sv);
  }
  return exact_side(point_, radial<mpq_class>(s, p, q), p);
}

Sign circumcentre_side(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                       const Point3& o, const Point3& e1_from, const Point3& e1_to,
                       const Point3& e2_from, const Point3& e2_to) {
  return CellCircumcentre(a, b, c, d).side(o, e1_from, e1_to, e2_from, e2_to);
}

Sign circumcentre_side(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                       const Point3& s, const Point3& p, const Point3& q) {
  return CellCircumcentre(a, b, c, d).side(s, p, q);
}

Sign circumcentre_radial_side(const Point3& a, const Point3& b, const Point3& c,
                              const Point3& d, const Point3& s, const Point3& p,
                              const Point3& q) {
  return CellCircumcentre(a, b, c, d).radial_side(s, p, q);
}

Sign point_side(const Point3& z, const Point3& o, const Point3& e1_from, const Point3& e1_to,
                const Point3& e2_from, const Point3& e2_to) {
  {
    const auto n = plane_normal<FilteredNumber>(e1_from, e1_to, e2_from, e2_to);
    const int sf = dot(n, minus<FilteredNumber>(z, o)).certified_sign();
    if (sf != 2) return static_cast<Sign>(sf);
  }
  const auto n = plane_normal<mpq_class>(e1_from, e1_to, e2_from, e2_to);
  return static_cast<Sign>(sgn(dot(n, minus<mpq_class>(z, o))));
}

std::uint64_t circumcentre_side_exact_calls() { return g_exact.load(std::memory_order_relaxed); }

}  // namespace rstruct::medial
