// Theorem 6.1 of Aichholzer et al. (SGP 2009) as written: with shrunk balls of radius
// rho~ D^(u), rho~ = 0.03, rho = 0.3, the proof combines |u - t| <= rho~ D^(u) with bound (8)
// of Lemma 5.6, |t - x| <= 0.27 D^(t), into |u - x| <= rho~ D^(u) + (rho - rho~) D^(u). But
// (8) is in units of D^(t), not D^(u), and D^(t) can be as large as D^(u) + |u - t| <=
// (1 + rho~) D^(u) (D^ is 1-Lipschitz). With the paper's 0.27 the step needs
// 0.27 (1 + rho~) <= rho - rho~, which FAILS (0.2781 > 0.27): should_fail, ERRATA E6. The
// conclusion survives with the exact constant of (8) (theorem_6_1_corrected.cpp).
#include "chain.hpp"

using namespace rstruct::proofs;

int main() {
  Proof proof("Theorem 6.1 as written (rho = 0.3, rho~ = 0.03)");
  const Interval rho = ratio(3, 10);
  const Interval rt = ratio(3, 100);
  proof.less("rho~ = 0.03 < rho = 0.3", rt, rho);
  proof.less_eq("|t - x| <= 0.27 D^(t) <= 0.27 (1 + rho~) D^(u) <= (rho - rho~) D^(u)",
                ratio(27, 100) * (1 + rt), rho - rt);
  return proof.finish();
}
