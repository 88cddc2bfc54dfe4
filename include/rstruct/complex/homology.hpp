#pragma once
/// \file
/// Simplicial homology over Z₂ (DESIGN.md §7; issue 7 "Z₂ homology"): Betti numbers
/// β₀..β₃ of a SimplicialComplex.
///
/// Method: the boundary matrices ∂₁..∂₃ are reduced column by column over Z₂ (pivot = the
/// largest row index, sorted-index columns, symmetric difference to add), from ∂₃ down to
/// ∂₁ with the clearing ("twist") optimisation of Chen & Kerber, "Persistent homology
/// computation with a twist" (EuroCG 2011): a d-simplex that is the pivot of a reduced
/// column of ∂_{d+1} has a column of ∂_d that reduces to zero, so it is skipped.
/// Then β_d = n_d − rank ∂_d − rank ∂_{d+1}.
///
/// By default the complex is first shrunk by coreductions (Mrozek & Batko, "Coreduction
/// homology algorithm", DCG 41 (2009)): in the chain complex of an S-complex, a cell a
/// whose boundary has exactly one remaining face b can be removed together with b without
/// changing homology, and a vertex whose every remaining coface has two remaining
/// vertices can be removed for one unit of β₀. The (usually tiny) rest is reduced as
/// above. Both paths are exact; tests check them against dense Gaussian elimination.

#include <array>
#include <cstddef>
#include <iosfwd>

#include "rstruct/complex/simplicial_complex.hpp"

namespace rstruct::complex {

/// Betti numbers over Z₂, β₀..β₃.
struct BettiNumbers {
  std::array<long long, 4> b{};

  long long operator[](std::size_t d) const { return b[d]; }
  /// Σ (−1)^d β_d, which equals the Euler characteristic of the complex.
  long long euler_characteristic() const { return b[0] - b[1] + b[2] - b[3]; }
  friend bool operator==(const BettiNumbers&, const BettiNumbers&) = default;
};

std::ostream& operator<<(std::ostream& out, const BettiNumbers& betti);

enum class HomologyMethod {
  reduction,                 ///< reduce the full boundary matrices (with clearing)
  coreduction_then_reduction ///< coreductions first, then reduce what is left
};

/// What a homology computation did (for benchmarks and reports).
struct HomologyStats {
  /// Cells of dimension d left after the coreductions (all cells for `reduction`).
  std::array<std::size_t, 4> cells_reduced{};
  std::size_t coreduction_pairs = 0;
  std::size_t column_additions = 0;  ///< symmetric differences performed by the reduction
  std::size_t cleared_columns = 0;   ///< columns skipped by clearing
};

/// Betti numbers of `complex` over Z₂. Exact. Linear memory in the complex size plus the
/// fill-in of the reduction.
BettiNumbers betti_numbers(const SimplicialComplex& complex,
                           HomologyMethod method = HomologyMethod::coreduction_then_reduction,
                           HomologyStats* stats = nullptr);

/// Ranks over Z₂ of the boundary matrices ∂_d (index d = 1..3; entry 0 is 0) of the whole
/// complex, by sparse column reduction with clearing.
std::array<std::size_t, 4> boundary_ranks(const SimplicialComplex& complex,
                                          HomologyStats* stats = nullptr);

}  // namespace rstruct::complex
