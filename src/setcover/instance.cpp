#include "rstruct/setcover/instance.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <sstream>

#include "rstruct/core/error.hpp"
#include "rstruct/core/parallel.hpp"

namespace rstruct::setcover {

namespace {

/// Instances with at least this many entries are checked and transposed on several
/// threads (when the caller gives them).
constexpr std::size_t kParallelEntries = std::size_t{1} << 20;

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

/// Whether every column's rows are increasing and in [0, num_rows), on `threads` threads.
bool columns_are_clean(std::int32_t num_rows, const std::vector<std::int64_t>& col_start,
                       const std::vector<std::int32_t>& col_rows, unsigned threads) {
  std::atomic<bool> clean{true};
  parallel_chunks(col_start.size() - 1, threads, std::size_t{1} << 14,
                  [&](std::size_t begin, std::size_t end, unsigned) {
                    for (std::size_t j = begin; j < end; ++j) {
                      std::int32_t previous = -1;
                      for (auto k = static_cast<std::size_t>(col_start[j]);
                           k < static_cast<std::size_t>(col_start[j + 1]); ++k) {
                        if (col_rows[k] <= previous || col_rows[k] >= num_rows) {
                          clean.store(false, std::memory_order_relaxed);
                          return;
                        }
                        previous = col_rows[k];
                      }
                    }
                  });
  return clean.load();
}

/// Every column sorted and without repeats, in place: entries move down over the repeats
/// removed before them (none, usually: then nothing moves).
/// \throws InvalidInput on a row outside [0, num_rows).
void normalize_columns(std::int32_t num_rows, std::vector<std::int64_t>& col_start,
                       std::vector<std::int32_t>& col_rows) {
  const std::size_t num_cols = col_start.size() - 1;
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
                            std::span<const std::int32_t> col_rows, std::vector<double> costs,
                            unsigned threads) {
  return from_csr(num_rows, std::vector<std::int64_t>(col_start.begin(), col_start.end()),
                  std::vector<std::int32_t>(col_rows.begin(), col_rows.end()), std::move(costs),
                  threads);
}

Instance Instance::from_csr(std::int32_t num_rows, std::vector<std::int64_t>&& col_start,
                            std::vector<std::int32_t>&& col_rows, std::vector<double> costs,
                            unsigned threads) {
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
  // Large instances are checked on all threads first: when every column is increasing and
  // in range (as the covering sets give them), nothing is left to do in one pass.
  const bool parallel = col_rows.size() >= kParallelEntries && thread_count(threads, 2) > 1;
  if (!parallel || !columns_are_clean(num_rows, col_start, col_rows, threads)) {
    normalize_columns(num_rows, col_start, col_rows);
  }
  Instance inst;
  inst.num_rows_ = num_rows;
  inst.costs_ = std::move(costs);
  inst.col_start_ = std::move(col_start);
  inst.col_rows_ = std::move(col_rows);
  inst.build_rows(parallel ? threads : 1);
  inst.classify_costs();
  return inst;
}

// The rows: a counting sort of the entries by row. With several threads each takes a
// stretch of columns holding about as many entries, counts its entries per row, and
// writes them after those of the stretches before it: every row lists its columns in
// increasing order, as one thread writes them.
void Instance::build_rows(unsigned threads) {
  const auto rows = static_cast<std::size_t>(num_rows_);
  const std::size_t entries = col_rows_.size();
  const unsigned t = thread_count(threads, entries, kParallelEntries / 4);
  // Stretch s: columns [first[s], first[s + 1]).
  std::vector<std::int32_t> first(t + 1, num_cols());
  for (unsigned s = 0; s < t; ++s) {
    const auto at = static_cast<std::int64_t>(entries * s / t);
    first[s] = static_cast<std::int32_t>(
        std::lower_bound(col_start_.begin(), col_start_.end() - 1, at) - col_start_.begin());
  }
  // Per stretch and row: the count, then where the stretch's next entry of the row goes.
  std::vector<std::vector<std::int64_t>> next(t);
  parallel_chunks(t, t, 1, [&](std::size_t s, std::size_t, unsigned) {
    next[s].assign(rows, 0);
    for (std::int32_t j = first[s]; j < first[s + 1]; ++j) {
      for (const std::int32_t r : column(j)) ++next[s][static_cast<std::size_t>(r)];
    }
  });
  row_start_.assign(rows + 1, 0);
  std::int64_t total = 0;
  for (std::size_t r = 0; r < rows; ++r) {
    row_start_[r] = total;
    for (unsigned s = 0; s < t; ++s) {
      const std::int64_t count = next[s][r];
      next[s][r] = total;
      total += count;
    }
  }
  row_start_[rows] = total;
  row_cols_.resize(entries);
  parallel_chunks(t, t, 1, [&](std::size_t s, std::size_t, unsigned) {
    std::vector<std::int64_t>& at = next[s];
    for (std::int32_t j = first[s]; j < first[s + 1]; ++j) {
      for (const std::int32_t r : column(j)) row_cols_[static_cast<std::size_t>(at[r]++)] = j;
    }
  });
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
