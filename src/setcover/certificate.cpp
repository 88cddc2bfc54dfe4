#include "rstruct/setcover/certificate.hpp"

#include <cmath>
#include <gmpxx.h>
#include <ostream>
#include <sstream>

#include "rstruct/core/error.hpp"

namespace rstruct::setcover {

namespace {

__extension__ typedef __int128 Int128;
__extension__ typedef unsigned __int128 UInt128;

/// ⌊a / b⌋ and ⌈a / b⌉ for b > 0.
Int128 floor_div(Int128 a, Int128 b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }
Int128 ceil_div(Int128 a, Int128 b) { return -floor_div(-a, b); }

mpz_class to_mpz(Int128 v) {
  const bool negative = v < 0;
  UInt128 x = negative ? static_cast<UInt128>(-v) : static_cast<UInt128>(v);
  mpz_class hi(static_cast<unsigned long>(static_cast<std::uint64_t>(x >> 64)));
  mpz_class lo(static_cast<unsigned long>(static_cast<std::uint64_t>(x)));
  mpz_class r = (hi << 64) + lo;
  return negative ? mpz_class(-r) : r;
}

}  // namespace

std::vector<std::int64_t> to_fixed_point(const std::vector<double>& u, std::int64_t scale) {
  std::vector<std::int64_t> out(u.size(), 0);
  const double limit = std::ldexp(1.0, 62);
  for (std::size_t i = 0; i < u.size(); ++i) {
    const double v = std::floor(u[i] * static_cast<double>(scale));
    // u * scale is exact (scale is a power of two) unless it overflows, and floor is exact.
    out[i] = !(v > 0.0) ? 0 : v >= limit ? (std::int64_t{1} << 62) : static_cast<std::int64_t>(v);
  }
  return out;
}

double certified_lower_bound(const Instance& inst, const Certificate& cert) {
  if (static_cast<std::int32_t>(cert.multipliers.size()) != inst.num_rows()) {
    throw InvalidInput("certificate has " + std::to_string(cert.multipliers.size()) +
                       " multipliers for " + std::to_string(inst.num_rows()) + " rows");
  }
  const Int128 scale = cert.scale;
  Int128 sum_u = 0;
  for (std::int64_t x : cert.multipliers) sum_u += x;
  const bool integer = cert.unicost || inst.has_integer_costs();
  if (integer) {
    Int128 numerator = sum_u;  // L · scale
    for (std::int32_t j = 0; j < inst.num_cols(); ++j) {
      Int128 r = cert.unicost ? scale : static_cast<Int128>(static_cast<std::int64_t>(inst.cost(j))) * scale;
      for (std::int32_t i : inst.column(j)) r -= cert.multipliers[i];
      if (r < 0) numerator += r;
    }
    return static_cast<double>(ceil_div(numerator, scale));
  }
  mpq_class total(to_mpz(sum_u), to_mpz(scale));
  for (std::int32_t j = 0; j < inst.num_cols(); ++j) {
    Int128 s = 0;
    for (std::int32_t i : inst.column(j)) s += cert.multipliers[i];
    mpq_class r = mpq_class(inst.cost(j)) - mpq_class(to_mpz(s), to_mpz(scale));
    if (r < 0) total += r;
  }
  total.canonicalize();
  double value = total.get_d();  // GMP truncates toward zero
  while (mpq_class(value) > total) value = std::nextafter(value, -INFINITY);
  return value;
}

std::string exact_rational_text(double value) {
  if (!std::isfinite(value)) throw InvalidInput("certificate: non-finite value");
  mpq_class q(value);
  q.canonicalize();
  return q.get_str();
}

std::string exact_cost_text(const Instance& inst, const std::vector<std::int32_t>& cols, bool unicost) {
  mpq_class total(0);
  for (std::int32_t j : cols) total += unicost ? mpq_class(1) : mpq_class(inst.cost(j));
  total.canonicalize();
  return total.get_str();
}

void write_certificate(std::ostream& out, const Certificate& cert) {
  out << "rstruct-setcover-certificate 1\n";
  out << "rows " << cert.num_rows << " columns " << cert.num_cols << " unicost "
      << (cert.unicost ? 1 : 0) << '\n';
  out << "scale " << cert.scale << '\n';
  out << "cover " << cert.cover.size();
  for (std::size_t k = 0; k < cert.cover.size(); ++k) out << (k % 20 == 0 ? '\n' : ' ') << cert.cover[k] + 1;
  out << "\nmultipliers " << cert.multipliers.size();
  for (std::size_t k = 0; k < cert.multipliers.size(); ++k) out << (k % 10 == 0 ? '\n' : ' ') << cert.multipliers[k];
  out << "\nclaim cost " << cert.cost_claim << " bound " << cert.bound_claim << "\nend\n";
}

std::string certificate_text(const Certificate& cert) {
  std::ostringstream out;
  write_certificate(out, cert);
  return out.str();
}

}  // namespace rstruct::setcover
