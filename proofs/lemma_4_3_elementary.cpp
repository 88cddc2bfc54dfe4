// Lemma 4.3a of Aichholzer et al. (SGP 2009) -- whose proof the paper omits -- by an
// elementary argument of ours, certified by branch-and-bound. It gives a much weaker angle
// than the paper's 14.99 deg, so it does not replace Lemma 4.3; it bounds what is known
// without the omitted proof (README.md, ERRATA E7).
//
// Setting: x in F inside a polar ball B_p (centre p, radius R), lfs(x) = 1, gamma = angle
// between p - x and the inward normal at x, D = |p - x| = R - delta (delta >= 0), w = 1/R in
// [0, 2] (B_p contains a medial-axis point [ACK01, Cor. 13], so lfs(x) <= 2R), and
// D >= c(0.08) R (Lemma 4.2).
//  * Sample constraint, at any y in F (our derivation): a sample t with |t - y| <= r lfs(y)
//    lies outside B_p and outside the two tangent balls of radius lfs(y) at y, so
//    |t - y| = |w'|, |w'.n_y| <= |w'|^2 / (2 lfs(y)) and
//    R^2 <= |t - p|^2 <= D_y^2 + 2 r l_y D_y sin(gamma_y) + r^2 l_y D_y + r^2 l_y^2.
//  * Lens: for |u| < 1, F has a point y = x + u e + h n with |h| <= 1 - sqrt(1 - u^2) (the
//    segment between the two tangent balls at x joins inside and outside of F); e is the
//    tangent direction towards p. lfs(y) <= 1 + |y - x|.
//  * x itself: the same constraint with its own angle; and gamma > 90 deg is impossible
//    beyond ~92.5 deg (see `back` below).
//  * Bootstrap: let G be the supremum of gamma over all such configurations; pick x with
//    gamma > G - eps. Using sin(gamma_y) <= sin(min(gamma + eps, 90 deg)) at the lens points
//    y(u), the constraint at some y(u) is violated for every gamma >= G1 - eps: so G < G1.
//  * Second pass: with sin(gamma_y) <= sin(G1) everywhere, for x with lfs(x) <= R (w <= 1,
//    the case of Lemma 5.1 / Theorem 4.1, where a medial ball of radius R_p touches x):
//    gamma < G2.
#include "chain.hpp"

using namespace rstruct::proofs;

namespace {

const Interval kR = ratio(8, 100);

/// Lower bound of (R^2 - D_y^2)/R - (right side)/R at the lens point y(u), over the box
/// (gamma, w, delta); > 0 means the sample constraint at y(u) is violated.
Interval violation(const Interval& u, const Interval& g, const Interval& w, const Interval& d,
                   const Interval& s) {
  Interval h = 1 - sqrt_nonneg(1 - u * u);
  Interval t = u * sin(g) - h * abs(cos(g));
  Interval dw = 1 - d * w;
  Interval uh = u * u + h * h;
  Interval rho_y = sqrt_nonneg(dw * dw - 2 * w * dw * t + w * w * uh);
  Interval l = 1 + sqrt_nonneg(uh);
  return d * (2 - d * w) + 2 * dw * t - w * uh - kR * l * (2 * rho_y * s + kR * rho_y + kR * l * w);
}

/// Objective over boxes (gamma, w, delta): max over the lens points u of the violation;
/// infeasible where the constraint at x itself or Lemma 4.2 fails. `s_of` gives an upper
/// bound of sin(gamma_y) for the box.
Objective refutation(std::function<Interval(const Interval&)> s_of) {
  Interval c42 = sqrt_nonneg(1 - 4 * (kR * kR - kR * kR * kR * kR / 4)) - kR * kR;
  return [s_of, c42](const Box& b) {
    const Interval& g = b[0];
    const Interval& w = b[1];
    const Interval& d = b[2];
    Interval s = s_of(g);
    Interval dw = 1 - d * w;
    // Sample constraint at x itself, with x's own angle.
    Interval at_x = kR * (2 * dw * sin(g) + kR * dw * abs(cos(g)) + kR * w) - d * (2 - d * w);
    Interval l42 = (1 - c42) - d * w;
    // gamma > 90deg: the segment x -> p starts into the open outer tangent ball (empty of F,
    // outside O) for a length 2|cos gamma|, and p is inside O, so F meets it again at z with
    // |x - z| >= 2|cos gamma|; z is deeper than x by |x - z| and needs a sample outside B_p
    // within r lfs(z) <= r (1 + |x - z|):  |x - z| <= (r - delta)/(1 - r).
    Interval cneg =
        Interval(lo(cos(g)) < 0 ? lo(cos(g)) : Real(0), hi(cos(g)) < 0 ? hi(cos(g)) : Real(0));
    Interval back = (kR - d) / (1 - kR) + 2 * cneg;
    bool none = hi(at_x) < 0 || hi(l42) < 0 || hi(back) < 0;
    bool all = lo(at_x) >= 0 && lo(l42) >= 0 && lo(back) >= 0;
    Feasible fe = none ? Feasible::kNone : all ? Feasible::kAll : Feasible::kSome;
    Interval best = Interval(-1000);
    for (int k = 1; k <= 24; ++k) {
      Interval v = violation(ratio(k, 40), g, w, d, s);
      if (lo(v) > lo(best)) best = Interval(lo(v), hi(v) > hi(best) ? hi(v) : hi(best));
    }
    return Eval{best, fe};
  };
}

}  // namespace

int main() {
  Proof proof("Lemma 4.3a by an elementary argument (ours), r = 0.08, lfs(x) = 1");
  const double eps = 1e-6;
  const Interval g1 = deg(ratio(365, 10));
  auto s_boot = [eps](const Interval& g) {
    Interval a = Interval(hi(g)) + eps;
    return hi(a) >= hi(pi() / 2) ? Interval(1) : Interval(hi(sin(a)));
  };
  BnbResult p1 =
      minimize(refutation(s_boot), {Interval(lo(g1) - eps, hi(pi())), hull(0, 2), hull(0, 0.15)},
               1e-9, 400000, {1.0, 2.0, 0.15}, nullptr, 0.0);
  proof.note("pass 1: B&B boxes " + std::to_string(p1.boxes));
  proof.greater(
      "pass 1: every configuration with gamma >= 36.5deg - eps is refuted "
      "(min over the box of the best violation > 0)  =>  gamma < 36.5deg",
      p1.extremum, Interval(0));
  const Interval s1 = sin(g1);
  const Interval g2 = deg(ratio(297, 10));
  BnbResult p2 = minimize(refutation([s1](const Interval&) { return s1; }),
                          {Interval(lo(g2), hi(pi())), hull(0, 1), hull(0, 0.15)}, 1e-9, 400000,
                          {1.0, 1.0, 0.15}, nullptr, 0.0);
  proof.note("pass 2: B&B boxes " + std::to_string(p2.boxes));
  proof.greater(
      "pass 2 (lfs(x) <= R_p, Lemma 5.1's case): gamma >= 29.7deg refuted  =>  "
      "gamma < 29.7deg",
      p2.extremum, Interval(0));
  proof.note("compare: the paper's 14.99deg; Lemma 5.1 needs <= 16.107deg");
  // Lemma 4.3b by the same constraint at x: delta (2 - delta w) <= r (2 (1 - delta w) sin(g)
  // + r (1 - delta w) + r w) with sin(g) <= sin(36.5deg), w in [0, 2] (lfs(x) = 1).
  Objective depth = [s1](const Box& b) {
    const Interval& w = b[0];
    const Interval& d = b[1];
    Interval dw = 1 - d * w;
    Interval at_x = kR * (2 * dw * s1 + kR * dw + kR * w) - d * (2 - d * w);
    Feasible fe = hi(at_x) < 0 ? Feasible::kNone : lo(at_x) >= 0 ? Feasible::kAll : Feasible::kSome;
    return Eval{d, fe};
  };
  BnbResult pd = maximize(depth, {hull(0, 2), hull(0, 0.15)}, 1e-7, 200000);
  proof.less("(b) penetration of x into B_p < 0.058 lfs(x) (B&B; the paper: 0.0114)", pd.extremum,
             ratio(58, 1000));
  proof.note("Lemma 5.6 (5) case (b) with it: 0.058 (1 + r) + r", ratio(58, 1000) * (1 + kR) + kR);
  Interval c51 = 1 + 2 * sin(g2 / 2);
  proof.note("Lemma 5.1 with gamma < 29.7deg: lfs(s) <= (1 + 2 sin(gamma/2)) D^(s)", c51);
  return proof.finish();
}
