// Lemma A.3 (= Lemma 5.4, Corollary 5.5) of Aichholzer et al. (SGP 2009), corrected
// (ERRATA E4, E3):
//  (A) accepting Lemma A.2's 120 deg: edge 0.866, triangle sqrt(2/3) > 0.8164 (so
//      Corollary 5.5 holds with 0.8164 instead of 0.817; 1/0.8164 <= 1.2249);
//  (B) with Lemma A.2 corrected to 110.8 deg (psi <= 69.2 deg): edge 0.823 (proved by B&B),
//      triangle 0.7550 (the paper's extreme configuration, not proved).
#include "chain.hpp"

using namespace rstruct::proofs;

int main() {
  Proof proof("Lemma A.3 corrected");
  const Interval psi_a = deg(60);
  proof.greater("(A) triangle: sqrt((1 + 2 cos 60deg)/3) > 0.8164", a3_triangle(psi_a),
                ratio(8164, 10000));
  proof.less_eq("(A) 1 / 0.8164 <= 1.2249", 1 / ratio(8164, 10000), ratio(12249, 10000));
  const Interval psi_b = deg(180) - deg(ratio(1108, 10));
  const Interval kappa_b = ratio(823, 1000);
  proof.greater("(B) edge: cos(psi/2) > 0.823, psi = 180 - 110.8 deg", cos(psi_b / 2), kappa_b);
  EdgeCheck e = a3_edge(psi_b, kappa_b);
  proof.less("(B) edge (i): max(a0, b0) > T (B&B)", e.corner.extremum, Interval(0));
  proof.greater("(B) edge (ii): g > 0 on admissible a0 < b0 (B&B)", e.g.extremum, Interval(0));
  proof.greater("(B) triangle: sqrt((1 + 2 cos psi)/3) > 0.7550", a3_triangle(psi_b),
                ratio(7550, 10000));
  return proof.finish();
}
