#pragma once
/// \file
/// Covering sets of the pruning step (paper §6, DESIGN.md §2): which balls cover which
/// points, as a set-cover matrix in compressed sparse column form. Columns are candidate
/// balls, rows are points (samples). Column j covers row i iff |p_i − c_j| ≤ r_j, decided
/// exactly (predicates::side_of_ball ≤ 0) for the double radius r_j: the only rounding is in
/// the radius itself (e.g. fl(ρ̃·D̂(u))), never in the membership decision.
///
/// Candidates come from a kd-tree radius search over the points with a slightly inflated
/// radius; the exact predicate then decides each candidate.

#include <cstdint>
#include <span>
#include <vector>

#include "rstruct/geometry/vec3.hpp"

namespace rstruct::poles {

/// Compressed sparse columns: column j covers rows[column_offsets[j] .. column_offsets[j+1]),
/// sorted increasingly, without duplicates. Offsets are 64-bit (entry counts of medial-axis
/// instances can be large), rows 32-bit.
struct CoveringSets {
  std::uint32_t row_count = 0;
  std::vector<std::uint64_t> column_offsets{0};
  std::vector<std::uint32_t> rows;

  std::size_t column_count() const { return column_offsets.size() - 1; }
  std::size_t entry_count() const { return rows.size(); }
  /// Rows covered by column j.
  std::span<const std::uint32_t> column(std::size_t j) const {
    return {rows.data() + column_offsets[j], rows.data() + column_offsets[j + 1]};
  }
  /// Offsets start at 0, never decrease and end at rows.size(); each column's rows are
  /// strictly increasing and < row_count.
  bool is_valid() const;
  /// Number of rows that no column covers.
  std::size_t uncovered_row_count() const;
};

/// Covering sets of `balls` (columns, in order) over `points` (rows, in order).
/// `threads` = 0 picks std::thread::hardware_concurrency(); 1 runs in the calling thread.
/// \throws InvalidInput if a ball has a negative or non-finite radius or centre, or a point is
/// not finite; or if there are 2³² or more points.
CoveringSets covering_sets(std::span<const Ball> balls, std::span<const Point3> points,
                           unsigned threads = 0);

/// Reference implementation for tests: every (ball, point) pair with the exact predicate.
CoveringSets covering_sets_brute_force(std::span<const Ball> balls,
                                       std::span<const Point3> points);

}  // namespace rstruct::poles
