// Power tests inside a plane and on a line (regular triangulations of dimension 2 and 1,
// and hull facets coplanar with a new point), and their perturbation.
//
// Plane: for coplanar a, b, c, e projected on a coordinate plane (u, v) where a, b, c
// stay a proper triangle, with true 3D heights h_p = |p − e|² − (w_p − w_e),
//   D3 = det[(p_u − e_u, p_v − e_v, h_p)]_{p=a,b,c} = −π(e) · orient2d(a, b, c)
// because h_p = −π(e) − 2 (p − e)·(e − z) (z the orthocentre) and the second term is a
// linear function of the in-plane coordinates, removed by column operations. Hence
// sign(−π(e)) = sign(D3) · sign(orient2d(a, b, c)), independent of the projection. D3 is
// also det[(q_p, H_p, 1)]_{p=a,b,c,e} with H_p = |p|² − w_p, linear in each H_p with
// cofactors +o(b,c,e), −o(a,c,e), +o(a,b,e), −o(a,b,c) (o = projected orient2d).
//
// Line: for collinear a, b, e and an axis q with a_q ≠ b_q,
//   D2 = (a_q − e_q) h_b − (b_q − e_q) h_a = −π(e) · (a_q − b_q),
// and D2 = det[(q_p, H_p, 1)]_{p=a,b,e} with cofactors e_q − b_q, a_q − e_q, b_q − a_q.
#include <array>
#include <string>

#include "rstruct/predicates/detail/counting.hpp"
#include "predicates/exact_stage.hpp"
#include "rstruct/predicates/detail/filters.hpp"
#include "predicates/perturbation.hpp"
#include "predicates/plane_axis.hpp"
#include "rstruct/core/error.hpp"
#include "rstruct/predicates/predicates.hpp"

namespace rstruct::predicates {
namespace {

int coplanar_d3_sign(const WeightedPoint& a, const WeightedPoint& b, const WeightedPoint& c,
                     const WeightedPoint& e, int k) {
  const int f = detail::coplanar_power_filter(a, b, c, e, k);
  if (f != detail::kUndecided) {
    RSTRUCT_PREDICATE_COUNT(coplanar_power_test, filter);
    return f;
  }
  RSTRUCT_PREDICATE_COUNT(coplanar_power_test, exact);
  return detail::coplanar_power_exact(a, b, c, e, k);
}

int collinear_d2_sign(const WeightedPoint& a, const WeightedPoint& b, const WeightedPoint& e,
                      int k) {
  const int f = detail::collinear_power_filter(a, b, e, k);
  if (f != detail::kUndecided) {
    RSTRUCT_PREDICATE_COUNT(collinear_power_test, filter);
    return f;
  }
  RSTRUCT_PREDICATE_COUNT(collinear_power_test, exact);
  return detail::collinear_power_exact(a, b, e, k);
}

int compare_doubles(double x, double y) { return x < y ? -1 : (x > y ? 1 : 0); }

/// An axis where a and b differ, and the sign of a_q − b_q.
std::pair<int, int> line_axis(const Point3& a, const Point3& b, const char* where) {
  detail::require_finite(where, {a.x, a.y, a.z, b.x, b.y, b.z});
  for (int k = 0; k < 3; ++k) {
    const auto q = static_cast<std::size_t>(k);
    if (a[q] != b[q]) return {k, compare_doubles(a[q], b[q])};
  }
  throw InvalidInput(std::string("predicates::") + where + ": the two points coincide");
}

}  // namespace

Sign coplanar_power_test(const WeightedPoint& a, const WeightedPoint& b,
                         const WeightedPoint& c, const WeightedPoint& e) {
  const detail::PlaneAxis axis = detail::choose_plane_axis(a.c, b.c, c.c, "coplanar_power_test");
  return static_cast<Sign>(coplanar_d3_sign(a, b, c, e, axis.drop) * axis.orientation);
}

Sign coplanar_power_test_sos(const WeightedPoint& a, const WeightedPoint& b,
                             const WeightedPoint& c, const WeightedPoint& e, std::uint32_t ia,
                             std::uint32_t ib, std::uint32_t ic, std::uint32_t ie) {
  const char* where = "coplanar_power_test_sos";
  const detail::PlaneAxis axis = detail::choose_plane_axis(a.c, b.c, c.c, where);
  const int s = coplanar_d3_sign(a, b, c, e, axis.drop);
  if (s != 0) return static_cast<Sign>(s * axis.orientation);
  RSTRUCT_PREDICATE_COUNT(coplanar_power_test, perturbed);
  const std::array<const Point3*, 4> p{&a.c, &b.c, &c.c, &e.c};
  for (const int k : detail::perturbation_order<4>({ia, ib, ic, ie}, where)) {
    std::array<const Point3*, 3> q{};
    for (int i = 0, j = 0; i < 4; ++i) {
      if (i != k) q[static_cast<std::size_t>(j++)] = p[static_cast<std::size_t>(i)];
    }
    const int o = detail::orient2d_axis(*q[0], *q[1], *q[2], axis.drop);
    // Cofactor (−1)^k·o of height k in D3; lowering the height by δ adds −δ·cofactor.
    if (o != 0) return static_cast<Sign>((k % 2 == 0 ? -o : o) * axis.orientation);
  }
  throw InternalError("coplanar_power_test_sos: no non-zero cofactor although a, b, c span a plane");
}

Sign collinear_power_test(const WeightedPoint& a, const WeightedPoint& b,
                          const WeightedPoint& e) {
  const auto [k, s] = line_axis(a.c, b.c, "collinear_power_test");
  return static_cast<Sign>(collinear_d2_sign(a, b, e, k) * s);
}

Sign collinear_power_test_sos(const WeightedPoint& a, const WeightedPoint& b,
                              const WeightedPoint& e, std::uint32_t ia, std::uint32_t ib,
                              std::uint32_t ie) {
  const char* where = "collinear_power_test_sos";
  const auto [k, s] = line_axis(a.c, b.c, where);
  const int d = collinear_d2_sign(a, b, e, k);
  if (d != 0) return static_cast<Sign>(d * s);
  RSTRUCT_PREDICATE_COUNT(collinear_power_test, perturbed);
  const auto q = static_cast<std::size_t>(k);
  // Cofactors of the heights of a, b, e in D2.
  const std::array<int, 3> cofactor{compare_doubles(e.c[q], b.c[q]),
                                    compare_doubles(a.c[q], e.c[q]),
                                    compare_doubles(b.c[q], a.c[q])};
  for (const int i : detail::perturbation_order<3>({ia, ib, ie}, where)) {
    const int c = cofactor[static_cast<std::size_t>(i)];
    if (c != 0) return static_cast<Sign>(-c * s);
  }
  throw InternalError("collinear_power_test_sos: no non-zero cofactor although a != b");
}

Sign coincident_power_test_sos(const WeightedPoint& a, const WeightedPoint& e,
                               std::uint32_t ia, std::uint32_t ie) {
  const char* where = "coincident_power_test_sos";
  detail::require_finite(where, {a.w, e.w});
  if (ia == ie) {
    throw InvalidInput(std::string("predicates::") + where + ": equal perturbation ids");
  }
  if (e.w != a.w) return e.w > a.w ? Sign::positive : Sign::negative;
  return ie < ia ? Sign::positive : Sign::negative;
}

}  // namespace rstruct::predicates
