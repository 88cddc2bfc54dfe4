#include "rstruct/setcover/instance.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>

#include "rstruct/core/error.hpp"

namespace rstruct::setcover {

namespace {

void check_costs(std::vector<double>& costs, std::size_t num_cols) {
  if (costs.empty()) {
    costs.assign(num_cols, 1.0);
    return;
  }
  if (costs.size() != num_cols) {
    throw InvalidInput("set cover: " + std::to_string(costs.size()) + " costs given for " +
                       std::to_string(num_cols) + " columns");
  }
  for (std::size_t j = 0; j < costs.size(); ++j) {
    if (!std::isfinite(costs[j]) || costs[j] < 0.0) {
      std::ostringstream msg;
      msg << "set cover: column " << j << " has cost " << costs[j]
          << " (costs must be finite and >= 0)";
      throw InvalidInput(msg.str());
    }
  }
}

}  // namespace

Instance Instance::from_columns(std::int32_t num_rows,
                                const std::vector<std::vector<std::int32_t>>& columns,
                                std::vector<double> costs) {
  std::vector<std::int64_t> start{0};
  std::vector<std::int32_t> rows;
  for (const auto& c : columns) {
    rows.insert(rows.end(), c.begin(), c.end());
    start.push_back(static_cast<std::int64_t>(rows.size()));
  }
  return from_csr(num_rows, start, rows, std::move(costs));
}

Instance Instance::from_csr(std::int32_t num_rows, std::span<const std::int64_t> col_start,
                            std::span<const std::int32_t> col_rows, std::vector<double> costs) {
  return from_csr(num_rows, std::vector<std::int64_t>(col_start.begin(), col_start.end()),
                  std::vector<std::int32_t>(col_rows.begin(), col_rows.end()), std::move(costs));
}

Instance Instance::from_csr(std::int32_t num_rows, std::vector<std::int64_t>&& col_start,
                            std::vector<std::int32_t>&& col_rows, std::vector<double> costs) {
  if (num_rows < 0) throw InvalidInput("set cover: negative number of rows");
  if (col_start.empty() || col_start.front() != 0 ||
      col_start.back() != static_cast<std::int64_t>(col_rows.size())) {
    throw InvalidInput("set cover: column offsets must run from 0 to the number of entries");
  }
  const std::size_t num_cols = col_start.size() - 1;
  if (num_cols > static_cast<std::size_t>(INT32_MAX)) {
    throw InvalidInput("set cover: too many columns");
  }
  // All offsets first: a later decrease would otherwise let an earlier column read past
  // the entries.
  for (std::size_t j = 0; j < num_cols; ++j) {
    if (col_start[j + 1] < col_start[j]) {
      throw InvalidInput("set cover: column offsets decrease at column " + std::to_string(j));
    }
  }
  check_costs(costs, num_cols);
  // Every column sorted and without repeats, in place: entries move down over the repeats
  // removed before them (none, usually: then nothing moves).
  std::size_t write = 0;
  std::size_t read = 0;  // column j's first entry as given (col_start[j] is rewritten)
  for (std::size_t j = 0; j < num_cols; ++j) {
    const auto end = static_cast<std::size_t>(col_start[j + 1]);
    const std::size_t first = write;
    for (std::size_t k = read; k < end; ++k) {
      const std::int32_t r = col_rows[k];
      if (r < 0 || r >= num_rows) {
        throw InvalidInput("set cover: column " + std::to_string(j) + " names row " +
                           std::to_string(r) + ", outside [0, " + std::to_string(num_rows) +
                           ")");
      }
      col_rows[write++] = r;
    }
    const auto begin = col_rows.begin() + static_cast<std::ptrdiff_t>(first);
    auto stop = col_rows.begin() + static_cast<std::ptrdiff_t>(write);
    if (std::adjacent_find(begin, stop, std::greater_equal<>()) != stop) {  // not increasing
      std::sort(begin, stop);
      stop = std::unique(begin, stop);
      write = static_cast<std::size_t>(stop - col_rows.begin());
    }
    col_start[j + 1] = static_cast<std::int64_t>(write);
    read = end;
  }
  col_rows.resize(write);
  Instance inst;
  inst.num_rows_ = num_rows;
  inst.costs_ = std::move(costs);
  inst.col_start_ = std::move(col_start);
  inst.col_rows_ = std::move(col_rows);
  inst.build_rows();
  inst.classify_costs();
  return inst;
}

void Instance::build_rows() {
  row_start_.assign(static_cast<std::size_t>(num_rows_) + 1, 0);
  for (std::int32_t r : col_rows_) ++row_start_[static_cast<std::size_t>(r) + 1];
  for (std::size_t i = 0; i < static_cast<std::size_t>(num_rows_); ++i) {
    row_start_[i + 1] += row_start_[i];
  }
  row_cols_.assign(col_rows_.size(), 0);
  std::vector<std::int64_t> fill(row_start_.begin(), row_start_.end() - 1);
  for (std::int32_t j = 0; j < num_cols(); ++j) {
    for (std::int32_t r : column(j)) row_cols_[static_cast<std::size_t>(fill[r]++)] = j;
  }
}

void Instance::classify_costs() {
  unicost_ = true;
  integer_costs_ = true;
  for (double c : costs_) {
    if (c != 1.0) unicost_ = false;
    if (c != std::floor(c) || c > 9007199254740992.0) integer_costs_ = false;
  }
}

Instance Instance::with_unit_costs() const {
  Instance copy = *this;
  copy.costs_.assign(costs_.size(), 1.0);
  copy.unicost_ = true;
  copy.integer_costs_ = true;
  return copy;
}

std::int32_t Instance::first_uncoverable_row() const {
  for (std::int32_t i = 0; i < num_rows_; ++i) {
    if (row_start_[i] == row_start_[i + 1]) return i;
  }
  return -1;
}

bool Instance::is_cover(std::span<const std::int32_t> cols) const {
  std::vector<char> covered(static_cast<std::size_t>(num_rows_), 0);
  for (std::int32_t j : cols) {
    if (j < 0 || j >= num_cols()) return false;
    for (std::int32_t r : column(j)) covered[r] = 1;
  }
  return std::all_of(covered.begin(), covered.end(), [](char c) { return c != 0; });
}

double Instance::cost_of(std::span<const std::int32_t> cols) const {
  double total = 0.0;
  for (std::int32_t j : cols) total += costs_[j];
  return total;
}

bool Instance::is_valid() const {
  if (col_start_.size() != costs_.size() + 1) return false;
  if (row_start_.size() != static_cast<std::size_t>(num_rows_) + 1) return false;
  if (col_rows_.size() != row_cols_.size()) return false;
  std::int64_t seen = 0;
  for (std::int32_t j = 0; j < num_cols(); ++j) {
    auto rows = column(j);
    for (std::size_t k = 0; k < rows.size(); ++k) {
      if (rows[k] < 0 || rows[k] >= num_rows_) return false;
      if (k > 0 && rows[k - 1] >= rows[k]) return false;
      auto cols = row(rows[k]);
      if (!std::binary_search(cols.begin(), cols.end(), j)) return false;
      ++seen;
    }
  }
  return seen == static_cast<std::int64_t>(row_cols_.size());
}

std::string Instance::summary() const {
  std::ostringstream out;
  out << num_rows_ << " rows, " << num_cols() << " columns, " << num_entries() << " entries, "
      << (unicost_ ? "unicost" : (integer_costs_ ? "integer costs" : "real costs"));
  return out.str();
}

}  // namespace rstruct::setcover
