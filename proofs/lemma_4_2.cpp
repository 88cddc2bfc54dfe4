// Lemma 4.2 of Aichholzer et al., "Recovering Structure from r-Sampled Objects" (SGP 2009):
// the surface F stays farther than R_p (sqrt(1 - 4(r^2 - r^4/4)) - r^2) from a pole p, which
// is > 0.9807 R_p at r = 0.08, and the bound is >= R_p (1 - 3r^2 - O(r^4)).
//
// Configuration (paper's Figure 4, re-derived here): x is the point of F nearest to p,
// d = |x - p| <= R_p; B_T is the empty tangent ball at x on the far side, radius l = lfs(x),
// centre c on the ray p -> x. A sample t lies within r l of x, outside B_p and B_T. The part
// of B(x, r l) outside B_p u B_T is non-empty iff the circle C = dB_p n dB_T is within r l of
// x; in the plane of p, x, c: dist(x, C)^2 = l (R_p^2 - d^2) / (d + l). Solving
// l (R^2 - d^2)/(d + l) <= r^2 l^2 for d gives exactly the paper's root
// d >= sqrt(R^2 - l^2 (r^2 - r^4/4)) - r^2 l / 2, decreasing in l; l <= 2 R_p because B_p
// contains a point of the inner medial axis [ACK01, Cor. 13] (imported fact).
#include "interval.hpp"

using namespace rstruct::proofs;

namespace {

/// The paper's closed form c(r) = sqrt(1 - 4(r^2 - r^4/4)) - r^2.
Interval closed_form(const Interval& r) {
  Interval r2 = r * r;
  return sqrt_nonneg(1 - 4 * (r2 - r2 * r2 / 4)) - r2;
}

/// The root d(l) for R_p = 1.
Interval root(const Interval& r, const Interval& l) {
  Interval r2 = r * r;
  return sqrt_nonneg(1 - l * l * (r2 - r2 * r2 / 4)) - r2 * l / 2;
}

}  // namespace

int main() {
  Proof proof("Lemma 4.2: distance from a pole to F (R_p = 1)");
  const Interval r = ratio(8, 100);
  const Interval c = closed_form(r);
  proof.greater("c(0.08) = sqrt(1-4(r^2-r^4/4)) - r^2 > 0.9807", c, ratio(9807, 10000));

  // The derivation, not only its end formula: minimise d over all configurations (d, l) with
  // d in [0, 1], l in (0, 2] that leave room for the sample t, i.e.
  // l (1 - d^2) / (d + l) <= r^2 l^2  <=>  (1 - d^2) <= r^2 l (d + l).
  Objective g = [&](const Box& b) {
    const Interval& d = b[0];
    const Interval& l = b[1];
    Interval slack = r * r * l * (d + l) - (1 - d * d);  // >= 0 on feasible points
    Feasible f = lo(slack) >= 0  ? Feasible::kAll
                 : hi(slack) < 0 ? Feasible::kNone
                                 : Feasible::kSome;
    return Eval{d, f};
  };
  BnbResult m = minimize(g, {hull(0, 1), hull(0, 2)}, 1e-9, 400000);
  proof.note("B&B boxes " + std::to_string(m.boxes) + ", minimiser (d, l) = (" +
             std::to_string(m.point.at(0)) + ", " + std::to_string(m.point.at(1)) + ")");
  proof.greater("min d over admissible configurations (B&B) > 0.9807", m.extremum,
                ratio(9807, 10000));
  proof.less_eq("B&B minimum agrees with the closed form (min d - c(0.08) <= 1e-8)", m.extremum - c,
                ratio(1, 100000000));

  // Monotonicity used by the paper (worst case l = 2R_p): d(l) decreasing on (0, 2].
  Objective slope = [&](const Box& b) {
    // d'(l) = -l (r^2 - r^4/4) / sqrt(1 - l^2 (r^2 - r^4/4)) - r^2 / 2
    Interval r2 = r * r;
    Interval q = r2 - r2 * r2 / 4;
    return Eval{-b[0] * q / sqrt_nonneg(1 - b[0] * b[0] * q) - r2 / 2, Feasible::kAll};
  };
  BnbResult s = maximize(slope, {hull(0, 2)}, 1e-6, 20000);
  proof.less("max over l in [0,2] of d'(l) < 0 (worst case is l = 2 R_p)", s.extremum, Interval(0));
  proof.less_eq("|d(l = 2) - c(0.08)| <= 1e-60 (the paper's worst case is this root)",
                abs(root(r, Interval(2)) - c), pow(Interval(10), -60));

  // Asymptotics: c(r) >= 1 - 3r^2 - 2r^4 for r in (0, 0.08]. Equivalent (both sides >= 0)
  // to (1 - 4r^2 + r^4) >= (1 - 2r^2 - 2r^4)^2, i.e. 1 - 8 r^2 - 4 r^4 >= 0.
  Objective poly = [](const Box& b) {
    Interval r2 = b[0] * b[0];
    return Eval{1 - 8 * r2 - 4 * r2 * r2, Feasible::kAll};
  };
  BnbResult p = minimize(poly, {hull(0, 0.08)}, 1e-9, 1000);
  proof.greater("min over r in (0,0.08] of 1 - 8r^2 - 4r^4 > 0  =>  c(r) >= 1-3r^2-2r^4",
                p.extremum, Interval(0));
  Objective rhs = [](const Box& b) {
    Interval r2 = b[0] * b[0];
    return Eval{1 - 2 * r2 - 2 * r2 * r2, Feasible::kAll};
  };
  proof.greater("min over r in (0,0.08] of 1 - 2r^2 - 2r^4 > 0 (squaring is valid)",
                minimize(rhs, {hull(0, 0.08)}, 1e-9, 1000).extremum, Interval(0));
  proof.greater("c(0.08) >= 1 - 3r^2 - 2r^4 at r = 0.08 (direct)", c,
                1 - 3 * r * r - 2 * r * r * r * r);

  // Values of the general formula for the property tests (issue 9: "the general formula for
  // the drawn r").
  for (int k : {1, 2, 4, 5, 6, 7, 8}) {
    proof.note("c(" + std::to_string(k) + "/100)", closed_form(ratio(k, 100)));
  }
  return proof.finish();
}
