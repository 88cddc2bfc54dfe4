#pragma once
// Constructive heuristics: Chvátal's greedy and the Lagrangian greedy of Caprara, Fischetti
// and Toth (1999), both with lazy priority updates, and redundant-column removal.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "rstruct/setcover/instance.hpp"

namespace rstruct::setcover::detail {

/// Greedy cover. Without multipliers the score of column j is c_j / μ_j (μ_j = rows of j
/// still uncovered). With multipliers u it is CFT's score on γ_j = c_j − Σ_{uncovered i ∈ j} u_i:
/// γ_j / μ_j if γ_j > 0, else γ_j · μ_j. Only columns with allowed[j] != 0 are used (all when
/// `allowed` is empty); the columns in `start` are taken first. γ_j is kept up to date as
/// rows get covered (c_j minus all of j's multipliers, then u_i added back when row i is
/// covered), so it may differ from a fresh sum in the last bits. Both scores only grow as
/// rows get covered, which makes lazy evaluation exact. Result has redundant columns removed.
/// \pre the allowed columns cover every row; no multiplier is negative.
std::vector<std::int32_t> greedy_cover(const Instance& inst, std::span<const double> u = {},
                                       std::span<const char> allowed = {},
                                       std::span<const std::int32_t> start = {});

/// greedy_cover with multipliers (u not empty), the allowed columns queued in batches in
/// the order of their first scores, `batch` at a time (at least one). The batches
/// change how fast it runs, never the columns it takes: greedy_cover queues a sixteenth of
/// the columns, or 256, at a time; the tests fewer.
std::vector<std::int32_t> lagrangian_greedy(const Instance& inst, std::span<const double> u,
                                            std::span<const char> allowed,
                                            std::span<const std::int32_t> start,
                                            std::size_t batch);

/// Removes columns whose rows are all covered by others, most expensive first (ties: larger
/// index first), so the result is a minimal cover.
void remove_redundant(const Instance& inst, std::vector<std::int32_t>& cols);

}  // namespace rstruct::setcover::detail
