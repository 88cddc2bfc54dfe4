#pragma once
/// \file
/// How often each stage of each predicate decides (filter, dynamic filter, exact,
/// perturbation), for benchmarks and for the triangulation's statistics. Compiled in only
/// when the meson option `counters` is on (macro RSTRUCT_COUNTERS); otherwise every count
/// stays zero and counting costs nothing. Counts are global, relaxed atomics (safe across
/// threads).

#include <cstddef>
#include <cstdint>

namespace rstruct::predicates {

/// The predicates that keep counts.
enum class PredicateId : unsigned char {
  orient3d,
  orient2d,  ///< 2D orientations inside a plane (coplanar tests and their perturbation)
  insphere,
  power_test,
  coplanar_power_test,
  collinear_power_test,
  compare_squared_distance,
  compare_power_distance,
  power_sign,
  side_of_ball,
  count_  ///< number of ids, not a predicate
};

/// Decisions per stage. A call that ends in the perturbation also counts the exact
/// evaluation that returned zero before it only under `perturbed`.
struct StageCounts {
  std::uint64_t filter = 0;     ///< decided by the floating-point filter
  std::uint64_t dynamic = 0;    ///< decided by the dynamic filter (in-sphere and power tests)
  std::uint64_t exact = 0;      ///< decided by the exact stage (including exact zeros)
  std::uint64_t perturbed = 0;  ///< decided by the symbolic perturbation
  std::uint64_t total() const { return filter + dynamic + exact + perturbed; }
};

/// True iff this build counts (meson option `counters`).
constexpr bool counters_enabled() {
#ifdef RSTRUCT_COUNTERS
  return true;
#else
  return false;
#endif
}

/// Current counts of one predicate.
StageCounts stage_counts(PredicateId id);

/// Sets every count to zero.
void reset_stage_counts();

/// Name of a predicate, for reports ("orient3d", ...).
const char* predicate_name(PredicateId id);

}  // namespace rstruct::predicates
