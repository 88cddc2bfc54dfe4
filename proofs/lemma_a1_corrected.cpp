// Lemma A.1 (= Lemma 5.2) of Aichholzer et al. (SGP 2009), corrected constants
// (proofs/ERRATA.md E1, E2): the smallest k that closes part (a) at r = 0.08 is 1.5363, so
// k = 1.537 and the paper's conclusion |v - s| <= 0.123 lfs(s) survives; part (b) holds with
// 0.0357 lfs(s) <= 0.0425 lfs(v^) instead of 0.0355 <= 0.0424.
#include "chain.hpp"

using namespace rstruct::proofs;

int main() {
  Proof proof("Lemma A.1, corrected (lfs(s) = 1, r = 0.08)");
  const Interval r = ratio(8, 100);
  Interval sp = angle_sp(r);
  // Smallest k: asin(1/(k(1-r))) = 60deg - asin(r/(1-r)) - 2 asin(r/(1-r)).
  Interval k_min = 1 / ((1 - r) * sin(deg(60) - 3 * asin_u(r / (1 - r))));
  proof.note("(a) smallest k closing the argument", k_min);
  const Interval k = ratio(1537, 1000);
  proof.less("(a) k = 1.537: angle(sv,n) + angle(n,sp) < 60deg", to_deg(angle_sv(k, r) + sp),
             Interval(60));
  proof.less_eq("(a) k r <= 0.123 (the lemma's conclusion survives)", k * r, ratio(123, 1000));
  const Interval a = ratio(123, 1000);
  BnbResult m = a1b_max_distance(a, sp, 400000);
  proof.note("(b) B&B boxes " + std::to_string(m.boxes) +
             (m.converged ? " (converged)" : " (budget)"));
  proof.less("(b) max dist(v, F) over Figure 13's region, |v - s| <= 0.123 (B&B) < 0.0357",
             m.extremum, ratio(357, 10000));
  proof.less("(b) closed form at the extreme point < 0.0357", a1b_closed_form(a, sp),
             ratio(357, 10000));
  proof.less_eq("(b) 0.0357 / (1 - 0.123 - 0.0357) <= 0.0425 (Lipschitz)",
                a1b_lipschitz(a, ratio(357, 10000)), ratio(425, 10000));
  return proof.finish();
}
