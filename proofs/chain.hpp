// Derivations shared by the programs that check the paper's numbers and the programs that
// check the corrected chain (proofs/ERRATA.md). Each function is one step of the paper's
// argument with its inputs as parameters, so a corrected constant can be fed through.
#pragma once

#include "interval.hpp"

namespace rstruct::proofs {

/// [AB99]: angle at s between sv and the normal, for v in Vor(s) with |v - s| >= k r lfs(s):
/// asin(1/(k(1-r))) + asin(r/(1-r)) (imported fact, quoted by Lemma A.1).
inline Interval angle_sv(const Interval& k, const Interval& r) {
  return asin_u(1 / (k * (1 - r))) + asin_u(r / (1 - r));
}
/// [AB99]: angle between the pole vector sp and the normal at s: 2 asin(r/(1-r)).
inline Interval angle_sp(const Interval& r) { return 2 * asin_u(r / (1 - r)); }

/// Lemma A.1(b), the configuration of the paper's Figure 13, lfs(s) = 1, s at the origin,
/// normal n = (0, 1) pointing to the side of v and p. v = rho (sin alpha, cos alpha) with
/// rho <= a (part (a)), outside the polar ball B_p = B(R (sin phi, cos phi), R) with
/// R >= lfs(s) = 1 (w = 1/R in [0, 1]) and |phi| <= theta ([AB99], angle_sp). F separates v
/// from the opposite medial ball, which contains the unit ball tangent at s on the other side,
/// so dist(v, F) <= |v - (0, -1)| - 1 = sqrt(rho^2 + 2 rho cos(alpha) + 1) - 1.
/// Returns the B&B maximum of that bound over the whole admissible region (a 2D section
/// suffices: the bound depends only on |v| and v.n, and the feasible heights are the same).
/// The B&B is seeded with the extreme point of a1b_closed_form (a feasible configuration:
/// v on the sphere of B_p), so the enclosure's lower end is attained.
inline Interval a1b_closed_form(const Interval& a, const Interval& theta);
inline BnbResult a1b_max_distance(const Interval& a, const Interval& theta, long budget) {
  Objective f = [](const Box& b) {
    const Interval& rho = b[0];
    const Interval& alpha = b[1];
    const Interval& phi = b[2];
    const Interval& w = b[3];
    // v outside B_p <=> rho^2 - 2 R rho cos(alpha - phi) >= 0 <=> rho w >= 2 cos(alpha - phi)
    Interval slack = rho * w - 2 * cos(alpha - phi);
    Feasible fe = lo(slack) >= 0 ? Feasible::kAll : hi(slack) < 0 ? Feasible::kNone
                                                                  : Feasible::kSome;
    return Eval{sqrt_nonneg(rho * rho + 2 * rho * cos(alpha) + 1) - 1, fe};
  };
  Box box{Interval(Real(0), hi(a)), Interval(Real(0), hi(pi())), Interval(-hi(theta), hi(theta)),
          hull(0, 1)};
  Interval witness = a1b_closed_form(a, theta);
  return maximize(f, box, 1e-7, budget, {}, &witness);
}

/// Closed form of the same maximum (rho = a, R = 1, phi = -theta):
/// sqrt(a^2 + 2 a cos(acos(a/2) - theta) + 1) - 1.
inline Interval a1b_closed_form(const Interval& a, const Interval& theta) {
  return sqrt_nonneg(a * a + 2 * a * cos(acos_u(a / 2) - theta) + 1) - 1;
}

/// Lemma A.1(b), last step: dist <= c lfs(s) and |s - v| <= a lfs(s) give, by the Lipschitz
/// condition lfs(s) <= lfs(v^) + |s - v^|, dist <= c / (1 - a - c) lfs(v^).
inline Interval a1b_lipschitz(const Interval& a, const Interval& c) { return c / (1 - a - c); }

}  // namespace rstruct::proofs

namespace rstruct::proofs {

/// Lemma A.2 (= 5.3), the paper's Figure 14 with lfs(v^) = 1. v lies on the sphere of a polar
/// ball B_q (radius rho), at distance d from its nearest surface point v^; the medial ball D
/// of v^ on the other side has centre c on the normal line, radius R_c >= 1, so
/// |c - v| = R_c + d. [ACK01, Lemma 17] (imported): B_q and D meet at an angle <= beta0, i.e.
/// |c - q|^2 >= rho^2 + R_c^2 + 2 rho R_c cos(beta0). The deviation phi of B_q's normal at v
/// from the surface normal is pi - angle(c v q), largest when |c - q| is smallest:
/// cos(angle cvq) <= C = (2 d + d^2 w - 2 rho cos(beta0)) / (2 rho (1 + d w)), w = 1/R_c.
/// The exterior angle between two such balls is >= pi - 2 phi = 2 acos(C) - pi.
inline Interval a2_cos_bound(const Interval& d, const Interval& w, const Interval& rho,
                             const Interval& beta0) {
  return (2 * d + d * d * w - 2 * rho * cos(beta0)) / (2 * rho * (1 + d * w));
}
inline Interval a2_exterior_angle(const Interval& c) { return 2 * acos_u(c) - pi(); }

/// min over d in [0, d_max], R_c >= 1, rho >= (1 - d) * factor of the exterior angle (B&B;
/// rho = (1 - d) factor / u with u in (0, 1]). Seeded with the point d = d_max, R_c = 1,
/// rho = (1 - d_max) factor. Returns the enclosure of the maximal cosine C.
inline BnbResult a2_max_cos(const Interval& d_max, const Interval& factor,
                            const Interval& beta0) {
  Objective f = [&](const Box& b) {
    // a2_cos_bound with 1/rho = u / ((1 - d) factor), written so each variable occurs few
    // times (less interval over-estimation).
    const Interval& d = b[0];
    const Interval& w = b[1];
    const Interval& u = b[2];
    Interval one_dw = 1 + d * w;
    return Eval{(2 * d + d * d * w) * u / (2 * (1 - d) * factor * one_dw) - cos(beta0) / one_dw,
                Feasible::kAll};
  };
  Interval witness = a2_cos_bound(d_max, Interval(1), (1 - d_max) * factor, beta0);
  Box box{Interval(Real(0), hi(d_max)), hull(0, 1), hull(0, 1)};
  return maximize(f, box, 1e-10, 200000, {}, &witness);
}

}  // namespace rstruct::proofs
