#pragma once
/// \file
/// Stage counters behind predicates/counters.hpp. RSTRUCT_PREDICATE_COUNT(id, stage)
/// compiles to nothing unless the meson option `counters` defines RSTRUCT_COUNTERS.

#include <array>
#include <atomic>
#include <cstdint>

#include "rstruct/predicates/counters.hpp"

namespace rstruct::predicates::detail {

enum class Stage : unsigned char { filter, dynamic, exact, perturbed };

using CounterTable = std::array<std::array<std::atomic<std::uint64_t>, 4>,
                                static_cast<std::size_t>(PredicateId::count_)>;
CounterTable& counter_table();

inline void count(PredicateId id, Stage stage) {
  counter_table()[static_cast<std::size_t>(id)][static_cast<std::size_t>(stage)].fetch_add(
      1, std::memory_order_relaxed);
}

}  // namespace rstruct::predicates::detail

#ifdef RSTRUCT_COUNTERS
#define RSTRUCT_PREDICATE_COUNT(id, stage)                             \
  ::rstruct::predicates::detail::count(::rstruct::predicates::PredicateId::id, \
                                       ::rstruct::predicates::detail::Stage::stage)
#else
#define RSTRUCT_PREDICATE_COUNT(id, stage) ((void)0)
#endif
