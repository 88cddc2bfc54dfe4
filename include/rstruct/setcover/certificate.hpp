#pragma once
/// \file
/// Set-cover certificates (issue 6; DESIGN.md §3). A certificate holds a cover and
/// Lagrangian multipliers u ≥ 0, stored as integers U_i = ⌊u_i · scale⌋. For any u ≥ 0,
///   L(u) = Σ_i u_i + Σ_j min(0, c_j − Σ_{i∈S_j} u_i)
/// is a lower bound on the optimum (Lagrangian relaxation of the covering constraints);
/// with integer costs ⌈L(u)⌉ is one too. The checker that reads these files is
/// verifier.hpp, written independently of the solver.
///
/// Text format (indices 1-based, whitespace separated):
///   rstruct-setcover-certificate 1
///   rows <m> columns <n> unicost <0|1>
///   scale <S>
///   cover <k> <j_1> … <j_k>
///   multipliers <m> <U_1> … <U_m>
///   claim cost <q> bound <q>
///   end
/// where <q> is an exact rational (integer or p/q). The verifier rejects a certificate whose
/// cover misses a row, whose multipliers are negative, whose claimed cost differs from the
/// cover's cost, or whose claimed bound exceeds the bound it recomputes.

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "rstruct/setcover/instance.hpp"

namespace rstruct::setcover {

struct Certificate {
  static constexpr std::int64_t kDefaultScale = std::int64_t{1} << 32;
  std::int32_t num_rows = 0;
  std::int32_t num_cols = 0;
  bool unicost = false;        ///< costs taken as 1 (the `--unicost` variant of a file)
  std::int64_t scale = kDefaultScale;
  std::vector<std::int32_t> cover;        ///< 0-based columns
  std::vector<std::int64_t> multipliers;  ///< U_i ≥ 0, one per row
  std::string cost_claim = "0";   ///< exact cost of the cover (rational text)
  std::string bound_claim = "0";  ///< certified bound claimed (rational text)
};

/// Exact text ("p" or "p/q") of a double.
std::string exact_rational_text(double value);

/// Exact cost of `cols` on `inst` (all costs 1 when `unicost`), as rational text.
std::string exact_cost_text(const Instance& inst, const std::vector<std::int32_t>& cols, bool unicost);

/// Rounds u down onto the fixed-point grid of `scale` (clamped to [0, 2⁶²]).
std::vector<std::int64_t> to_fixed_point(const std::vector<double>& u, std::int64_t scale);

/// Exact value of the certificate's bound on `inst` computed by the solver side:
/// L(U / scale) rounded down to a double, and rounded up to an integer first when all
/// costs are integers. Columns with a negative reduced cost all count (never a core).
double certified_lower_bound(const Instance& inst, const Certificate& cert);

/// Writes the text format above.
void write_certificate(std::ostream& out, const Certificate& cert);
std::string certificate_text(const Certificate& cert);

}  // namespace rstruct::setcover
