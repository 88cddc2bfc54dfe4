// Lemma 4.3 of Aichholzer et al. (SGP 2009). For a surface point x inside a polar ball B_p:
// (a) the angle between xp and the normal at x is <= 3r + O(r^2), used as 14.99 deg at
//     r = 0.08 in Lemma 5.1;
// (b) the penetration of x into B_p is <= 3/2 lfs(x) (r^2 + O(r^3)), used as 0.0114 lfs at
//     r = 0.08 in Lemma 5.6.
// The paper omits the proof ("for lack of space"), so neither constant can be checked
// against a derivation. This program checks what can be checked: that the stated numbers are
// consistent with the stated leading terms, and which closed forms reproduce them. The
// verdict in README.md is therefore UNPROVEN, not HOLDS. What we can certify instead (a much
// weaker angle) is lemma_4_3_elementary.cpp.
#include "interval.hpp"

using namespace rstruct::proofs;

int main() {
  Proof proof("Lemma 4.3 (proof omitted in the paper): consistency of 14.99 deg and 0.0114");
  const Interval r = ratio(8, 100);
  const Interval a = deg(ratio(1499, 100));

  proof.less("(a) leading term 3r (rad) < 14.99deg", 3 * r, a);
  proof.note("(a) room left for the O(r^2) term, in units of r^2", (a - 3 * r) / (r * r));
  Interval ab = asin_u(r / (1 - r));
  proof.less(
      "(a) candidate closed form 3 asin(r/(1-r)) < 14.99deg "
      "(= angle(n_s, sp) <= 2 asin(r/(1-r)) [AB99] + one more asin(r/(1-r)))",
      3 * ab, a);
  proof.note("(a) 3 asin(r/(1-r)) in degrees", to_deg(3 * ab));

  const Interval b = ratio(114, 10000);
  proof.less("(b) leading term 3/2 r^2 < 0.0114", 3 * r * r / 2, b);
  proof.note("(b) room left for the O(r^3) term, in units of r^3",
             (b - 3 * r * r / 2) / (r * r * r));
  proof.less("(b) candidate closed form 3/2 r^2/(1-r)^2 < 0.0114",
             3 * r * r / (2 * (1 - r) * (1 - r)), b);
  return proof.finish();
}
