// Lemma A.2 (= Lemma 5.3) of Aichholzer et al. (SGP 2009), corrected (ERRATA E3): with the
// polar-ball radius bound the cited facts give, rho >= (1 - d)/2 (B_q contains a medial-axis
// point [ACK01, Cor. 13]), and d <= 0.0425 lfs(v^) (lemma_a1_corrected.cpp), the exterior
// angle between the polar balls of an alpha-shape edge is >= 110.8 deg (not 120 deg). The
// angle psi = 180 deg - 110.8 deg = 69.2 deg at which the balls may meet feeds Lemma A.3.
#include "chain.hpp"

using namespace rstruct::proofs;

int main() {
  Proof proof("Lemma A.2 corrected (lfs(v^) = 1, r = 0.08)");
  const Interval r = ratio(8, 100);
  const Interval beta0 = 2 * asin_u(2 * r);
  BnbResult m = a2_max_cos(ratio(425, 10000), ratio(1, 2), beta0);
  proof.note("B&B boxes " + std::to_string(m.boxes) + (m.converged ? " (converged)" : ""));
  proof.greater("rho >= (1-d)/2, d <= 0.0425, R_c >= 1 (B&B): exterior angle > 110.8deg",
                to_deg(a2_exterior_angle(m.extremum)), ratio(1108, 10));
  return proof.finish();
}
