// Self-test of proofs/interval.hpp: the enclosures contain known values, the branch-and-bound
// encloses known extrema (unconstrained, constrained, maximisation, with a witness), and the
// claim reporter gives FAILS / UNDECIDED where it must. Not a claim of the paper: it checks
// the machinery every other program relies on.
#include <sstream>

#include "interval.hpp"

using namespace rstruct::proofs;

namespace {

/// 1 if `x` contains `value` and is narrower than `width`, else 0 (as an interval claim).
Interval encloses(const BnbResult& r, const Interval& value, double width) {
  bool in = lo(r.extremum) <= lo(value) && hi(value) <= hi(r.extremum);
  bool narrow = hi(r.extremum) - lo(r.extremum) <= width;
  return Interval(in && narrow ? 1 : 0);
}

}  // namespace

int main() {
  Proof proof("self-test of the interval layer");
  Interval p = pi();
  proof.less("pi < 355/113", p, ratio(355, 113));
  proof.greater("pi > 3.14159265358979", p, ratio(314159265358979L, 100000000000000L));
  proof.less("width(pi) < 1e-70", hi(p) - lo(p) < 1e-70 ? Interval(0) : Interval(1), ratio(1, 2));
  proof.less("|sin(pi)| < 1e-70", abs(sin(p)), pow(Interval(10), -70));
  proof.less("|sqrt(2)^2 - 2| < 1e-70", abs(sqrt(Interval(2)) * sqrt(Interval(2)) - 2),
             pow(Interval(10), -70));

  Objective bowl = [](const Box& b) {
    Interval x = b[0] - ratio(1, 3);
    Interval y = b[1] + ratio(1, 5);
    return Eval{x * x + y * y + ratio(1, 7), Feasible::kAll};
  };
  BnbResult m1 = minimize(bowl, {hull(-1, 1), hull(-1, 1)}, 1e-10, 100000);
  proof.greater("B&B min of (x-1/3)^2 + (y+1/5)^2 + 1/7 encloses 1/7 (width 1e-9)",
                encloses(m1, ratio(1, 7), 1e-9), ratio(1, 2));

  // min x + y subject to x^2 + y^2 >= 1 on [0, 2]^2: 1, at (1, 0) and (0, 1).
  Objective ring = [](const Box& b) {
    Interval c = b[0] * b[0] + b[1] * b[1] - 1;
    Feasible f = lo(c) >= 0 ? Feasible::kAll : hi(c) < 0 ? Feasible::kNone : Feasible::kSome;
    return Eval{b[0] + b[1], f};
  };
  Interval one(1);
  BnbResult m2 = minimize(ring, {hull(0, 2), hull(0, 2)}, 1e-8, 200000, {}, &one);
  proof.greater("constrained B&B min of x + y, x^2 + y^2 >= 1, encloses 1",
                encloses(m2, Interval(1), 1e-7), ratio(1, 2));

  Objective wave = [](const Box& b) { return Eval{sin(b[0]), Feasible::kAll}; };
  BnbResult m3 = maximize(wave, {hull(0, 3)}, 1e-10, 100000);
  proof.greater("B&B max of sin on [0, 3] encloses 1", encloses(m3, Interval(1), 1e-9),
                ratio(1, 2));

  // prove_above stops once the claim is proved, with a certified lower bound above it.
  BnbResult m4 = minimize(bowl, {hull(-1, 1), hull(-1, 1)}, 1e-10, 100000, {}, nullptr, 0.1);
  proof.greater("prove_above: min > 0.1 certified", m4.extremum, ratio(1, 10));

  // The reporter: a false claim FAILS, an undecidable one is UNDECIDED (printed to a
  // discarded stream).
  std::ostringstream sink;
  auto* old = std::cout.rdbuf(sink.rdbuf());
  Proof inner("inner");
  Verdict v1 = inner.less("2 < 1", Interval(2), Interval(1));
  Verdict v2 = inner.less("1/3 < 1/3", ratio(1, 3), ratio(1, 3));
  Verdict v3 = inner.less_eq("1 <= 1 (exact)", Interval(1), Interval(1));
  std::cout.rdbuf(old);
  proof.greater("a false claim is reported FAILS", Interval(v1 == Verdict::kFails ? 1 : 0),
                ratio(1, 2));
  proof.greater("an undecidable claim is reported UNDECIDED",
                Interval(v2 == Verdict::kUndecided ? 1 : 0), ratio(1, 2));
  proof.greater("an exact equality passes <=", Interval(v3 == Verdict::kHolds ? 1 : 0),
                ratio(1, 2));
  return proof.finish();
}
