// Lemma A.1 (= Lemma 5.2) of Aichholzer et al. (SGP 2009) with the paper's own constants:
// k = 1.536, 47.2 deg, 12.8 deg, 60 deg, 0.123, 0.0355, 0.0424 at r = 0.08.
// Expected to FAIL (registered should_fail; proofs/ERRATA.md, E1 and E2):
//  - asin(1/(k(1-r))) + asin(r/(1-r)) is 50.03 deg, not < 47.2 deg, and the sum of the true
//    angle bounds is 60.01 deg, not < 60 deg, so k = 1.536 does not close the argument;
//  - the configuration the proof describes (Figure 13) allows dist(v, F) = 0.03560 lfs(s),
//    more than the stated 0.0355.
// The corrected chain (k = 1.537, 0.0357, 0.0425) is lemma_a1_corrected.cpp.
#include "chain.hpp"

using namespace rstruct::proofs;

int main() {
  Proof proof("Lemma A.1 with the paper's constants (lfs(s) = 1, r = 0.08)");
  const Interval r = ratio(8, 100);
  const Interval k = ratio(1536, 1000);
  proof.less_eq("(a) k r <= 0.123", k * r, ratio(123, 1000));
  Interval sv = angle_sv(k, r);
  proof.less("(a) asin(1/(k(1-r))) + asin(r/(1-r)) < 47.2deg [AB99]", to_deg(sv), ratio(472, 10));
  Interval sp = angle_sp(r);
  proof.less("(a) 2 asin(r/(1-r)) < 12.8deg", to_deg(sp), ratio(128, 10));
  proof.less("(a) angle vsp <= angle(sv,n) + angle(n,sp) < 60deg", to_deg(sv + sp), Interval(60));

  BnbResult m = a1b_max_distance(k * r, sp, 400000);
  proof.note("(b) B&B boxes " + std::to_string(m.boxes) +
             (m.converged ? " (converged)" : " (budget)"));
  proof.less_eq("(b) max dist(v, F) over Figure 13's region (B&B) <= 0.0355", m.extremum,
                ratio(355, 10000));
  proof.note("(b) closed form at the extreme point (rho = kr, R = lfs(s), phi = -theta)",
             a1b_closed_form(k * r, sp));
  proof.less_eq("(b) 0.0355 / (1 - 0.123 - 0.0355) <= 0.0424 (Lipschitz)",
                a1b_lipschitz(ratio(123, 1000), ratio(355, 10000)), ratio(424, 10000));
  return proof.finish();
}
