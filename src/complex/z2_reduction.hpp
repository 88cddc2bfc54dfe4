#pragma once
// Sparse column reduction over Z₂ of the boundary matrices of a chain complex with cells
// in dimensions 0..3 (private to the complex module; see rstruct/complex/homology.hpp).

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "rstruct/complex/homology.hpp"

namespace rstruct::complex::detail {

/// A chain complex over Z₂: sizes[d] cells of dimension d, and ∂_d (d = 1..3) in
/// compressed columns (column j = the (d−1)-cells in the boundary of d-cell j, sorted
/// increasingly). Must satisfy ∂_{d−1} ∂_d = 0 (clearing relies on it).
struct Z2ChainComplex {
  std::array<std::size_t, 4> sizes{};
  std::array<std::vector<std::size_t>, 4> offsets;  // offsets[d].size() == sizes[d] + 1
  std::array<std::vector<std::uint32_t>, 4> rows;

  std::span<const std::uint32_t> column(int d, std::size_t j) const {
    return {rows[d].data() + offsets[d][j], rows[d].data() + offsets[d][j + 1]};
  }
  /// Starts a new empty complex with the given cell counts (offsets sized, no entries).
  void reset(const std::array<std::size_t, 4>& cell_counts);
};

/// Ranks of ∂_1..∂_3 (entry 0 is 0) by column reduction with clearing, from ∂_3 down.
std::array<std::size_t, 4> reduce_ranks(const Z2ChainComplex& complex, HomologyStats& stats);

/// The chain complex of a simplicial complex (cells = simplices, same indices).
Z2ChainComplex chain_complex_of(const SimplicialComplex& complex);

/// Coreduces the chain complex of `complex` (Mrozek & Batko): returns the chain complex of
/// what is left and adds to `betti0` one per vertex removed as a homology generator.
Z2ChainComplex coreduce(const SimplicialComplex& complex, long long& betti0,
                        HomologyStats& stats);

}  // namespace rstruct::complex::detail
