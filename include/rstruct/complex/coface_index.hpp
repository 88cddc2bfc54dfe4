#pragma once
/// \file
/// The coface relation of a simplicial complex: for every simplex of dimension d < 3, the
/// indices of the (d + 1)-simplices that have it as a face, in increasing order. Built in
/// linear time from the face lists (compressed rows); used by collapses, coreductions and
/// the manifold tests.

#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "rstruct/complex/simplicial_complex.hpp"

namespace rstruct::complex {

class CofaceIndex {
 public:
  explicit CofaceIndex(const SimplicialComplex& complex);

  /// Cofaces (indices of dimension d + 1) of the d-simplex i, 0 ≤ d ≤ 2, increasing.
  std::span<const SimplexIndex> cofaces(int d, SimplexIndex i) const {
    const auto& off = offsets_[d];
    return {data_[d].data() + off[i], data_[d].data() + off[i + 1]};
  }
  /// Number of (d + 1)-cofaces of the d-simplex i.
  std::size_t degree(int d, SimplexIndex i) const {
    return offsets_[d][i + 1] - offsets_[d][i];
  }

 private:
  std::array<std::vector<std::size_t>, 3> offsets_;
  std::array<std::vector<SimplexIndex>, 3> data_;
};

}  // namespace rstruct::complex
