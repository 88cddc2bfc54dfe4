#pragma once
// Small random set-cover instances for the set-cover tests, and a brute-force optimum by
// dynamic programming over covered-row masks (rows <= 16).
#include <rapidcheck.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <ostream>
#include <vector>

#include "rstruct/setcover/instance.hpp"

namespace rstruct::setcover::testing {

struct SmallInstance {
  std::int32_t rows = 0;
  std::vector<std::vector<std::int32_t>> columns;
  std::vector<double> costs;  // empty: unicost

  Instance build() const { return Instance::from_columns(rows, columns, costs); }
};

/// 1..12 rows, 1..20 columns, every row covered; integer costs 1..9 or unicost.
inline rc::Gen<SmallInstance> gen_small_instance() {
  return rc::gen::exec([] {
    SmallInstance s;
    s.rows = *rc::gen::inRange<std::int32_t>(1, 13);
    const auto n = *rc::gen::inRange<std::int32_t>(1, 21);
    const bool unicost = *rc::gen::arbitrary<bool>();
    std::vector<char> covered(static_cast<std::size_t>(s.rows), 0);
    for (std::int32_t j = 0; j < n; ++j) {
      auto rows = *rc::gen::container<std::vector<std::int32_t>>(
          *rc::gen::inRange<std::size_t>(0, 6), rc::gen::inRange<std::int32_t>(0, s.rows));
      for (std::int32_t r : rows) covered[r] = 1;
      s.columns.push_back(rows);
      if (!unicost) s.costs.push_back(*rc::gen::inRange<int>(1, 10));
    }
    for (std::int32_t r = 0; r < s.rows; ++r) {  // cover the rest
      if (covered[r]) continue;
      const auto j = *rc::gen::inRange<std::size_t>(0, s.columns.size());
      s.columns[j].push_back(r);
    }
    return s;
  });
}

/// Optimal cost by DP over masks of covered rows.
inline double brute_force_optimum(const Instance& inst) {
  const std::int32_t m = inst.num_rows();
  const std::uint32_t full = (1u << m) - 1;
  std::vector<double> best(static_cast<std::size_t>(full) + 1, std::numeric_limits<double>::infinity());
  best[0] = 0.0;
  std::vector<std::uint32_t> mask(static_cast<std::size_t>(inst.num_cols()), 0);
  for (std::int32_t j = 0; j < inst.num_cols(); ++j) {
    for (std::int32_t r : inst.column(j)) mask[j] |= 1u << r;
  }
  for (std::uint32_t s = 0; s <= full; ++s) {
    if (best[s] == std::numeric_limits<double>::infinity()) continue;
    for (std::int32_t j = 0; j < inst.num_cols(); ++j) {
      const std::uint32_t t = s | mask[j];
      best[t] = std::min(best[t], best[s] + inst.cost(j));
    }
  }
  return best[full];
}

inline void showValue(const SmallInstance& s, std::ostream& os) {
  os << "rows " << s.rows << " columns:";
  for (std::size_t j = 0; j < s.columns.size(); ++j) {
    os << " [";
    for (std::int32_t r : s.columns[j]) os << r << ' ';
    os << "]" << (s.costs.empty() ? 1.0 : s.costs[j]);
  }
}

}  // namespace rstruct::setcover::testing
