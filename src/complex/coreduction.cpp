// Coreductions of the chain complex of a simplicial complex (Mrozek & Batko, "Coreduction
// homology algorithm", Discrete Comput. Geom. 41 (2009)).
//
// The cells still present form an S-complex S: its chain complex is that of the simplicial
// complex with the boundary restricted to S, and ∂² = 0 still holds. Two moves keep H(S):
//  - a coreduction pair (a, b): b is the only face of a left in S. Removing both is an
//    isomorphism on homology (b and a form an acyclic summand).
//  - removing a vertex v when no cell has exactly one face left: then every remaining
//    edge has zero or two vertices left, so the augmentation (sum of coefficients) vanishes
//    on boundaries, v is not a boundary, and the exact sequence of the pair ({v}, S) gives
//    H(S) = H(S \ v) ⊕ Z₂ in degree 0.
// Cells whose count of remaining faces drops to one are queued when it happens; counts
// only decrease, so when the queue is empty no remaining cell has exactly one face. The
// queue is first in, first out: grown breadth-first from a removed vertex, the removed
// edges leave triangles with two removed edges around it, so coreductions sweep across
// triangles and tetrahedra too; depth-first order builds path-like trees that leave most
// triangles with two faces and the reduction with most of the complex.

#include <algorithm>
#include <cstdint>
#include <deque>

#include "complex/z2_reduction.hpp"
#include "rstruct/complex/coface_index.hpp"
#include "rstruct/core/assert.hpp"

namespace rstruct::complex::detail {
namespace {

class Coreducer {
 public:
  explicit Coreducer(const SimplicialComplex& complex) : complex_(complex), cofaces_(complex) {
    for (int d = 0; d < 4; ++d) {
      alive_[d].assign(complex.size(d), 1);
      remaining_faces_[d].assign(complex.size(d), static_cast<std::uint8_t>(d == 0 ? 0 : d + 1));
    }
  }

  /// Runs coreductions and vertex removals until no vertex is left; returns the number of
  /// vertices removed as generators of H₀.
  long long run(HomologyStats& stats) {
    long long generators = 0;
    std::size_t next_vertex = 0;
    for (;;) {
      while (!queue_.empty()) {
        const auto [d, i] = queue_.front();
        queue_.pop_front();
        if (!alive_[d][i] || remaining_faces_[d][i] != 1) continue;
        const SimplexIndex f = alive_face(d, i);
        remove(d, i);
        remove(d - 1, f);
        ++stats.coreduction_pairs;
      }
      while (next_vertex < complex_.size(0) && !alive_[0][next_vertex]) ++next_vertex;
      if (next_vertex == complex_.size(0)) break;
      remove(0, static_cast<SimplexIndex>(next_vertex));
      ++generators;
    }
    return generators;
  }

  /// The chain complex of the cells left (re-indexed in increasing order).
  Z2ChainComplex remainder() const {
    std::array<std::vector<std::uint32_t>, 4> new_index;
    std::array<std::size_t, 4> counts{};
    for (int d = 0; d < 4; ++d) {
      new_index[d].assign(complex_.size(d), 0);
      for (std::size_t i = 0; i < complex_.size(d); ++i) {
        if (alive_[d][i]) new_index[d][i] = static_cast<std::uint32_t>(counts[d]++);
      }
    }
    Z2ChainComplex c;
    c.reset(counts);
    for (int d = 1; d < 4; ++d) {
      std::size_t j = 0;
      for (std::size_t i = 0; i < complex_.size(d); ++i) {
        if (!alive_[d][i]) continue;
        const std::size_t start = c.rows[d].size();
        for (const SimplexIndex f : complex_.faces(d, static_cast<SimplexIndex>(i))) {
          if (alive_[d - 1][f]) c.rows[d].push_back(new_index[d - 1][f]);
        }
        std::sort(c.rows[d].begin() + static_cast<std::ptrdiff_t>(start), c.rows[d].end());
        c.offsets[d][++j] = c.rows[d].size();
      }
    }
    return c;
  }

 private:
  SimplexIndex alive_face(int d, SimplexIndex i) const {
    for (const SimplexIndex f : complex_.faces(d, i)) {
      if (alive_[d - 1][f]) return f;
    }
    RSTRUCT_ASSERT_MSG(false, "coreduction: a cell counted one face left but has none");
  }

  void remove(int d, SimplexIndex i) {
    alive_[d][i] = 0;
    if (d == 3) return;
    for (const SimplexIndex c : cofaces_.cofaces(d, i)) {
      if (alive_[d + 1][c] && --remaining_faces_[d + 1][c] == 1) queue_.emplace_back(d + 1, c);
    }
  }

  const SimplicialComplex& complex_;
  CofaceIndex cofaces_;
  std::array<std::vector<std::uint8_t>, 4> alive_;
  std::array<std::vector<std::uint8_t>, 4> remaining_faces_;
  std::deque<std::pair<int, SimplexIndex>> queue_;
};

}  // namespace

Z2ChainComplex coreduce(const SimplicialComplex& complex, long long& betti0,
                        HomologyStats& stats) {
  Coreducer coreducer(complex);
  betti0 += coreducer.run(stats);
  return coreducer.remainder();
}

}  // namespace rstruct::complex::detail
