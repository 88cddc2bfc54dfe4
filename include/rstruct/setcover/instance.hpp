#pragma once
/// \file
/// A set-cover instance (paper §6: pruning surface and medial balls is a set-cover problem;
/// issue 6). Rows are the elements to cover (samples), columns the candidate sets (balls).
/// Stored twice, column-major and row-major (compressed sparse columns and rows), so that
/// both "rows of column j" and "columns covering row i" are contiguous spans.

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "rstruct/core/huge_page_allocator.hpp"

namespace rstruct::setcover {

/// Immutable set-cover instance: minimise Σ c_j x_j subject to Σ_{j ∋ i} x_j ≥ 1 for every
/// row i, x ∈ {0,1}ⁿ. Costs are finite doubles ≥ 0 (integers are represented exactly up to
/// 2⁵³). A column's rows are sorted and free of duplicates.
class Instance {
 public:
  Instance() = default;

  /// Builds from one row list per column (0-based rows). `costs` empty means unicost.
  /// Duplicate rows inside a column are merged.
  /// \throws InvalidInput on a row outside [0, num_rows), a cost that is negative, NaN or
  /// infinite, or a cost vector whose size is not the number of columns.
  static Instance from_columns(std::int32_t num_rows,
                               const std::vector<std::vector<std::int32_t>>& columns,
                               std::vector<double> costs = {});

  /// Builds from compressed sparse columns: column j covers rows
  /// col_rows[col_start[j] .. col_start[j+1]). `costs` empty means unicost.
  /// \throws InvalidInput as from_columns, and on a col_start that is not a non-decreasing
  /// sequence from 0 to col_rows.size().
  /// `threads` (0: all) check and transpose a large instance.
  static Instance from_csr(std::int32_t num_rows, std::span<const std::int64_t> col_start,
                           std::span<const std::int32_t> col_rows, std::vector<double> costs = {},
                           unsigned threads = 1);
  /// The same, taking over the arrays instead of copying them (an instance of 10^6 samples'
  /// shrunk balls has 2.5·10^7 entries: each copy is 100 MB of fresh memory).
  static Instance from_csr(std::int32_t num_rows, std::vector<std::int64_t>&& col_start,
                           std::vector<std::int32_t>&& col_rows, std::vector<double> costs = {},
                           unsigned threads = 1);

  std::int32_t num_rows() const { return num_rows_; }
  std::int32_t num_cols() const { return static_cast<std::int32_t>(costs_.size()); }
  std::int64_t num_entries() const { return static_cast<std::int64_t>(col_rows_.size()); }

  /// Rows covered by column j, sorted increasingly.
  std::span<const std::int32_t> column(std::int32_t j) const {
    return {col_rows_.data() + col_start_[j], col_rows_.data() + col_start_[j + 1]};
  }
  /// Columns covering row i, sorted increasingly.
  std::span<const std::int32_t> row(std::int32_t i) const {
    return {row_cols_.data() + row_start_[i], row_cols_.data() + row_start_[i + 1]};
  }
  double cost(std::int32_t j) const { return costs_[j]; }
  const std::vector<double>& costs() const { return costs_; }

  /// True when every cost is 1.
  bool is_unicost() const { return unicost_; }
  /// True when every cost is an integer (then optimal costs are integers and a lower bound
  /// may be rounded up).
  bool has_integer_costs() const { return integer_costs_; }

  /// The same sets with every cost 1.
  Instance with_unit_costs() const;

  /// Index of the first row that no column covers, or -1 when every row can be covered.
  std::int32_t first_uncoverable_row() const;

  /// True when `cols` (any order, duplicates allowed) covers every row.
  bool is_cover(std::span<const std::int32_t> cols) const;

  /// Σ costs of `cols` (each counted once per occurrence).
  double cost_of(std::span<const std::int32_t> cols) const;

  /// Structural consistency: both directions hold the same entries, sorted, in range.
  bool is_valid() const;

  /// Short human-readable size summary ("200 rows, 1000 columns, 4000 entries, unicost").
  std::string summary() const;

 private:
  void build_rows(unsigned threads);
  void classify_costs();

  std::int32_t num_rows_ = 0;
  std::vector<std::int64_t> col_start_{0};
  std::vector<std::int32_t> col_rows_;
  std::vector<std::int64_t> row_start_{0};
  // Default-initialised (the transposition writes every entry, on several threads).
  std::vector<std::int32_t, HugePageAllocator<std::int32_t>> row_cols_;
  std::vector<double> costs_;
  bool unicost_ = true;
  bool integer_costs_ = true;
};

}  // namespace rstruct::setcover
