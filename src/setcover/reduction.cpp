#include "reduction.hpp"

#include <algorithm>
#include <numeric>

#include "rstruct/core/assert.hpp"

namespace rstruct::setcover::detail {

namespace {

/// Alive flags and alive counts over the original instance.
class Presolver {
 public:
  Presolver(const Instance& inst, double deadline, const Stopwatch& clock, std::int64_t work_limit)
      : inst_(inst),
        deadline_(deadline),
        work_limit_(work_limit),
        clock_(clock),
        row_alive_(static_cast<std::size_t>(inst.num_rows()), 1),
        col_alive_(static_cast<std::size_t>(inst.num_cols()), 1),
        row_len_(static_cast<std::size_t>(inst.num_rows())),
        col_len_(static_cast<std::size_t>(inst.num_cols())),
        mark_(static_cast<std::size_t>(std::max(inst.num_rows(), inst.num_cols())), 0) {
    for (std::int32_t i = 0; i < inst.num_rows(); ++i) row_len_[i] = static_cast<std::int32_t>(inst.row(i).size());
    for (std::int32_t j = 0; j < inst.num_cols(); ++j) col_len_[j] = static_cast<std::int32_t>(inst.column(j).size());
  }

  /// 64-bit Bloom signatures of the alive columns of every row and alive rows of every
  /// column, for a cheap "cannot be a subset" test. Sets only shrink during a pass, so a
  /// signature taken at the pass start over-approximates: it can hide a domination (less
  /// reduction) but never fake one (the exact count below decides).
  void take_signatures() {
    row_sig_.assign(static_cast<std::size_t>(inst_.num_rows()), 0);
    col_sig_.assign(static_cast<std::size_t>(inst_.num_cols()), 0);
    for (std::int32_t j = 0; j < inst_.num_cols(); ++j) {
      if (!col_alive_[j]) continue;
      for (std::int32_t i : inst_.column(j)) {
        if (!row_alive_[i]) continue;
        row_sig_[i] |= bit(j);
        col_sig_[j] |= bit(i);
      }
    }
  }
  static std::uint64_t bit(std::int32_t x) {
    return std::uint64_t{1} << ((static_cast<std::uint64_t>(x) * 0x9E3779B97F4A7C15ULL) >> 58);
  }

  void kill_col(std::int32_t j) {
    col_alive_[j] = 0;
    for (std::int32_t i : inst_.column(j)) --row_len_[i];
  }
  void kill_row(std::int32_t i) {
    row_alive_[i] = 0;
    for (std::int32_t j : inst_.row(i)) {
      if (--col_len_[j] == 0 && col_alive_[j]) kill_col(j);
    }
  }
  /// Takes column j into every solution: its rows are covered.
  void fix_col(std::int32_t j) {
    out.fixed_cols.push_back(j);
    kill_col(j);
    for (std::int32_t i : inst_.column(j)) {
      if (row_alive_[i]) kill_row(i);
    }
  }

  void take_zero_cost() {
    for (std::int32_t j = 0; j < inst_.num_cols(); ++j) {
      if (col_len_[j] == 0) col_alive_[j] = 0;
    }
    for (std::int32_t j = 0; j < inst_.num_cols(); ++j) {
      if (col_alive_[j] && inst_.cost(j) == 0.0) fix_col(j);
    }
  }

  bool force_singletons() {
    bool changed = false;
    for (std::int32_t i = 0; i < inst_.num_rows(); ++i) {
      if (!row_alive_[i] || row_len_[i] != 1) continue;
      std::int32_t j = -1;
      for (std::int32_t k : inst_.row(i)) {
        if (col_alive_[k]) j = k;
      }
      RSTRUCT_ASSERT(j >= 0);
      out.forced_multipliers.emplace_back(i, inst_.cost(j));
      ++out.forced_cols;
      fix_col(j);
      changed = true;
    }
    return changed;
  }

  /// Column j is dominated by k when its alive rows are a subset of k's and c_k <= c_j
  /// (identical columns: the larger index goes).
  bool remove_dominated_cols() {
    bool changed = false;
    for (std::int32_t j = 0; j < inst_.num_cols(); ++j) {
      if (!col_alive_[j]) continue;
      if (out_of_work() || ((j & 1023) == 0 && out_of_time())) break;
      std::int32_t pivot = -1;
      for (std::int32_t i : inst_.column(j)) {
        if (row_alive_[i] && (pivot < 0 || row_len_[i] < row_len_[pivot])) pivot = i;
      }
      for (std::int32_t i : inst_.column(j)) mark_[i] = row_alive_[i];
      work_ += 3 * static_cast<std::int64_t>(inst_.column(j).size()) +
               static_cast<std::int64_t>(inst_.row(pivot).size());
      bool dominated = false;
      for (std::int32_t k : inst_.row(pivot)) {
        if (k == j || !col_alive_[k] || col_len_[k] < col_len_[j] || inst_.cost(k) > inst_.cost(j)) continue;
        if (col_len_[k] == col_len_[j] && inst_.cost(k) == inst_.cost(j) && k > j) continue;
        if ((col_sig_[j] & ~col_sig_[k]) != 0) continue;
        work_ += static_cast<std::int64_t>(inst_.column(k).size());
        std::int32_t hits = 0;
        for (std::int32_t i : inst_.column(k)) hits += mark_[i];
        if (hits == col_len_[j]) {
          dominated = true;
          break;
        }
      }
      for (std::int32_t i : inst_.column(j)) mark_[i] = 0;
      if (dominated) {
        kill_col(j);
        ++out.dominated_cols;
        changed = true;
      }
    }
    return changed;
  }

  /// Row i is dominated by row k when k's alive columns are a subset of i's: covering k
  /// covers i. Identical rows: the larger index goes.
  bool remove_dominated_rows() {
    bool changed = false;
    for (std::int32_t k = 0; k < inst_.num_rows(); ++k) {
      if (!row_alive_[k]) continue;
      if (out_of_work() || ((k & 1023) == 0 && out_of_time())) break;
      std::int32_t pivot = -1;
      for (std::int32_t j : inst_.row(k)) {
        if (col_alive_[j] && (pivot < 0 || col_len_[j] < col_len_[pivot])) pivot = j;
      }
      for (std::int32_t j : inst_.row(k)) mark_[j] = col_alive_[j];
      work_ += 3 * static_cast<std::int64_t>(inst_.row(k).size()) +
               static_cast<std::int64_t>(inst_.column(pivot).size());
      for (std::int32_t i : inst_.column(pivot)) {
        if (i == k || !row_alive_[i] || row_len_[i] < row_len_[k]) continue;
        if (row_len_[i] == row_len_[k] && i < k) continue;
        if ((row_sig_[k] & ~row_sig_[i]) != 0) continue;
        work_ += static_cast<std::int64_t>(inst_.row(i).size());
        std::int32_t hits = 0;
        for (std::int32_t j : inst_.row(i)) hits += mark_[j];
        if (hits == row_len_[k]) {
          kill_row(i);
          ++out.dominated_rows;
          changed = true;
        }
      }
      for (std::int32_t j : inst_.row(k)) mark_[j] = 0;
    }
    return changed;
  }

  void split_components();
  bool out_of_time() {
    if (clock_.seconds() > deadline_) out.timed_out = true;
    return out.timed_out;
  }
  /// Deterministic: the entries scanned so far (a count, not seconds).
  bool out_of_work() {
    if (work_limit_ > 0 && work_ > work_limit_) out.work_limited = true;
    return out.work_limited;
  }
  std::int64_t work() const { return work_; }

  Reduction out;

 private:
  const Instance& inst_;
  double deadline_;
  std::int64_t work_limit_;
  std::int64_t work_ = 0;
  const Stopwatch& clock_;
  std::vector<char> row_alive_, col_alive_;
  std::vector<std::int32_t> row_len_, col_len_;
  std::vector<std::int32_t> mark_;
  std::vector<std::uint64_t> row_sig_, col_sig_;
};

std::int32_t find_root(std::vector<std::int32_t>& parent, std::int32_t x) {
  while (parent[x] != x) {
    parent[x] = parent[parent[x]];
    x = parent[x];
  }
  return x;
}

void Presolver::split_components() {
  const std::int32_t m = inst_.num_rows();
  std::vector<std::int32_t> parent(static_cast<std::size_t>(m));
  std::iota(parent.begin(), parent.end(), 0);
  for (std::int32_t j = 0; j < inst_.num_cols(); ++j) {
    if (!col_alive_[j]) continue;
    std::int32_t first = -1;
    for (std::int32_t i : inst_.column(j)) {
      if (!row_alive_[i]) continue;
      if (first < 0) {
        first = find_root(parent, i);
      } else {
        const std::int32_t r = find_root(parent, i);
        if (r != first) parent[r] = first;
      }
    }
  }
  std::vector<std::int32_t> comp_of_root(static_cast<std::size_t>(m), -1);
  std::vector<std::int32_t> local(static_cast<std::size_t>(m), -1);
  for (std::int32_t i = 0; i < m; ++i) {
    if (!row_alive_[i]) continue;
    const std::int32_t r = find_root(parent, i);
    if (comp_of_root[r] < 0) {
      comp_of_root[r] = static_cast<std::int32_t>(out.components.size());
      out.components.emplace_back();
    }
    auto& c = out.components[static_cast<std::size_t>(comp_of_root[r])];
    local[i] = static_cast<std::int32_t>(c.rows.size());
    c.rows.push_back(i);
  }
  std::vector<std::vector<std::int64_t>> starts(out.components.size(), std::vector<std::int64_t>{0});
  std::vector<std::vector<std::int32_t>> entries(out.components.size());
  std::vector<std::vector<double>> costs(out.components.size());
  // Calls entry(comp, i) for every alive row i of column j, comp being i's component, and
  // returns the column's component (−1: no alive row).
  const auto visit = [&](std::int32_t j, auto&& entry) {
    std::int32_t comp = -1;
    for (std::int32_t i : inst_.column(j)) {
      if (!row_alive_[i]) continue;
      comp = comp_of_root[find_root(parent, i)];
      entry(comp, i);
    }
    return comp;
  };
  {
    // Exact sizes first: grown by doubling, the arrays would take about twice their size in
    // fresh memory (10^6 torus samples: 2.5·10^7 entries in one component).
    std::vector<std::int64_t> entry_count(out.components.size(), 0);
    std::vector<std::int32_t> col_count(out.components.size(), 0);
    for (std::int32_t j = 0; j < inst_.num_cols(); ++j) {
      if (!col_alive_[j]) continue;
      const std::int32_t comp = visit(j, [&](std::int32_t c, std::int32_t) { ++entry_count[c]; });
      if (comp >= 0) ++col_count[comp];
    }
    for (std::size_t c = 0; c < out.components.size(); ++c) {
      entries[c].reserve(static_cast<std::size_t>(entry_count[c]));
      starts[c].reserve(static_cast<std::size_t>(col_count[c]) + 1);
      costs[c].reserve(static_cast<std::size_t>(col_count[c]));
      out.components[c].cols.reserve(static_cast<std::size_t>(col_count[c]));
    }
  }
  for (std::int32_t j = 0; j < inst_.num_cols(); ++j) {
    if (!col_alive_[j]) continue;
    const std::int32_t comp =
        visit(j, [&](std::int32_t c, std::int32_t i) { entries[c].push_back(local[i]); });
    RSTRUCT_ASSERT(comp >= 0);
    starts[comp].push_back(static_cast<std::int64_t>(entries[comp].size()));
    costs[comp].push_back(inst_.cost(j));
    out.components[comp].cols.push_back(j);
  }
  for (std::size_t c = 0; c < out.components.size(); ++c) {
    auto& comp = out.components[c];
    comp.instance = Instance::from_csr(static_cast<std::int32_t>(comp.rows.size()),
                                       std::move(starts[c]), std::move(entries[c]),
                                       std::move(costs[c]));
  }
}

}  // namespace

Reduction reduce(const Instance& inst, bool use_domination, double deadline, const Stopwatch& clock,
                 std::int64_t work_limit) {
  Presolver p(inst, deadline, clock, work_limit);
  p.take_zero_cost();
  p.force_singletons();
  // Domination passes are the expensive part: two rounds catch nearly everything.
  for (int pass = 0; use_domination && pass < 2 && !p.out_of_time() && !p.out_of_work(); ++pass) {
    p.take_signatures();
    bool changed = p.remove_dominated_rows();
    p.take_signatures();
    changed = p.remove_dominated_cols() || changed;
    changed = p.force_singletons() || changed;
    if (!changed) break;
  }
  while (p.force_singletons()) {
  }
  p.split_components();
  p.out.work = p.work();
  return std::move(p.out);
}

}  // namespace rstruct::setcover::detail
