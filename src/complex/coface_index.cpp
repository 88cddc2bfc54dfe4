#include "rstruct/complex/coface_index.hpp"

namespace rstruct::complex {

CofaceIndex::CofaceIndex(const SimplicialComplex& complex) {
  for (int d = 0; d < 3; ++d) {
    const std::size_t n = complex.size(d);
    const std::size_t m = complex.size(d + 1);
    auto& off = offsets_[d];
    off.assign(n + 1, 0);
    for (SimplexIndex c = 0; c < m; ++c) {
      for (const SimplexIndex f : complex.faces(d + 1, c)) ++off[f + 1];
    }
    for (std::size_t i = 0; i < n; ++i) off[i + 1] += off[i];
    auto& data = data_[d];
    data.resize(off[n]);
    std::vector<std::size_t> fill(off.begin(), off.end() - 1);
    // Cofaces visited in increasing order, so every row ends up sorted.
    for (SimplexIndex c = 0; c < m; ++c) {
      for (const SimplexIndex f : complex.faces(d + 1, c)) data[fill[f]++] = c;
    }
  }
}

}  // namespace rstruct::complex
