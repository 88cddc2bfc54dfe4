// Lemma 5.6 of Aichholzer et al. (SGP 2009): "rho can be chosen in [0.24, 0.56]" (eq. (1)).
// The paper proves rho = 0.3 only. Running its chain (2)-(8) for a general rho with its own
// constants (0.817, 0.123, 1.2802) and the best multipliers in (8), condition (4)
// rho >= K(rho) fails above rho ~ 0.397; at rho = 0.56, K = 1.34. Expected to FAIL
// (should_fail; ERRATA E5). The true admissible interval is lemma_5_6_corrected.cpp.
#include "chain.hpp"

using namespace rstruct::proofs;

int main() {
  Proof proof("Lemma 5.6 for rho in [0.24, 0.56] (paper's constants)");
  Chain56 ch{ratio(817, 1000), ratio(123, 1000), ratio(12802, 10000)};
  const Interval lo = ratio(24, 100);
  const Interval hi = ratio(56, 100);
  proof.greater_eq("(4) at rho_min = 0.24: rho >= K(rho)", ch.slack4(lo), Interval(0));
  proof.greater_eq("(4) at rho_max = 0.56: rho >= K(rho)", ch.slack4(hi), Interval(0));
  proof.note("K(0.56)", ch.k8(hi));
  BnbResult m = min_over_rho([&](const Interval& x) { return ch.slack4(x); }, 0.24, 0.56);
  proof.greater_eq("(4) for all rho in [0.24, 0.56] (B&B of min rho - K(rho))", m.extremum,
                   Interval(0));
  return proof.finish();
}
