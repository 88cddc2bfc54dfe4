// Lemma 5.6 of Aichholzer et al. (SGP 2009) at rho = 0.3, the paper's chain and constants:
// k1 = 0.074, (2) 0.37, 0.368, (3) the ratio 5, (6) 10.6, (7) 0.1575 and 6.3, (8) the
// multipliers 0.095, 0.175 and 0.27, (5) case (b) 0.0931 <= 0.123, and 1/0.817 <= 1.224.
// Inputs taken from other lemmas: Corollary 5.5 (0.817; lemma_a3.cpp: really 0.8165),
// Lemma 5.1 (1.2802; rests on the unproven Lemma 4.3a), Lemma A.1 (0.123), Lemma 4.3b
// (0.0114, unproven). All steps HOLD, and still hold with 0.817 replaced by 0.8164.
// The claim for general rho in [0.24, 0.56] is lemma_5_6_interval.cpp.
#include "chain.hpp"

using namespace rstruct::proofs;

namespace {

/// (2) by B&B: min |s - x| / |s - m| over s = (w, y) with |s - m| >= 1, y >= xi, xi in
/// [k1, 1], m = (0, 1), x = (0, xi). Outside the box w, y <= 3 the ratio is >= 1/2 since
/// then |s - m| >= 2 and |s - x| >= |s - m| - 1.
BnbResult min_ratio2(const Interval& k1) {
  Objective f = [](const Box& b) {
    const Interval& w = b[0];
    const Interval& y = b[1];
    const Interval& xi = b[2];
    Interval sm2 = w * w + (y - 1) * (y - 1);
    Interval above = y - xi;
    Interval out = sm2 - 1;
    Feasible fe = (lo(above) >= 0 && lo(out) >= 0) ? Feasible::kAll
                  : (hi(above) < 0 || hi(out) < 0) ? Feasible::kNone
                                                   : Feasible::kSome;
    return Eval{sqrt_nonneg((w * w + (y - xi) * (y - xi)) / sm2), fe};
  };
  Interval witness = sqrt_nonneg(2 * k1 - k1 * k1);  // the corner s_0 at xi = k1
  return minimize(f, {hull(0, 3), hull(0, 3), Interval(lo(k1), Real(1))}, 1e-7, 300000, {},
                  &witness);
}

}  // namespace

int main() {
  Proof proof("Lemma 5.6 at rho = 0.3 with the paper's constants");
  const Interval rho = ratio(3, 10);
  const Interval r = ratio(8, 100);
  const Interval k1 = ratio(74, 1000);
  const Interval c55 = ratio(817, 1000);

  proof.greater("(2) corner s_0: sqrt(1 - (1 - k1)^2) > 0.37", sqrt_nonneg(1 - (1 - k1) * (1 - k1)),
                ratio(37, 100));
  BnbResult m2 = min_ratio2(k1);
  proof.greater("(2) min |s-x|/|s-m| over the shaded region, xi >= k1 (B&B) > 0.37", m2.extremum,
                ratio(37, 100));
  proof.less("rho / 0.817 < 0.368", rho / c55, ratio(368, 1000));
  proof.less("rho / 0.8164 < 0.368 (with Corollary 5.5 corrected, ERRATA E4)",
             rho / ratio(8164, 10000), ratio(368, 1000));
  proof.less("0.368 < 0.37: the contradiction that gives |x - v| <= k1", ratio(368, 1000),
             ratio(37, 100));
  Chain56 ch{c55, ratio(123, 1000), ratio(12802, 10000)};
  proof.less_eq("exact threshold k1(0.3) = 1 - sqrt(1 - (rho/0.817)^2) <= 0.074", ch.k1(rho), k1);
  proof.greater_eq("(3) sqrt(2/k1 - 1) >= 5", sqrt_nonneg(2 / k1 - 1), Interval(5));
  proof.greater("(6) 5 (1/rho - 1) - 1 > 10.6", 5 * (1 / rho - 1) - 1, ratio(106, 10));
  Interval c7 = ratio(123, 1000) * ratio(12802, 10000);
  proof.less("(7) 0.123 * 1.2802 < 0.1575", c7, ratio(1575, 10000));
  proof.greater("(7) 1 / 0.1575 > 6.3", 1 / ratio(1575, 10000), ratio(63, 10));
  proof.greater_eq("(8) 0.095 * 10.6 >= 1 (coefficient of |x - v|)",
                   ratio(95, 1000) * ratio(106, 10), Interval(1));
  proof.greater_eq("(8) 0.175 * 6.3 - 0.095 >= 1 (coefficient of |v - t|)",
                   ratio(175, 1000) * ratio(63, 10) - ratio(95, 1000), Interval(1));
  proof.less_eq("(8) 0.095 + 0.175 <= 0.27 (in thousandths)", Interval(95 + 175), Interval(270));
  proof.less_eq("(4) 0.27 <= rho = 0.3", ratio(27, 100), rho);
  proof.note("(8) exact best constant K(0.3) of this chain", ch.k8(rho));
  proof.less_eq("(5) case (b): 0.0114 (1 + r) + r <= 0.0931", ratio(114, 10000) * (1 + r) + r,
                ratio(931, 10000));
  proof.less_eq("(5) 0.0931 <= 0.123 (case (a) dominates)", ratio(931, 10000), ratio(123, 1000));
  proof.less_eq("(5b) 1 / 0.817 <= 1.224", 1 / c55, ratio(1224, 1000));
  return proof.finish();
}
