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
    Feasible fe = lo(slack) >= 0  ? Feasible::kAll
                  : hi(slack) < 0 ? Feasible::kNone
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
inline BnbResult a2_max_cos(const Interval& d_max, const Interval& factor, const Interval& beta0) {
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

namespace rstruct::proofs {

/// Lemma 5.6 for a general rho (the paper proves rho = 0.3 only). Fibre v -> m, |m - v| = 1,
/// a surface ball B_s (radius rho D^(s)) entering the fibre at x, xi = |x - v|.
///  (2)  s outside B(m, 1), above x:  |s - x|^2 >= 1 - (1 - xi)^2 and |s-x|/|s-m| >=
///       sqrt(2 xi - xi^2) (minimum at the corner s_0, checked by B&B in lemma_5_6.cpp);
///       with |s - m| >= lfs~(s) >= c55 D^(s) >= (c55/rho) |s - x| this forces
///       xi <= k1(rho) = 1 - sqrt(1 - (rho/c55)^2).
///  (3)  |s - x| / |x - v| >= sqrt(2/k1 - 1) = (1 + sqrt(1 - sigma^2)) / sigma, sigma = rho/c55.
///  (6)  D^(t) >= A |x - v| - |v - t|,  A = ratio3 (1/rho - 1) - 1.
///  (7)  D^(t) >= B |v - t|,  B = 1 / (c5 c51)  (|v - t| <= c5 lfs(t), lfs <= c51 D^).
///  (8)  |x - v| + |v - t| <= K D^(t) with the best multipliers: K = (1 + 1/B)/A + 1/B
///       (the maximum of X + Y subject to A X - Y <= 1, B Y <= 1 -- exact for this chain).
///  (4)  holds iff rho >= K(rho).
struct Chain56 {
  Interval c55;  ///< Corollary 5.5: lfs~(s) >= c55 D^(s)          (paper: 0.817)
  Interval c5;   ///< (5): |v - t| <= c5 lfs(t)                      (paper: 0.123)
  Interval c51;  ///< Lemma 5.1: lfs(s) <= c51 D^(s)                 (paper: 1.2802)

  Interval sigma(const Interval& rho) const { return rho / c55; }
  Interval k1(const Interval& rho) const {
    Interval s = sigma(rho);
    return 1 - sqrt_nonneg(1 - s * s);
  }
  Interval ratio3(const Interval& rho) const {
    Interval s = sigma(rho);
    return (1 + sqrt_nonneg(1 - s * s)) / s;
  }
  Interval a6(const Interval& rho) const { return ratio3(rho) * (1 / rho - 1) - 1; }
  Interval b7() const { return 1 / (c5 * c51); }
  Interval k8(const Interval& rho) const {
    Interval inv_b = c5 * c51;
    return (1 + inv_b) / a6(rho) + inv_b;
  }
  /// rho - K(rho): (4) holds iff > 0 (requires rho < c55 and A > 0).
  Interval slack4(const Interval& rho) const { return rho - k8(rho); }
  /// Theorem 6.1: with D^(t) <= (1 + rho~) D^(u), the pruned union keeps the fibre property
  /// iff K (1 + rho~) <= rho - rho~, i.e. rho~ <= (rho - K)/(1 + K).
  Interval rho_tilde_max(const Interval& rho) const {
    Interval k = k8(rho);
    return (rho - k) / (1 + k);
  }
};

/// A zero of f in [a, b] where f(a), f(b) have opposite signs, by bisection on midpoints (a
/// locator only: the interval it suggests is then certified by B&B).
inline double bisect_root(const std::function<Interval(const Interval&)>& f, double a, double b) {
  bool neg_a = mid_d(f(Interval(a))) < 0;
  for (int i = 0; i < 60; ++i) {
    double m = 0.5 * (a + b);
    if ((mid_d(f(Interval(m))) < 0) == neg_a) {
      a = m;
    } else {
      b = m;
    }
  }
  return 0.5 * (a + b);
}

/// B&B of min over rho in [lo, hi] of f(rho); `f` must be defined on the whole interval.
inline BnbResult min_over_rho(const std::function<Interval(const Interval&)>& f, double lo,
                              double hi) {
  Objective g = [&f](const Box& b) { return Eval{f(b[0]), Feasible::kAll}; };
  return minimize(g, {hull(lo, hi)}, 1e-9, 100000);
}

}  // namespace rstruct::proofs

namespace rstruct::proofs {

/// Lemma A.3 (= 5.4), edge case, our proof (the paper's "the angles are minimised when v lies
/// on the intersection" is not true for all v outside the balls; the bound still holds).
/// Normalise |p - q| = 1, p = (0,0), q = (1,0), v above the axis and nearer to p. If the foot
/// of v on pq is interior, |m - v| / min(|v-p|, |v-q|) >= sin(angle vpq), so a ratio < kappa
/// puts v in the triangle W' = {0 <= x <= 1/2, 0 <= y <= x tan(tau)}, tau = asin(kappa),
/// whose farthest point from p and q is its apex at distance T = 1/(2 cos tau). Balls of
/// radii a0, b0 meeting at angle <= psi (a0^2 + b0^2 - 1 - 2 a0 b0 cos(psi) >= 0, the
/// "admissible" pairs) cover W':
///  (i)  max(a0, b0) > T: then if a0 >= b0, B_p covers W' (every point within T of p);
///  (ii) if a0 < b0 <= ... : B_q covers the apex (b0 > T); the upper boundary of the union
///       crosses the line y = x tan(tau) only if the circles' intersection point v0 lies
///       below it; v0 lies above iff 1 + a0^2 - b0^2 < 2 a0 cos(tau), implied (admissibility)
///       by g = cos(tau) - a0 + b0 cos(psi) > 0 for a0 < b0, a0 <= T. On the B_q arc the
///       line is inside by convexity of (1-x)^2 + x^2 tan^2(tau) between x0 and 1/2.
/// So v outside both balls has ratio >= kappa whenever (i) and (ii) hold, checked below by
/// B&B for given psi, kappa.
struct EdgeCheck {
  BnbResult corner;  ///< max over [0,T]^2 of a0^2 + b0^2 - 1 - 2 a0 b0 cos(psi): < 0 => (i)
  BnbResult g;       ///< min of g over admissible a0 < b0, a0 <= T: > 0 => (ii)
};
inline EdgeCheck a3_edge(const Interval& psi, const Interval& kappa) {
  Interval tau = asin_u(kappa);
  Interval t_apex = 1 / (2 * cos(tau));
  Interval cpsi = cos(psi);
  EdgeCheck out;
  Objective h = [&](const Box& b) {
    return Eval{b[0] * b[0] + b[1] * b[1] - 1 - 2 * b[0] * b[1] * cpsi, Feasible::kAll};
  };
  Box sq{Interval(Real(0), hi(t_apex)), Interval(Real(0), hi(t_apex))};
  out.corner = maximize(h, sq, 1e-9, 100000);
  Interval ctau = cos(tau);
  Objective g = [&](const Box& b) {
    const Interval& a0 = b[0];
    const Interval& b0 = b[1];
    Interval adm = a0 * a0 + b0 * b0 - 1 - 2 * a0 * b0 * cpsi;
    Interval order = b0 - a0;
    Interval sum = a0 + b0 - 1;
    Interval diff = 1 - (b0 - a0);
    bool all = lo(adm) >= 0 && lo(order) >= 0 && lo(sum) >= 0 && lo(diff) >= 0;
    bool none = hi(adm) < 0 || hi(order) < 0 || hi(sum) < 0 || hi(diff) < 0;
    return Eval{ctau - a0 + b0 * cpsi, all    ? Feasible::kAll
                                       : none ? Feasible::kNone
                                              : Feasible::kSome};
  };
  Box region{Interval(Real(0), hi(t_apex)), Interval(Real(0), hi(t_apex) + 1)};
  out.g = minimize(g, region, 1e-9, 200000);
  return out;
}

/// Lemma A.3, triangle case, the paper's extreme configuration: regular pyramid with apex
/// angles psi, height / edge = sqrt((1 + 2 cos psi) / 3). That this configuration is extreme
/// is asserted, not proved, in the paper.
inline Interval a3_triangle(const Interval& psi) { return sqrt_nonneg((1 + 2 * cos(psi)) / 3); }

}  // namespace rstruct::proofs
