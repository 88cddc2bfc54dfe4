#include "complex/z2_reduction.hpp"

#include <algorithm>
#include <iterator>
#include <limits>

namespace rstruct::complex::detail {
namespace {

constexpr std::uint32_t kNoOwner = std::numeric_limits<std::uint32_t>::max();

/// Reduces the columns of ∂_d that are not cleared; marks in `pivot_rows` (size of
/// dimension d − 1) the pivot of every non-zero reduced column. Returns the rank.
std::size_t reduce_matrix(const Z2ChainComplex& c, int d, const std::vector<bool>& cleared,
                          std::vector<bool>& pivot_rows, HomologyStats& stats) {
  const std::size_t rows = c.sizes[d - 1];
  pivot_rows.assign(rows, false);
  // owner[p]: index in `reduced` of the reduced column whose pivot is row p.
  std::vector<std::uint32_t> owner(rows, kNoOwner);
  std::vector<std::vector<std::uint32_t>> reduced;
  std::vector<std::uint32_t> work;
  std::vector<std::uint32_t> sum;
  for (std::size_t j = 0; j < c.sizes[d]; ++j) {
    if (!cleared.empty() && cleared[j]) {
      ++stats.cleared_columns;
      continue;
    }
    const auto column = c.column(d, j);
    work.assign(column.begin(), column.end());
    while (!work.empty() && owner[work.back()] != kNoOwner) {
      const auto& other = reduced[owner[work.back()]];
      sum.clear();
      std::set_symmetric_difference(work.begin(), work.end(), other.begin(), other.end(),
                                    std::back_inserter(sum));
      work.swap(sum);
      ++stats.column_additions;
    }
    if (work.empty()) continue;
    owner[work.back()] = static_cast<std::uint32_t>(reduced.size());
    pivot_rows[work.back()] = true;
    reduced.push_back(work);
  }
  return reduced.size();
}

}  // namespace

void Z2ChainComplex::reset(const std::array<std::size_t, 4>& cell_counts) {
  sizes = cell_counts;
  for (int d = 0; d < 4; ++d) {
    offsets[d].assign(d == 0 ? 1 : sizes[d] + 1, 0);
    rows[d].clear();
  }
}

std::array<std::size_t, 4> reduce_ranks(const Z2ChainComplex& complex, HomologyStats& stats) {
  std::array<std::size_t, 4> ranks{};
  std::vector<bool> cleared;  // d-cells whose column of ∂_d is known to reduce to zero
  std::vector<bool> pivots;
  for (int d = 3; d >= 1; --d) {
    ranks[d] = reduce_matrix(complex, d, cleared, pivots, stats);
    cleared.swap(pivots);
  }
  return ranks;
}

Z2ChainComplex chain_complex_of(const SimplicialComplex& complex) {
  Z2ChainComplex c;
  c.reset({complex.size(0), complex.size(1), complex.size(2), complex.size(3)});
  for (int d = 1; d <= 3; ++d) {
    auto& rows = c.rows[d];
    rows.reserve(c.sizes[d] * static_cast<std::size_t>(d + 1));
    for (std::size_t j = 0; j < c.sizes[d]; ++j) {
      const auto faces = complex.faces(d, static_cast<SimplexIndex>(j));
      const std::size_t start = rows.size();
      rows.insert(rows.end(), faces.begin(), faces.end());
      std::sort(rows.begin() + static_cast<std::ptrdiff_t>(start), rows.end());
      c.offsets[d][j + 1] = rows.size();
    }
  }
  return c;
}

}  // namespace rstruct::complex::detail
