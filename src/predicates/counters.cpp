#include "rstruct/predicates/counters.hpp"

#include "rstruct/predicates/detail/counting.hpp"

namespace rstruct::predicates {
namespace detail {

CounterTable& counter_table() {
  static CounterTable table{};
  return table;
}

}  // namespace detail

StageCounts stage_counts(PredicateId id) {
  const auto& row = detail::counter_table()[static_cast<std::size_t>(id)];
  StageCounts c;
  c.filter = row[0].load(std::memory_order_relaxed);
  c.dynamic = row[1].load(std::memory_order_relaxed);
  c.exact = row[2].load(std::memory_order_relaxed);
  c.perturbed = row[3].load(std::memory_order_relaxed);
  return c;
}

void reset_stage_counts() {
  for (auto& row : detail::counter_table()) {
    for (auto& c : row) c.store(0, std::memory_order_relaxed);
  }
}

const char* predicate_name(PredicateId id) {
  switch (id) {
    case PredicateId::orient3d: return "orient3d";
    case PredicateId::orient2d: return "orient2d";
    case PredicateId::insphere: return "insphere";
    case PredicateId::power_test: return "power_test";
    case PredicateId::coplanar_power_test: return "coplanar_power_test";
    case PredicateId::collinear_power_test: return "collinear_power_test";
    case PredicateId::compare_squared_distance: return "compare_squared_distance";
    case PredicateId::compare_power_distance: return "compare_power_distance";
    case PredicateId::power_sign: return "power_sign";
    case PredicateId::side_of_ball: return "side_of_ball";
    case PredicateId::count_: break;
  }
  return "unknown";
}

}  // namespace rstruct::predicates
