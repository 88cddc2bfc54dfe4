// Lemma A.2 (= Lemma 5.3) of Aichholzer et al. (SGP 2009): the 120 deg bound needs the
// polar-ball radius |q - v| >= 1 - d (lfs(v^) = 1), which the paper asserts "by the triangle
// inequality". What the cited facts give: B_q contains a point m of the medial axis
// [ACK01, Cor. 13], so 1 = lfs(v^) <= |v^ - m| <= d + 2 rho, i.e. rho >= (1 - d)/2. With
// that radius bound the same derivation gives only ~115 deg: expected to FAIL
// (should_fail; ERRATA E3). Using Theorem 4.1's quantitative form (Lemma 5.1: the pole is
// within 0.2802 rho of the medial axis, itself resting on the unproven Lemma 4.3a),
// rho >= (1 - d)/1.2802, which is also printed.
#include "chain.hpp"

using namespace rstruct::proofs;

int main() {
  Proof proof("Lemma A.2 with the radius bound the cited facts give (lfs(v^) = 1, r = 0.08)");
  const Interval r = ratio(8, 100);
  const Interval beta0 = 2 * asin_u(2 * r);
  const Interval d = ratio(424, 10000);
  BnbResult half = a2_max_cos(d, ratio(1, 2), beta0);
  proof.greater("rho >= (1-d)/2, d <= 0.0424 (B&B): exterior angle > 120deg",
                to_deg(a2_exterior_angle(half.extremum)), Interval(120));
  BnbResult lfs = a2_max_cos(d, 1 / ratio(12802, 10000), beta0);
  proof.note(
      "rho >= (1-d)/1.2802 (conditional on Lemma 4.3a), d <= 0.0424: min exterior "
      "angle (deg)",
      to_deg(a2_exterior_angle(lfs.extremum)));
  BnbResult lfs355 = a2_max_cos(ratio(355, 10000), 1 / ratio(12802, 10000), beta0);
  proof.note("rho >= (1-d)/1.2802, d <= 0.0355: min exterior angle (deg)",
             to_deg(a2_exterior_angle(lfs355.extremum)));
  return proof.finish();
}
