#pragma once
/// \file
/// Symbolic perturbation of the lifted determinants (see predicates.hpp): the weight of
/// the point with id i becomes w_i + ε^(i+1). The lifted determinant of points
/// p_0, ..., p_m (rows (p, |p|² − w_p, 1)) is linear in each lifting height, with the
/// cofactor of p_k equal to ±(orientation of the other points); the perturbed sign is the
/// unperturbed one if non-zero, else decided by the non-zero cofactor of smallest id.

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>

#include "rstruct/core/error.hpp"

namespace rstruct::predicates::detail {

/// Positions 0..N−1 sorted by increasing id (largest perturbation first).
/// \throws InvalidInput if two ids are equal.
template <std::size_t N>
std::array<int, N> perturbation_order(const std::array<std::uint32_t, N>& ids,
                                      const char* where) {
  std::array<int, N> order;
  for (std::size_t i = 0; i < N; ++i) order[i] = static_cast<int>(i);
  std::sort(order.begin(), order.end(), [&](int x, int y) {
    return ids[static_cast<std::size_t>(x)] < ids[static_cast<std::size_t>(y)];
  });
  for (std::size_t i = 1; i < N; ++i) {
    if (ids[static_cast<std::size_t>(order[i])] == ids[static_cast<std::size_t>(order[i - 1])]) {
      throw InvalidInput(std::string("predicates::") + where +
                         ": two points share the perturbation id " +
                         std::to_string(ids[static_cast<std::size_t>(order[i])]));
    }
  }
  return order;
}

}  // namespace rstruct::predicates::detail
