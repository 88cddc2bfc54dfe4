// Lemma A.2 (= Lemma 5.3) of Aichholzer et al. (SGP 2009): two polar balls whose centres
// span an edge of the weighted alpha-shape meet at an exterior angle >= 120 deg, r = 0.08.
// This program checks the paper's derivation as written: polar-ball radius |q - v| = 1 - d
// (lfs(v^) = 1), medial-ball radius 1, beta = 2 asin(2r), d = 0.0355 -- and the same
// derivation over everything its constraints (i)-(iii) allow (d <= 0.0424, R_c >= 1,
// radius >= 1 - d), by branch-and-bound. Both HOLD. The radius assumption |q - v| >= 1 - d
// is not justified in the paper ("using the triangle inequality"); what it rests on is
// checked in lemma_a2_radius.cpp (ERRATA E3).
#include "chain.hpp"

using namespace rstruct::proofs;

int main() {
  Proof proof("Lemma A.2 as derived in the paper (lfs(v^) = 1, r = 0.08)");
  const Interval r = ratio(8, 100);
  const Interval beta0 = 2 * asin_u(2 * r);
  proof.note("beta0 = 2 asin(2r) in degrees [ACK01, Lemma 17]", to_deg(beta0));
  const Interval d1 = ratio(355, 10000);
  Interval c1 = a2_cos_bound(d1, Interval(1), 1 - d1, beta0);
  proof.greater("paper's point (d = 0.0355, R_c = 1, rho = 1-d): exterior angle > 120deg",
                to_deg(a2_exterior_angle(c1)), Interval(120));
  const Interval d2 = ratio(424, 10000);
  Interval c2 = a2_cos_bound(d2, Interval(1), 1 - d2, beta0);
  proof.greater("with the lemma's own bound d = 0.0424: exterior angle > 120deg",
                to_deg(a2_exterior_angle(c2)), Interval(120));
  BnbResult m = a2_max_cos(d2, Interval(1), beta0);
  proof.note("B&B boxes " + std::to_string(m.boxes) + (m.converged ? " (converged)" : ""));
  proof.greater("min over d <= 0.0424, R_c >= 1, rho >= 1 - d (B&B): exterior > 120deg",
                to_deg(a2_exterior_angle(m.extremum)), Interval(120));
  return proof.finish();
}
