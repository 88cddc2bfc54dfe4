#pragma once
/// \file
/// Independent checker of set-cover certificates (issue 6). It shares no code with the
/// solver: it parses the instance and the certificate itself, and recomputes coverage,
/// cost and the Lagrangian bound
///   L(u) = Σ_i u_i + Σ_j min(0, c_j − Σ_{i∈S_j} u_i),  u_i = U_i / scale,
/// over every column in exact rational arithmetic (GMP), costs read exactly from their
/// decimal text. The bound is rounded up to an integer only when every cost is an integer.
/// Validity: the cover covers every row with valid, distinct column indices; every U_i is a
/// non-negative integer; the claimed cost equals the cover's cost; the claimed bound does
/// not exceed the recomputed one. Any u ≥ 0 gives a valid bound (weak Lagrangian duality).

#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

namespace rstruct::setcover {

struct Verdict {
  bool valid = false;
  std::vector<std::string> problems;  ///< why INVALID (empty when valid)
  std::string cost;                   ///< exact cost of the cover ("p" or "p/q")
  std::string bound;                  ///< exact recomputed bound (after ⌈⌉ for integer costs)
  double cost_value = 0.0;
  double bound_value = 0.0;
  double gap = 0.0;  ///< (cost − bound) / cost, 0 when cost is 0
  bool integer_costs = false;
  std::int64_t uncovered_rows = 0;

  /// "VALID cost … bound … gap …" or "INVALID: <first problem>".
  std::string summary() const;
};

/// Instance file layout, as OR-Library's row format (scp files: m n, costs, then per row
/// its columns) or column format (rail files: m n, then per column cost, count, rows).
enum class VerifierInputFormat { kRows, kColumns };

/// Checks `certificate` against the instance file. \throws IoError if a file cannot be
/// read, InvalidInput if the instance file is malformed. A malformed certificate gives an
/// INVALID verdict, not an exception.
Verdict verify_certificate_files(const std::filesystem::path& instance,
                                 const std::filesystem::path& certificate,
                                 VerifierInputFormat format);

/// Checks a certificate against an in-memory instance: `columns[j]` lists the 0-based rows
/// of column j; `costs` empty means unicost (otherwise doubles, taken exactly).
Verdict verify_certificate(std::int64_t num_rows, const std::vector<std::vector<std::int32_t>>& columns,
                           const std::vector<double>& costs, std::istream& certificate);

}  // namespace rstruct::setcover
