#include "rstruct/complex/dual_complex.hpp"

#include <string>

#include "complex/ball_cells.hpp"
#include "rstruct/complex/coface_index.hpp"
#include "rstruct/complex/orthosphere_predicates.hpp"
#include "rstruct/core/error.hpp"
#include "rstruct/triangulation/regular_triangulation_3.hpp"

namespace rstruct::complex {
namespace {

class Classifier {
 public:
  Classifier(std::span<const WeightedPoint> points, DualComplex& out)
      : points_(points), r_(out.triangulation), cof_(r_), in_k_(out.in_k) {
    for (int d = 0; d < 4; ++d) in_k_[d].assign(r_.size(d), false);
  }

  void run() {
    for (SimplexIndex t = 0; t < r_.size(3); ++t) {
      in_k_[3][t] = orthosphere_power_sign(detail::weighted_simplex(points_, r_.tetrahedra()[t])) !=
                    Sign::positive;
    }
    for (SimplexIndex f = 0; f < r_.size(2); ++f) {
      in_k_[2][f] = classify(2, f, r_.triangles()[f], r_.tetrahedra());
    }
    for (SimplexIndex e = 0; e < r_.size(1); ++e) {
      in_k_[1][e] = classify(1, e, r_.edges()[e], r_.triangles());
    }
    for (SimplexIndex v = 0; v < r_.size(0); ++v) {
      in_k_[0][v] = classify(0, v, std::array<VertexId, 1>{r_.vertices()[v]}, r_.edges());
    }
  }

 private:
  /// Membership of the simplex `s` of dimension d < 3 (index i), its cofaces classified.
  template <std::size_t K, class Cofaces>
  bool classify(int d, SimplexIndex i, const std::array<VertexId, K>& s,
                const Cofaces& coface_list) const {
    const auto cofaces = cof_.cofaces(d, i);
    for (const SimplexIndex c : cofaces) {
      if (in_k_[d + 1][c]) return true;  // V_c ⊂ V_s, and K is closed under faces
    }
    const auto sigma = detail::weighted_simplex(points_, s);
    // No coface in K: the minimum of π over V_s is ≤ 0 only at z_s, if z_s ∈ V_s.
    if (orthosphere_power_sign(sigma) == Sign::positive) return false;
    for (const SimplexIndex c : cofaces) {
      const VertexId p = detail::opposite_vertex<K>(coface_list[c], s);
      if (orthosphere_attachment_sign(sigma, points_[p]) == Sign::negative) return false;
    }
    return true;
  }

  std::span<const WeightedPoint> points_;
  const SimplicialComplex& r_;
  CofaceIndex cof_;
  std::array<std::vector<bool>, 4>& in_k_;
};

void classify_facets(DualComplex& k) {
  const CofaceIndex cof(k.triangulation);
  k.facet_class.assign(k.triangulation.size(2), FacetClass::exterior);
  for (SimplexIndex f = 0; f < k.triangulation.size(2); ++f) {
    if (!k.in_k[2][f]) continue;
    int tets_in_k = 0;
    for (const SimplexIndex t : cof.cofaces(2, f)) tets_in_k += k.in_k[3][t] ? 1 : 0;
    k.facet_class[f] = static_cast<FacetClass>(1 + tets_in_k);
  }
}

}  // namespace

const char* to_string(FacetClass c) {
  switch (c) {
    case FacetClass::exterior: return "exterior";
    case FacetClass::singular: return "singular";
    case FacetClass::regular: return "regular";
    case FacetClass::interior: return "interior";
  }
  return "?";
}

std::array<std::size_t, 4> DualComplex::counts() const {
  std::array<std::size_t, 4> n{};
  for (int d = 0; d < 4; ++d) {
    for (const bool b : in_k[d]) n[d] += b ? 1 : 0;
  }
  return n;
}

std::array<std::size_t, 4> DualComplex::facet_class_counts() const {
  std::array<std::size_t, 4> n{};
  for (const FacetClass c : facet_class) ++n[static_cast<std::size_t>(c)];
  return n;
}

DualComplex dual_complex(std::span<const WeightedPoint> points,
                         std::span<const Tetrahedron> cells) {
  detail::require_points_exist(cells, points.size(), "dual_complex");
  DualComplex k;
  k.triangulation = SimplicialComplex::closure_of(cells);
  Classifier(points, k).run();
  classify_facets(k);
  return k;
}

DualComplex dual_complex(const triangulation::RegularTriangulation3& triangulation) {
  const detail::BallCells input = detail::ball_cells(triangulation);
  return dual_complex(input.points, input.cells);
}

}  // namespace rstruct::complex
