#pragma once
/// \file
/// The polynomials behind every predicate, written once as templates over the number
/// type. The same template is instantiated with `double` (the filters), with `mpz_class`
/// on exactly scaled integers (the exact stage) and with the error-tracking type of
/// proofs/filter_bounds.cpp (which re-derives the filter constants from these very
/// evaluation orders). Changing an evaluation order here changes the rounding error:
/// run the proofs suite after any edit.
///
/// Arguments are *differences* of input coordinates (and of weights), so that every
/// polynomial is translation invariant and homogeneous.

namespace rstruct::predicates::detail {

/// 2×2 minor px·qy − qx·py.
template <class T>
T minor2(const T& px, const T& py, const T& qx, const T& qy) {
  return T(px * qy) - T(qx * py);
}

/// 3×3 determinant of rows p, q, r, expanded along the third column:
/// pz·m(q, r) − qz·m(p, r) + rz·m(p, q) with m the 2×2 minor of the first two columns.
template <class T>
T det3_from_minors(const T& pz, const T& qz, const T& rz, const T& m_qr, const T& m_pr,
                   const T& m_pq) {
  return T(T(pz * m_qr) - T(qz * m_pr)) + T(rz * m_pq);
}

/// 3×3 determinant det[p; q; r] (rows).
template <class T>
T det3(const T& px, const T& py, const T& pz, const T& qx, const T& qy, const T& qz,
       const T& rx, const T& ry, const T& rz) {
  const T m_qr = minor2(qx, qy, rx, ry);
  const T m_pr = minor2(px, py, rx, ry);
  const T m_pq = minor2(px, py, qx, qy);
  return det3_from_minors(pz, qz, rz, m_qr, m_pr, m_pq);
}

/// Squared length x² + y² + z², summed as (x² + y²) + z².
template <class T>
T squared_length(const T& x, const T& y, const T& z) {
  return T(T(x * x) + T(y * y)) + T(z * z);
}

/// Rows of a lifted 4×4 determinant: (x, y, z, l) for four points relative to a fifth.
template <class T>
struct LiftedRows {
  T ax, ay, az, al;
  T bx, by, bz, bl;
  T cx, cy, cz, cl;
  T dx, dy, dz, dl;
};

/// −det[(a, la); (b, lb); (c, ld); (d, ld)] (rows of four entries), expanded along the
/// lifted column: (la·M_a − lb·M_b) + (lc·M_c − ld·M_d) where M_p is the 3×3 determinant of
/// the other three rows' (x, y, z) in order. With rows p − e and l = |p − e|² − (w_p − w_e)
/// this is minus the 5×5 lifted determinant det[(p, |p|² − w_p, 1)] of a, b, c, d, e
/// (see predicates.hpp for the sign convention it produces).
/// Always inlined: the filters' rows then stay in registers (the triangulation's conflict
/// test calls it for every cell it visits); inlining does not change the evaluation order.
template <class T>
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
inline T lifted_det4_negated(const LiftedRows<T>& r) {
  const T m_ab = minor2(r.ax, r.ay, r.bx, r.by);
  const T m_ac = minor2(r.ax, r.ay, r.cx, r.cy);
  const T m_ad = minor2(r.ax, r.ay, r.dx, r.dy);
  const T m_bc = minor2(r.bx, r.by, r.cx, r.cy);
  const T m_bd = minor2(r.bx, r.by, r.dx, r.dy);
  const T m_cd = minor2(r.cx, r.cy, r.dx, r.dy);
  const T det_bcd = det3_from_minors(r.bz, r.cz, r.dz, m_cd, m_bd, m_bc);
  const T det_acd = det3_from_minors(r.az, r.cz, r.dz, m_cd, m_ad, m_ac);
  const T det_abd = det3_from_minors(r.az, r.bz, r.dz, m_bd, m_ad, m_ab);
  const T det_abc = det3_from_minors(r.az, r.bz, r.cz, m_bc, m_ac, m_ab);
  return T(T(r.al * det_bcd) - T(r.bl * det_acd)) + T(T(r.cl * det_abd) - T(r.dl * det_abc));
}

/// det[(au, av, ah); (bu, bv, bh); (cu, cv, ch)]: the lifted determinant of three points
/// in a plane, projected to two coordinates (u, v) and lifted by h.
template <class T>
T lifted_det3(const T& au, const T& av, const T& ah, const T& bu, const T& bv, const T& bh,
              const T& cu, const T& cv, const T& ch) {
  return det3(au, av, ah, bu, bv, bh, cu, cv, ch);
}

/// det[(aq, ah); (bq, bh)] = aq·bh − bq·ah: the lifted determinant of two points on a line
/// projected to one coordinate q and lifted by h.
template <class T>
T lifted_det2(const T& aq, const T& ah, const T& bq, const T& bh) {
  return T(aq * bh) - T(bq * ah);
}

/// Lifting height |t|² − tw of a point at difference t from the query, with weight
/// difference tw = w_p − w_e.
template <class T>
T lifted_height(const T& x, const T& y, const T& z, const T& tw) {
  return squared_length(x, y, z) - tw;
}

/// |x − p|² − |x − q|² from the differences tp = x − p, tq = x − q.
template <class T>
T squared_distance_difference(const T& px, const T& py, const T& pz, const T& qx,
                              const T& qy, const T& qz) {
  return squared_length(px, py, pz) - squared_length(qx, qy, qz);
}

/// (|tp|² − wp) − (|tq|² − wq): difference of two power distances at one point.
template <class T>
T power_difference(const T& px, const T& py, const T& pz, const T& wp, const T& qx,
                   const T& qy, const T& qz, const T& wq) {
  return T(squared_length(px, py, pz) - wp) - T(squared_length(qx, qy, qz) - wq);
}

/// |t|² − w: the power of a point at difference t from a weighted point of weight w.
template <class T>
T power_value(const T& x, const T& y, const T& z, const T& w) {
  return squared_length(x, y, z) - w;
}

/// |t|² − r·r: the side of a point at difference t from the centre of a ball of radius r.
template <class T>
T ball_side_value(const T& x, const T& y, const T& z, const T& r) {
  return squared_length(x, y, z) - T(r * r);
}

}  // namespace rstruct::predicates::detail
