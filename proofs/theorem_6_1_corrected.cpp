// Theorem 6.1 of Aichholzer et al. (SGP 2009), corrected (ERRATA E6): the pruned union
// keeps the fibre property iff K(rho) (1 + rho~) <= rho - rho~, K the exact constant of
// Lemma 5.6's bound (8) (Chain56 in chain.hpp).
//  (A) Corollary 5.5 = 0.8164 (E4): rho = 0.3, rho~ = 0.03 holds (the theorem survives);
//      rho~ = 0.03 is valid exactly for rho in [0.2815, 0.3272]; the best rho~ is 0.0315.
//  (B) Corollary 5.5 = 0.7550 (E3 too): no rho admits rho~ = 0.03; the best is 0.0236.
#include <cmath>

#include "chain.hpp"

using namespace rstruct::proofs;

namespace {

/// Largest rho~ over rho in [0.2, 0.39] (B&B), with its maximiser.
BnbResult best_rho_tilde(const Chain56& ch) {
  Objective f = [&](const Box& b) { return Eval{ch.rho_tilde_max(b[0]), Feasible::kAll}; };
  return maximize(f, {hull(0.2, 0.39)}, 1e-8, 20000);
}

/// Certified range of rho on which rho~ = 0.03 is valid (located by bisection, rounded
/// inward to 4 decimals, certified by B&B, shown tight to 1e-3).
void range(Proof& proof, const std::string& name, const Chain56& ch, const Interval& rt) {
  auto slack = [&](const Interval& x) { return x - rt - (1 + rt) * ch.k8(x); };
  double lo = std::ceil(bisect_root(slack, 0.2, 0.3) * 1e4) / 1e4;
  double hi = std::floor(bisect_root(slack, 0.3, 0.39) * 1e4) / 1e4;
  BnbResult m = min_over_rho(slack, lo, hi);
  proof.greater(name + ": rho~ = 0.03 valid for all rho in [" + std::to_string(lo) + ", " +
                    std::to_string(hi) + "] (B&B)",
                m.extremum, Interval(0));
  proof.less(name + ": not valid at rho = " + std::to_string(lo - 1e-3), slack(Interval(lo - 1e-3)),
             Interval(0));
  proof.less(name + ": not valid at rho = " + std::to_string(hi + 1e-3), slack(Interval(hi + 1e-3)),
             Interval(0));
}

}  // namespace

int main() {
  Proof proof("Theorem 6.1 corrected: rho~ <= (rho - K(rho)) / (1 + K(rho))");
  const Interval rho = ratio(3, 10);
  const Interval rt = ratio(3, 100);
  Chain56 a{ratio(8164, 10000), ratio(123, 1000), ratio(12802, 10000)};
  proof.less_eq("(A) c55 = 0.8164: K(0.3) (1 + 0.03) <= 0.3 - 0.03", a.k8(rho) * (1 + rt),
                rho - rt);
  proof.note("(A) largest rho~ at rho = 0.3", a.rho_tilde_max(rho));
  proof.note("(A) largest rho~ at rho = 0.24", a.rho_tilde_max(ratio(24, 100)));
  range(proof, "(A) c55 = 0.8164", a, rt);
  proof.note("(A) largest rho~ over rho in [0.2, 0.39] (B&B)", best_rho_tilde(a).extremum);
  Chain56 b{ratio(7550, 10000), ratio(123, 1000), ratio(12802, 10000)};
  // With E3's correction no rho admits rho~ = 0.03; the best is ~0.0236.
  BnbResult best = best_rho_tilde(b);
  proof.less("(B) c55 = 0.7550: max over rho in [0.2, 0.39] of rho~_max < 0.03 (B&B)",
             best.extremum, rt);
  Interval rho_b = Interval(best.point.at(0));
  proof.greater_eq("(B) rho~ = 0.0236 valid at rho = " + std::to_string(best.point.at(0)),
                   b.rho_tilde_max(rho_b), ratio(236, 10000));
  proof.note("(B) largest rho~ at rho = 0.3", b.rho_tilde_max(rho));
  return proof.finish();
}
