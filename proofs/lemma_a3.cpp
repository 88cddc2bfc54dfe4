// Lemma A.3 (= Lemma 5.4, Corollary 5.5) of Aichholzer et al. (SGP 2009) with the paper's
// constants: edge case cos 30 deg > 0.866, triangle case sqrt((1 + 2 cos 60deg)/3) > 0.817,
// from the 120 deg of Lemma A.2 (pair angle psi <= 60 deg).
// Expected to FAIL (should_fail; ERRATA E4): sqrt(2/3) = 0.81650 < 0.817. The edge case
// HOLDS, and is proved here by B&B for every pair of admissible balls (chain.hpp, a3_edge),
// because the paper's reduction to v on the intersection circle is not valid in general.
// The triangle case's extreme configuration (regular pyramid) is asserted, not proved, by
// the paper; it is only evaluated here.
#include "chain.hpp"

using namespace rstruct::proofs;

int main() {
  Proof proof("Lemma A.3 with the paper's constants (psi = 60 deg)");
  const Interval psi = deg(60);
  const Interval kappa = ratio(866, 1000);
  proof.greater("edge: cos 30deg > 0.866", cos(psi / 2), kappa);
  EdgeCheck e = a3_edge(psi, kappa);
  proof.less(
      "edge (i): max(a0, b0) > T for admissible balls (B&B max of the constraint "
      "on [0,T]^2 < 0)",
      e.corner.extremum, Interval(0));
  proof.greater("edge (ii): g = cos(tau) - a0 + b0 cos(psi) > 0 on admissible a0 < b0 (B&B)",
                e.g.extremum, Interval(0));
  proof.greater("triangle: sqrt((1 + 2 cos 60deg)/3) > 0.817", a3_triangle(psi), ratio(817, 1000));
  proof.less_eq("1 / 0.817 <= 1.224 (used in Lemma 5.6 (b))", 1 / ratio(817, 1000),
                ratio(1224, 1000));
  return proof.finish();
}
