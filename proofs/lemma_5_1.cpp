// Lemma 5.1 of Aichholzer et al. (SGP 2009): lfs(s) <= 1.2802 D^(s) for r <= 0.08, with the
// constants 14.99 deg (from Lemma 4.3a), 0.2802, 0.0193, and the surface-ball radius lower
// bound rho >= r/(1-r) * 1.2802 (Section 5.2.1).
//
// Case (2a) (paper's Figure 6): m_x is the centre of a medial ball of radius R_p = 1 tangent
// to F at x in K_1, p lies on a ray from x at angle gamma <= 14.99 deg from x m_x, at distance
// d = |x - p| in [c(0.08), 1] (Lemma 4.2; x lies in B_p). Exactly, by the law of cosines,
// |p - m_x|^2 = d^2 + 1 - 2 d cos(gamma); the paper bounds it by the triangle inequality
// 2 sin(gamma/2) + (1 - d). Case (2b): |p - m| <= 1 - c(0.08). Then
// lfs(s) <= |s - p| + |p - m| <= D^(s) + 0.2802 R_p <= 1.2802 D^(s) since R_p <= |s - p|.
//
// The 14.99 deg is imported from Lemma 4.3a, whose proof the paper omits (see
// lemma_4_3.cpp); this program also prints how large that angle may be for 0.2802 to hold.
#include "interval.hpp"

using namespace rstruct::proofs;

namespace {

Interval c42(const Interval& r) {
  Interval r2 = r * r;
  return sqrt_nonneg(1 - 4 * (r2 - r2 * r2 / 4)) - r2;
}

/// max over d in [c, 1], gamma in [0, g] of |p - m_x| (B&B).
BnbResult max_distance(const Interval& c, const Interval& g) {
  Objective f = [](const Box& b) {
    const Interval& d = b[0];
    return Eval{sqrt_nonneg(d * d + 1 - 2 * d * cos(b[1])), Feasible::kAll};
  };
  return maximize(f, {hull(lo_d(c), 1.0), Interval(Real(0), hi(g))}, 1e-9, 200000);
}

}  // namespace

int main() {
  Proof proof("Lemma 5.1: lfs(s) <= 1.2802 D^(s) (R_p = 1)");
  const Interval r = ratio(8, 100);
  const Interval gamma = deg(ratio(1499, 100));
  const Interval c = c42(r);
  const Interval k2802 = ratio(2802, 10000);

  proof.less("case 2a, paper: 2 sin(14.99deg/2) + (1 - 0.9807) < 0.2802",
             2 * sin(gamma / 2) + (1 - ratio(9807, 10000)), k2802);
  BnbResult m = max_distance(c, gamma);
  proof.less("case 2a, exact: max |p - m_x| over d in [c(r),1], gamma <= 14.99deg (B&B)",
             m.extremum, k2802);
  proof.less("case 2b: 1 - c(0.08) < 0.0193", 1 - c, ratio(193, 10000));
  proof.less(
      "case 2b's 0.0193 < case 2a's 0.2802, so lfs(s) <= D^(s) + 0.2802 R_p "
      "<= 1.2802 D^(s) (R_p <= |s - p| = D^(s))",
      ratio(193, 10000), k2802);

  // Slack in the imported angle: largest gamma with max distance 2 sin(gamma/2) <= 0.2802
  // (the maximum over d is at d = 1 because cos(gamma) < c(0.08) for these angles).
  Interval g_star = 2 * asin_u(k2802 / 2);
  proof.note("largest gamma keeping 0.2802 (deg) = 2 asin(0.1401)", to_deg(g_star));
  Interval g161 = deg(ratio(161, 10));
  proof.less("cos(16.1deg) < c(0.08): on [c,1] the distance grows with d", cos(g161), c);
  proof.less("exact max |p - m_x| for gamma <= 16.1deg (B&B) < 0.2802",
             max_distance(c, g161).extremum, k2802);

  // Surface-ball radius lower bound (Section 5.2.1). [AB99]: x in Vor(s) n F has
  // |x - s| <= r lfs(x) <= r (lfs(s) + |x - s|), so |x - s| <= r/(1-r) lfs(s).
  Interval cover = r / (1 - r);
  proof.note("r/(1-r) at r = 0.08", cover);
  Interval rho_low = cover * ratio(12802, 10000);
  proof.less("radius lower bound r/(1-r) * 1.2802 < rho_min = 0.24", rho_low, ratio(24, 100));
  proof.note("r/(1-r) * 1.2802 at r = 0.08 (smallest rho covering F by this argument)", rho_low);
  return proof.finish();
}
