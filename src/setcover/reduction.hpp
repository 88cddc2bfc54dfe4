#pragma once
// Presolve of a set-cover instance (issue 6, "Reduction"): zero-cost columns taken, rows
// covered by a single column force it, dominated rows and dominated columns removed; the
// rest split into connected components (rows linked through shared columns).

#include <cstdint>
#include <vector>

#include "rstruct/core/stopwatch.hpp"
#include "rstruct/setcover/instance.hpp"

namespace rstruct::setcover::detail {

/// One connected component of the reduced instance, with its maps to the original.
struct Component {
  Instance instance;
  std::vector<std::int32_t> rows;  ///< component row -> original row
  std::vector<std::int32_t> cols;  ///< component column -> original column
};

struct Reduction {
  std::vector<std::int32_t> fixed_cols;  ///< original columns every solution takes
  /// Multipliers implied by the forced columns: (original row, value). A row covered only
  /// by column j gets u = c_j; with all other rows of j at 0, j's reduced cost is 0.
  std::vector<std::pair<std::int32_t, double>> forced_multipliers;
  std::vector<Component> components;
  std::int64_t dominated_rows = 0;
  std::int64_t dominated_cols = 0;
  std::int64_t forced_cols = 0;
  bool timed_out = false;  ///< domination checks were cut short by the deadline
  bool work_limited = false;  ///< domination checks were cut short by the work limit
  std::int64_t work = 0;      ///< entries scanned by the domination checks
};

/// Reduces `inst`. Domination checks stop (leaving a valid, less reduced instance) once
/// `clock` passes `deadline` or they have scanned more than `work_limit` entries (0: no
/// work limit). They run on `threads` threads (0: hardware concurrency); the result and
/// the work do not depend on that number. \pre every row is covered by some column.
Reduction reduce(const Instance& inst, bool use_domination, double deadline, const Stopwatch& clock,
                 std::int64_t work_limit = 0, unsigned threads = 1);

}  // namespace rstruct::setcover::detail
