// Fuzz target: the solver and the verifier on small instances decoded from the bytes.
// Checks: the result is a cover, its certificate verifies, the certified bound is at most the
// brute-force optimum, which the solver reaches (small instances get the exact search).
#include <algorithm>
#include <cstdint>
#include <limits>
#include <sstream>
#include <vector>

#include "rstruct/core/assert.hpp"
#include "rstruct/core/error.hpp"
#include "rstruct/setcover/solver.hpp"
#include "rstruct/setcover/verifier.hpp"

namespace {

double optimum(std::int32_t m, const std::vector<std::vector<std::int32_t>>& cols,
               const std::vector<double>& costs) {
  const std::uint32_t full = (1u << m) - 1;
  std::vector<double> best(full + 1, std::numeric_limits<double>::infinity());
  best[0] = 0;
  for (std::uint32_t s = 0; s <= full; ++s) {
    if (best[s] == std::numeric_limits<double>::infinity()) continue;
    for (std::size_t j = 0; j < cols.size(); ++j) {
      std::uint32_t t = s;
      for (std::int32_t r : cols[j]) t |= 1u << r;
      best[t] = std::min(best[t], best[s] + (costs.empty() ? 1.0 : costs[j]));
    }
  }
  return best[full];
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace rstruct::setcover;
  if (size < 2) return 0;
  const std::int32_t m = 1 + data[0] % 12;
  const bool unicost = (data[1] & 1) != 0;
  std::vector<std::vector<std::int32_t>> cols;
  std::vector<double> costs;
  for (std::size_t k = 2; k + 2 < size && cols.size() < 16; k += 3) {
    const std::uint32_t mask = (static_cast<std::uint32_t>(data[k]) | (static_cast<std::uint32_t>(data[k + 1]) << 8)) &
                               ((1u << m) - 1);
    std::vector<std::int32_t> rows;
    for (std::int32_t r = 0; r < m; ++r) {
      if (mask & (1u << r)) rows.push_back(r);
    }
    cols.push_back(rows);
    if (!unicost) costs.push_back(static_cast<double>(data[k + 2] % 17) / (data[1] & 2 ? 4.0 : 1.0));
  }
  const Instance inst = Instance::from_columns(m, cols, costs);
  SolverOptions options;
  options.time_limit = 10.0;
  options.max_local_search_iterations = 5000;
  Solution sol;
  try {
    sol = solve(inst, options);
  } catch (const rstruct::ComputationFailed&) {
    RSTRUCT_ASSERT(inst.first_uncoverable_row() >= 0);
    return 0;
  }
  RSTRUCT_ASSERT(inst.is_cover(sol.columns));
  const double opt = optimum(m, cols, costs);
  RSTRUCT_ASSERT(sol.lower_bound <= opt);
  RSTRUCT_ASSERT(sol.cost == opt);
  std::istringstream cert(certificate_text(sol.certificate));
  const Verdict v = verify_certificate(m, cols, costs, cert);
  RSTRUCT_ASSERT_MSG(v.valid, v.summary());
  return 0;
}
