// Lemma 5.6 of Aichholzer et al. (SGP 2009), general rho: the admissible interval of the
// paper's chain (2)-(8) (see Chain56 in chain.hpp), with
//  (A) the paper's constants, Corollary 5.5 rounded correctly (0.8164, ERRATA E4):
//      rho in [0.1907, 0.3979];
//  (B) additionally Lemma A.2 with the radius bound the cited facts give (ERRATA E3:
//      exterior angle >= 110.8 deg, Corollary 5.5 constant 0.7550): rho in [0.1960, 0.3725].
//  (C) with Lemma 4.3 replaced by our certified elementary bounds (lemma_4_3_elementary.cpp):
//      no rho is admissible -- the topological guarantee rests on the omitted proof.
// Each interval is certified by B&B (rho - K(rho) > 0 on it), and shown to be tight to 1e-3
// (K(rho) > rho just outside). Inputs still conditional on Lemma 4.3 (proof omitted).
#include <cmath>

#include "chain.hpp"

using namespace rstruct::proofs;

namespace {

/// Locates the admissible interval {rho : rho >= K(rho)}, rounds it inward to 4 decimals and
/// certifies it; returns it for the report.
void interval(Proof& proof, const std::string& name, const Chain56& ch) {
  auto slack = [&](const Interval& x) { return ch.slack4(x); };
  double c55 = lo_d(ch.c55);
  double lo = std::ceil(bisect_root(slack, 0.05, 0.3) * 1e4) / 1e4;
  double hi = std::floor(bisect_root(slack, 0.3, 0.999 * c55) * 1e4) / 1e4;
  BnbResult m = min_over_rho([&](const Interval& x) { return ch.slack4(x); }, lo, hi);
  proof.greater(name + ": rho >= K(rho) for all rho in [" + std::to_string(lo) + ", " +
                    std::to_string(hi) + "] (B&B)",
                m.extremum, Interval(0));
  proof.less(name + ": chain breaks just below, rho = " + std::to_string(lo - 1e-3),
             ch.slack4(Interval(lo - 1e-3)), Interval(0));
  proof.less(name + ": chain breaks just above, rho = " + std::to_string(hi + 1e-3),
             ch.slack4(Interval(hi + 1e-3)), Interval(0));
}

}  // namespace

int main() {
  Proof proof("Lemma 5.6: admissible rho of the paper's chain, corrected inputs");
  Chain56 a{ratio(8164, 10000), ratio(123, 1000), ratio(12802, 10000)};
  interval(proof, "(A) c55 = 0.8164", a);
  proof.note("(A) K(0.24)", a.k8(ratio(24, 100)));
  proof.note("(A) K(0.3)", a.k8(ratio(3, 10)));
  Chain56 b{ratio(7550, 10000), ratio(123, 1000), ratio(12802, 10000)};
  interval(proof, "(B) c55 = 0.7550", b);
  // (C) only what is certified here: Lemma 4.3 replaced by lemma_4_3_elementary.cpp
  // (c51 = 1.5126; case (b) of (5): 0.058 (1 + r) + r = 0.14264 > 0.123).
  Chain56 c{ratio(8164, 10000), ratio(14265, 100000), ratio(15126, 10000)};
  // A(rho) decreases in rho; beyond rho1 (A < 1/2) K >= 2 (1 + c5 c51) > 0.8 > rho, or
  // A <= 0 and (6) gives nothing; below rho1 B&B.
  double rho1 =
      std::ceil(bisect_root([&](const Interval& x) { return c.a6(x) - ratio(1, 2); }, 0.3, 0.8) *
                1e4) /
      1e4;
  proof.less("(C) A(rho1) < 1/2 at rho1 = " + std::to_string(rho1) + " (A decreasing)",
             c.a6(Interval(rho1)), ratio(1, 2));
  Objective f = [&](const Box& bx) { return Eval{c.slack4(bx[0]), Feasible::kAll}; };
  BnbResult m = maximize(f, {hull(0.01, rho1)}, 1e-9, 100000);
  proof.less(
      "(C) c51 = 1.5126, c5 = 0.14265: max over rho in [0.01, rho1] of rho - K(rho) < 0"
      " (no rho is admissible; rho < 0.01 fails since K >= c5 c51)",
      m.extremum, Interval(0));
  return proof.finish();
}
