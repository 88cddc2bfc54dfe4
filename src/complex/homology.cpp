#include "rstruct/complex/homology.hpp"

#include <ostream>

#include "complex/z2_reduction.hpp"

namespace rstruct::complex {
namespace {

BettiNumbers betti_from_ranks(const std::array<std::size_t, 4>& sizes,
                              const std::array<std::size_t, 4>& ranks) {
  BettiNumbers betti;
  for (std::size_t d = 0; d < 4; ++d) {
    const std::size_t rank_out = d == 0 ? 0 : ranks[d];
    const std::size_t rank_in = d == 3 ? 0 : ranks[d + 1];
    betti.b[d] = static_cast<long long>(sizes[d]) - static_cast<long long>(rank_out) -
                 static_cast<long long>(rank_in);
  }
  return betti;
}

}  // namespace

std::ostream& operator<<(std::ostream& out, const BettiNumbers& betti) {
  return out << '(' << betti.b[0] << ", " << betti.b[1] << ", " << betti.b[2] << ", "
             << betti.b[3] << ')';
}

BettiNumbers betti_numbers(const SimplicialComplex& complex, HomologyMethod method,
                           HomologyStats* stats) {
  HomologyStats local;
  HomologyStats& s = stats ? *stats : local;
  s = HomologyStats{};
  long long generators = 0;
  const detail::Z2ChainComplex chains = method == HomologyMethod::reduction
                                            ? detail::chain_complex_of(complex)
                                            : detail::coreduce(complex, generators, s);
  s.cells_reduced = chains.sizes;
  BettiNumbers betti = betti_from_ranks(chains.sizes, detail::reduce_ranks(chains, s));
  betti.b[0] += generators;
  return betti;
}

std::array<std::size_t, 4> boundary_ranks(const SimplicialComplex& complex,
                                          HomologyStats* stats) {
  HomologyStats local;
  HomologyStats& s = stats ? *stats : local;
  return detail::reduce_ranks(detail::chain_complex_of(complex), s);
}

}  // namespace rstruct::complex
