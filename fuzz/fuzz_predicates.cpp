// Fuzz target for the predicates: the bytes become a predicate choice and doubles
// (raw IEEE bits, or "structured": small integers at a common power-of-two scale moved by
// a few ulps, so that exactly and nearly degenerate configurations are frequent). Each
// predicate's filtered answer is compared with its exact stage alone, and with the
// independent GMP-rational oracle of the tests (also for the perturbed predicates).
// Any disagreement aborts. Non-finite inputs must throw InvalidInput; nothing else may.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "../tests/predicates/rational_oracle.hpp"
#include "predicates/exact_stage.hpp"
#include "rstruct/predicates/detail/filters.hpp"
#include "rstruct/core/error.hpp"
#include "rstruct/predicates/predicates.hpp"

namespace {

using rstruct::Point3;
using rstruct::Sign;
using rstruct::WeightedPoint;
namespace pr = rstruct::predicates;
namespace pd = rstruct::predicates::detail;
namespace oracle = rstruct::oracle;

class Reader {
 public:
  Reader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  std::uint8_t byte() { return pos_ < size_ ? data_[pos_++] : 0; }
  double raw_double() {
    std::uint64_t bits = 0;
    for (int i = 0; i < 8; ++i) bits = (bits << 8) | byte();
    double v;
    std::memcpy(&v, &bits, sizeof v);
    return v;
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

struct Input {
  WeightedPoint p[5];
  std::uint32_t id[5];
  bool finite = true;
};

Input read_input(Reader& r, bool structured) {
  Input in;
  const int scale = static_cast<int>(static_cast<std::int8_t>(r.byte())) * 4;
  auto value = [&](bool weight) {
    if (!structured) return r.raw_double();
    const auto small = static_cast<std::int8_t>(r.byte());
    const std::uint8_t wiggle = r.byte();
    double v = std::ldexp(static_cast<double>(small % 9), weight ? 2 * scale : scale);
    if ((wiggle & 0xc0) == 0xc0) v = std::nextafter(v, (wiggle & 1) != 0 ? HUGE_VAL : -HUGE_VAL);
    return v;
  };
  for (WeightedPoint& q : in.p) {
    q.c = {value(false), value(false), value(false)};
    q.w = (r.byte() & 3) == 0 ? 0.0 : value(true);
    in.finite = in.finite && std::isfinite(q.c.x) && std::isfinite(q.c.y) &&
                std::isfinite(q.c.z) && std::isfinite(q.w);
  }
  for (int i = 0; i < 5; ++i) in.id[i] = static_cast<std::uint32_t>(i * 7 + (r.byte() % 7));
  return in;
}

[[noreturn]] void fail(const char* what, const Input& in) {
  std::fprintf(stderr, "fuzz_predicates: %s disagrees on", what);
  for (const WeightedPoint& q : in.p) {
    std::fprintf(stderr, " (%a %a %a; %a)", q.c.x, q.c.y, q.c.z, q.w);
  }
  std::fprintf(stderr, "\n");
  std::abort();
}

void check(bool ok, const char* what, const Input& in) {
  if (!ok) fail(what, in);
}

void run_orient(const Input& in) {
  const Point3 &a = in.p[0].c, &b = in.p[1].c, &c = in.p[2].c, &d = in.p[3].c;
  const int s = rstruct::to_int(pr::orient3d(a, b, c, d));
  check(s == pd::orient3d_exact(a, b, c, d), "orient3d filtered vs exact", in);
  check(s == oracle::orient3d(a, b, c, d), "orient3d vs oracle", in);
}

void run_lifted(const Input& in, bool sos) {
  const WeightedPoint* p = in.p;
  const int s = rstruct::to_int(pr::power_test(p[0], p[1], p[2], p[3], p[4]));
  check(s == pd::lifted4_exact(p[0], p[1], p[2], p[3], p[4]), "power_test filtered vs exact", in);
  if (pr::orient3d(p[0].c, p[1].c, p[2].c, p[3].c) == Sign::zero) return;
  check(s == oracle::power_test(p[0], p[1], p[2], p[3], p[4]), "power_test vs oracle", in);
  if (!sos) return;
  const Sign t = pr::power_test_sos(p[0], p[1], p[2], p[3], p[4], in.id[0], in.id[1], in.id[2],
                                    in.id[3], in.id[4]);
  check(t != Sign::zero && (s == 0 || rstruct::to_int(t) == s), "power_test_sos vs plain", in);
  check(rstruct::to_int(t) ==
            oracle::power_test_sos({p[0], p[1], p[2], p[3], p[4]},
                                   {in.id[0], in.id[1], in.id[2], in.id[3], in.id[4]}),
        "power_test_sos vs oracle", in);
}

void run_plane(const Input& in) {
  const WeightedPoint* p = in.p;
  if (pr::orient3d(p[0].c, p[1].c, p[2].c, p[3].c) != Sign::zero) return;
  if (oracle::qcross(oracle::qsub(oracle::qp(p[1].c), oracle::qp(p[0].c)),
                     oracle::qsub(oracle::qp(p[2].c), oracle::qp(p[0].c))) ==
      oracle::QPoint{0, 0, 0}) {
    return;  // collinear triangle: precondition
  }
  const int s = rstruct::to_int(pr::coplanar_power_test(p[0], p[1], p[2], p[3]));
  check(s == oracle::coplanar_power_test(p[0], p[1], p[2], p[3]), "coplanar vs oracle", in);
  const Sign t = pr::coplanar_power_test_sos(p[0], p[1], p[2], p[3], in.id[0], in.id[1],
                                             in.id[2], in.id[3]);
  check(rstruct::to_int(t) == oracle::coplanar_power_test_sos(
                                  {p[0], p[1], p[2], p[3]}, {in.id[0], in.id[1], in.id[2], in.id[3]}),
        "coplanar_sos vs oracle", in);
}

void run_distances(const Input& in) {
  const WeightedPoint* p = in.p;
  const Point3& x = p[0].c;
  const int d = rstruct::to_int(pr::compare_squared_distance(x, p[1].c, p[2].c));
  check(d == pd::squared_distance_difference_exact(x, p[1].c, p[2].c), "distance vs exact", in);
  const int w = rstruct::to_int(pr::compare_power_distance(x, p[1], p[2]));
  check(w == oracle::compare_power_distance(x, p[1], p[2]), "power distance vs oracle", in);
  const int b = rstruct::to_int(pr::side_of_ball(x, p[3].c, p[3].w));
  check(b == oracle::side_of_ball(x, p[3].c, p[3].w), "side_of_ball vs oracle", in);
  const int s = rstruct::to_int(pr::power_sign(x, p[4]));
  check(s == pd::power_value_exact(x, p[4]), "power_sign vs exact", in);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  Reader r(data + 1, size - 1);
  const std::uint8_t selector = data[0];
  const Input in = read_input(r, (selector & 0x80) != 0);
  try {
    switch (selector % 5) {
      case 0: run_orient(in); break;
      case 1: run_lifted(in, false); break;
      case 2: run_lifted(in, true); break;
      case 3: run_plane(in); break;
      default: run_distances(in); break;
    }
  } catch (const rstruct::InvalidInput&) {
    // The harness screens every precondition (flat cells, collinear plane triangles,
    // distinct ids), so only non-finite data may throw.
    check(!in.finite, "unexpected InvalidInput", in);
  }
  return 0;
}
