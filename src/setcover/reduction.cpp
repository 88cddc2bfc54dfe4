#include "reduction.hpp"

#include <algorithm>
#include <limits>
#include <numeric>

#include "rstruct/core/assert.hpp"
#include "rstruct/core/parallel.hpp"

namespace rstruct::setcover::detail {

namespace {

/// Items per round of a domination pass, and per parallel chunk of a round.
constexpr std::int32_t kRound = 1 << 16;
constexpr std::size_t kChunk = 1 << 10;
/// Rows or columns per parallel chunk of the signatures and of the components' copy (and
/// the columns of a component copied on all threads).
constexpr std::size_t kListChunk = 1 << 14;

/// Alive flags and alive counts over the original instance.
class Presolver {
 public:
  Presolver(const Instance& inst, double deadline, const Stopwatch& clock, std::int64_t work_limit,
            unsigned threads)
      : inst_(inst),
        deadline_(deadline),
        work_limit_(work_limit),
        threads_(thread_count(threads, std::numeric_limits<std::size_t>::max())),
        clock_(clock),
        row_alive_(static_cast<std::size_t>(inst.num_rows()), 1),
        col_alive_(static_cast<std::size_t>(inst.num_cols()), 1),
        row_len_(static_cast<std::size_t>(inst.num_rows())),
        col_len_(static_cast<std::size_t>(inst.num_cols())),
        mark_size_(static_cast<std::size_t>(std::max(inst.num_rows(), inst.num_cols()))),
        marks_(threads_) {
    for (std::int32_t i = 0; i < inst.num_rows(); ++i) row_len_[i] = static_cast<std::int32_t>(inst.row(i).size());
    for (std::int32_t j = 0; j < inst.num_cols(); ++j) col_len_[j] = static_cast<std::int32_t>(inst.column(j).size());
  }

  /// 64-bit Bloom signatures of the alive columns of every row (`rows`) or of the alive
  /// rows of every column (otherwise), for a cheap "cannot be a subset" test. Sets only
  /// shrink during a pass, so a signature taken at the pass start over-approximates: it can
  /// hide a domination (less reduction) but never fake one (the exact count below decides).
  /// Each item on its own (from the instance's lists), so that the loop runs on all
  /// threads without sharing a word. Only the kind the next pass reads (both were taken
  /// before each pass, 4 × 0.06 s of the 10^6-sample torus level's reduction on two
  /// threads): 5·10^5 torus samples, one thread, 6 simultaneous pinned pairs with the cores
  /// swapped, reduction 0.560-0.582 s (median 0.569) -> 0.495-0.566 s (median 0.512), the
  /// same output.
  void take_signatures(bool rows) {
    // sig[x] = the bits of the alive members of item x's list (0 for a dead item).
    const auto sign = [&](std::vector<std::uint64_t>& sig, const std::vector<char>& alive,
                          const std::vector<char>& member_alive, auto&& list) {
      sig.resize(alive.size());
      parallel_chunks(sig.size(), threads_, kListChunk,
                      [&](std::size_t begin, std::size_t end, unsigned) {
                        for (std::size_t x = begin; x < end; ++x) {
                          std::uint64_t bits = 0;
                          if (alive[x]) {
                            for (std::int32_t y : list(static_cast<std::int32_t>(x))) {
                              if (member_alive[y]) bits |= bit(y);
                            }
                          }
                          sig[x] = bits;
                        }
                      });
    };
    if (rows) {
      sign(row_sig_, row_alive_, col_alive_, [&](std::int32_t i) { return inst_.row(i); });
    } else {
      sign(col_sig_, col_alive_, row_alive_, [&](std::int32_t j) { return inst_.column(j); });
    }
  }
  /// The first alive member of `list` whose alive count is least (−1 if none is alive),
  /// with a conditional move per member rather than a branch.
  static std::int32_t shortest_alive(std::span<const std::int32_t> list,
                                     const std::vector<char>& alive,
                                     const std::vector<std::int32_t>& len) {
    std::int32_t pivot = -1;
    std::int32_t least = std::numeric_limits<std::int32_t>::max();
    for (const std::int32_t x : list) {
      const bool better = (alive[x] != 0) & (len[x] < least);
      pivot = better ? x : pivot;
      least = better ? len[x] : least;
    }
    return pivot;
  }
  /// Whether a candidate (another item, alive) can contain the checked item's list: at
  /// least as long, no costlier, not tied with it on both where `loses_tie`, and its
  /// signature `big` covering `small`. Evaluated without short-circuit: the candidates'
  /// outcomes are hard to predict (10^6 torus samples: 0.66 million of the 20.6 million
  /// candidates that reach the signature test pass it), so one branch on the whole instead
  /// of one per test. One thread, 500,000 torus samples, 2 simultaneous pinned pairs with
  /// the cores swapped: reduction 0.78 / 0.64 s -> 0.71 / 0.58 s, the same output.
  static bool candidate_passes(bool other, bool alive, std::int32_t len, std::int32_t checked_len,
                               double cost, double checked_cost, bool loses_tie,
                               std::uint64_t small, std::uint64_t big) {
    const bool tie = (len == checked_len) & (cost == checked_cost) & loses_tie;
    return other & alive & (len >= checked_len) & (cost <= checked_cost) & !tie &
           ((small & ~big) == 0);
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
  /// (identical columns: the larger index goes). Every dominated column has an undominated
  /// dominator (a strict partial order), and no row dies in this pass, so the columns
  /// removed do not depend on the order of the checks: they run in parallel against the
  /// state at the start of each round (see run_pass).
  bool remove_dominated_cols() {
    return run_pass(
        inst_.num_cols(), [&](std::int32_t j) { return col_alive_[j] != 0; },
        [&](std::int32_t j, std::vector<std::int32_t>& mark, std::vector<std::int32_t>& kills) {
          const std::int32_t pivot = shortest_alive(inst_.column(j), row_alive_, row_len_);
          for (std::int32_t i : inst_.column(j)) mark[i] = row_alive_[i];
          std::int64_t work = 3 * static_cast<std::int64_t>(inst_.column(j).size()) +
                              static_cast<std::int64_t>(inst_.row(pivot).size());
          const std::int32_t len = col_len_[j];
          const double cost = inst_.cost(j);
          const std::uint64_t sig = col_sig_[j];
          for (std::int32_t k : inst_.row(pivot)) {
            // All the cheap tests at once, without a branch each: few candidates pass
            // (see candidate_passes).
            if (!candidate_passes(k != j, col_alive_[k] != 0, col_len_[k], len, inst_.cost(k),
                                  cost, k > j, sig, col_sig_[k])) {
              continue;
            }
            work += static_cast<std::int64_t>(inst_.column(k).size());
            std::int32_t hits = 0;
            for (std::int32_t i : inst_.column(k)) hits += mark[i];
            if (hits == col_len_[j]) {
              kills.push_back(j);
              break;
            }
          }
          for (std::int32_t i : inst_.column(j)) mark[i] = 0;
          return work;
        },
        [&](std::int32_t j) {
          if (!col_alive_[j]) return false;
          kill_col(j);
          ++out.dominated_cols;
          return true;
        });
  }

  /// Row i is dominated by row k when k's alive columns are a subset of i's: covering k
  /// covers i. Identical rows: the larger index goes. As for columns, the rows removed do
  /// not depend on the order (a column dies only once all its rows have), so the checks
  /// run in parallel.
  bool remove_dominated_rows() {
    return run_pass(
        inst_.num_rows(), [&](std::int32_t k) { return row_alive_[k] != 0; },
        [&](std::int32_t k, std::vector<std::int32_t>& mark, std::vector<std::int32_t>& kills) {
          const std::int32_t pivot = shortest_alive(inst_.row(k), col_alive_, col_len_);
          for (std::int32_t j : inst_.row(k)) mark[j] = col_alive_[j];
          std::int64_t work = 3 * static_cast<std::int64_t>(inst_.row(k).size()) +
                              static_cast<std::int64_t>(inst_.column(pivot).size());
          const std::int32_t len = row_len_[k];
          const std::uint64_t sig = row_sig_[k];
          for (std::int32_t i : inst_.column(pivot)) {
            if (!candidate_passes(i != k, row_alive_[i] != 0, row_len_[i], len, 0.0, 0.0, i < k,
                                  sig, row_sig_[i])) {
              continue;
            }
            work += static_cast<std::int64_t>(inst_.row(i).size());
            std::int32_t hits = 0;
            for (std::int32_t j : inst_.row(i)) hits += mark[j];
            if (hits == row_len_[k]) kills.push_back(i);
          }
          for (std::int32_t j : inst_.row(k)) mark[j] = 0;
          return work;
        },
        [&](std::int32_t i) {
          if (!row_alive_[i]) return false;
          kill_row(i);
          ++out.dominated_rows;
          return true;
        });
  }

  /// One domination pass over items 0..count−1, in rounds of kRound items. In a round,
  /// check(item, mark, kills) runs in parallel on the items alive at the round's start,
  /// reading only the state, returning its work and appending the items it removes; then
  /// the rounds' results are applied in item order — an item still alive has its work
  /// counted and its removals made with remove(x) (false if x was already gone) — until
  /// the work limit is passed, as the sequential pass would stop. The work and the result
  /// depend on kRound, never on the number of threads.
  template <class Alive, class Check, class Remove>
  bool run_pass(std::int32_t count, Alive&& alive, Check&& check, Remove&& remove) {
    struct Verdict {
      std::int32_t item;
      std::int64_t work;
      std::uint32_t kills_end;  // end of its removals in the chunk's kill list
    };
    struct ChunkResult {
      std::vector<Verdict> verdicts;
      std::vector<std::int32_t> kills;
    };
    bool changed = false;
    std::vector<ChunkResult> chunks;
    for (std::int32_t begin = 0; begin < count; begin += kRound) {
      if (out_of_work() || out_of_time()) break;
      const std::int32_t end = std::min(count, begin + kRound);
      const auto n = static_cast<std::size_t>(end - begin);
      chunks.assign((n + kChunk - 1) / kChunk, ChunkResult{});
      parallel_chunks(n, threads_, kChunk, [&](std::size_t b, std::size_t e, unsigned worker) {
        ChunkResult& r = chunks[b / kChunk];
        std::vector<std::int32_t>& mark = marks_[worker];
        if (mark.empty()) mark.assign(mark_size_, 0);
        for (std::size_t x = b; x < e; ++x) {
          const auto item = static_cast<std::int32_t>(begin + static_cast<std::int32_t>(x));
          if (!alive(item)) continue;
          const std::int64_t work = check(item, mark, r.kills);
          r.verdicts.push_back({item, work, static_cast<std::uint32_t>(r.kills.size())});
        }
      });
      for (const ChunkResult& r : chunks) {
        std::uint32_t from = 0;
        for (const Verdict& v : r.verdicts) {
          if (out_of_work()) return changed;
          if (alive(v.item)) {
            work_ += v.work;
            for (std::uint32_t t = from; t < v.kills_end; ++t) changed = remove(r.kills[t]) || changed;
          }
          from = v.kills_end;
        }
      }
    }
    return changed;
  }

  void split_components();
  /// Component c's entries (its rows' local numbers, column by column) into `entries`, at
  /// the offsets `starts` of its columns, on `threads` threads.
  void copy_component(std::size_t c, const std::vector<std::int32_t>& comp_of_row,
                      const std::vector<std::int32_t>& local,
                      const std::vector<std::int64_t>& starts, std::vector<std::int32_t>& entries,
                      unsigned threads) const;
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
  unsigned threads_;
  std::int64_t work_ = 0;
  const Stopwatch& clock_;
  std::vector<char> row_alive_, col_alive_;
  std::vector<std::int32_t> row_len_, col_len_;
  std::size_t mark_size_;
  std::vector<std::vector<std::int32_t>> marks_;  // per worker, all zero between checks
  std::vector<std::uint64_t> row_sig_, col_sig_;
};

std::int32_t find_root(std::vector<std::int32_t>& parent, std::int32_t x) {
  while (parent[x] != x) {
    parent[x] = parent[parent[x]];
    x = parent[x];
  }
  return x;
}

void Presolver::copy_component(std::size_t c, const std::vector<std::int32_t>& comp_of_row,
                               const std::vector<std::int32_t>& local,
                               const std::vector<std::int64_t>& starts,
                               std::vector<std::int32_t>& entries, unsigned threads) const {
  const std::vector<std::int32_t>& cols = out.components[c].cols;
  parallel_chunks(cols.size(), threads, kListChunk,
                  [&](std::size_t begin, std::size_t end, unsigned) {
                    for (std::size_t k = begin; k < end; ++k) {
                      const std::int32_t j = cols[k];
                      auto at = static_cast<std::size_t>(starts[k]);
                      for (std::int32_t i : inst_.column(j)) {
                        if (comp_of_row[i] >= 0) entries[at++] = local[i];
                      }
                      RSTRUCT_ASSERT(at == static_cast<std::size_t>(starts[k + 1]));
                    }
                  });
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
  // Per alive row: its component and its index there (the roots are looked up once here,
  // not once per entry below).
  std::vector<std::int32_t> comp_of_root(static_cast<std::size_t>(m), -1);
  std::vector<std::int32_t> comp_of_row(static_cast<std::size_t>(m), -1);
  std::vector<std::int32_t> local(static_cast<std::size_t>(m), -1);
  for (std::int32_t i = 0; i < m; ++i) {
    if (!row_alive_[i]) continue;
    const std::int32_t r = find_root(parent, i);
    if (comp_of_root[r] < 0) {
      comp_of_root[r] = static_cast<std::int32_t>(out.components.size());
      out.components.emplace_back();
    }
    comp_of_row[i] = comp_of_root[r];
    auto& c = out.components[static_cast<std::size_t>(comp_of_root[r])];
    local[i] = static_cast<std::int32_t>(c.rows.size());
    c.rows.push_back(i);
  }
  parent = {};
  comp_of_root = {};
  // Each alive column's component (that of any of its alive rows: union-find put them all
  // in one) and place there, and where its entries go: a column has col_len_ alive rows.
  // The entries are then copied on all threads, each column to its own place. The
  // per-column arrays get their exact sizes first (grown by doubling, up to twice their
  // size in fresh memory).
  const std::size_t num_comps = out.components.size();
  std::vector<std::int32_t> comp_of_col(static_cast<std::size_t>(inst_.num_cols()), -1);
  std::vector<std::size_t> col_count(num_comps, 0);
  for (std::int32_t j = 0; j < inst_.num_cols(); ++j) {
    if (!col_alive_[j]) continue;
    for (std::int32_t i : inst_.column(j)) {
      if (comp_of_row[i] >= 0) {
        comp_of_col[j] = comp_of_row[i];
        break;
      }
    }
    RSTRUCT_ASSERT(comp_of_col[j] >= 0);
    ++col_count[static_cast<std::size_t>(comp_of_col[j])];
  }
  std::vector<std::vector<std::int64_t>> starts(num_comps);
  std::vector<std::vector<double>> costs(num_comps);
  for (std::size_t c = 0; c < num_comps; ++c) {
    starts[c].reserve(col_count[c] + 1);
    starts[c].push_back(0);
    costs[c].reserve(col_count[c]);
    out.components[c].cols.reserve(col_count[c]);
  }
  for (std::int32_t j = 0; j < inst_.num_cols(); ++j) {
    if (comp_of_col[j] < 0) continue;
    const auto c = static_cast<std::size_t>(comp_of_col[j]);
    starts[c].push_back(starts[c].back() + col_len_[j]);
    costs[c].push_back(inst_.cost(j));
    out.components[c].cols.push_back(j);
  }
  std::vector<std::vector<std::int32_t>> entries(num_comps);
  for (std::size_t c = 0; c < num_comps; ++c) {
    entries[c].resize(static_cast<std::size_t>(starts[c].back()));
  }
  parallel_chunks(num_comps, threads_, 1, [&](std::size_t begin, std::size_t end, unsigned) {
    for (std::size_t c = begin; c < end; ++c) {
      // Small components: one thread each; a large one is copied below on all of them.
      if (out.components[c].cols.size() >= kListChunk) continue;
      copy_component(c, comp_of_row, local, starts[c], entries[c], 1);
    }
  });
  for (std::size_t c = 0; c < num_comps; ++c) {
    if (out.components[c].cols.size() < kListChunk) continue;
    copy_component(c, comp_of_row, local, starts[c], entries[c], threads_);
  }
  for (std::size_t c = 0; c < out.components.size(); ++c) {
    auto& comp = out.components[c];
    comp.instance = Instance::from_csr(static_cast<std::int32_t>(comp.rows.size()),
                                       std::move(starts[c]), std::move(entries[c]),
                                       std::move(costs[c]), threads_);
  }
}

}  // namespace

Reduction reduce(const Instance& inst, bool use_domination, double deadline, const Stopwatch& clock,
                 std::int64_t work_limit, unsigned threads) {
  Presolver p(inst, deadline, clock, work_limit, threads);
  p.take_zero_cost();
  p.force_singletons();
  // Domination passes are the expensive part: two rounds catch nearly everything.
  for (int pass = 0; use_domination && pass < 2 && !p.out_of_time() && !p.out_of_work(); ++pass) {
    p.take_signatures(true);
    bool changed = p.remove_dominated_rows();
    p.take_signatures(false);
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
