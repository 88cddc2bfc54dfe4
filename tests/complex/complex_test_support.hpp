#pragma once
// Test oracles and generators for the complex module: dense Gaussian elimination over Z₂
// (shares nothing with the sparse reduction it checks) and random small complexes.

#include <rapidcheck.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <random>
#include <set>
#include <vector>

#include "rstruct/complex/homology.hpp"
#include "rstruct/complex/simplicial_complex.hpp"

namespace rstruct::complex::testing {

/// Rank over Z₂ of a dense matrix given as rows of bits (Gaussian elimination).
inline std::size_t dense_z2_rank(std::vector<std::vector<std::uint64_t>> rows) {
  std::size_t rank = 0;
  const std::size_t words = rows.empty() ? 0 : rows[0].size();
  for (std::size_t col = 0; col < words * 64 && rank < rows.size(); ++col) {
    const std::size_t w = col / 64;
    const std::uint64_t bit = std::uint64_t{1} << (col % 64);
    std::size_t pivot = rank;
    while (pivot < rows.size() && !(rows[pivot][w] & bit)) ++pivot;
    if (pivot == rows.size()) continue;
    std::swap(rows[pivot], rows[rank]);
    for (std::size_t r = 0; r < rows.size(); ++r) {
      if (r != rank && (rows[r][w] & bit)) {
        for (std::size_t k = 0; k < words; ++k) rows[r][k] ^= rows[rank][k];
      }
    }
    ++rank;
  }
  return rank;
}

/// The d-th boundary matrix (rows = d-simplices, bits = (d−1)-simplices), built from the
/// vertex tuples alone (faces found by set membership, not from the complex's face
/// indices).
inline std::vector<std::vector<std::uint64_t>> dense_boundary(const SimplicialComplex& k,
                                                              int d) {
  std::vector<std::vector<VertexId>> lower;
  std::vector<std::vector<VertexId>> upper;
  auto tuples = [&](int dim) {
    std::vector<std::vector<VertexId>> out;
    if (dim == 0) {
      for (const auto v : k.vertices()) out.push_back({v});
    } else if (dim == 1) {
      for (const auto& s : k.edges()) out.emplace_back(s.begin(), s.end());
    } else if (dim == 2) {
      for (const auto& s : k.triangles()) out.emplace_back(s.begin(), s.end());
    } else {
      for (const auto& s : k.tetrahedra()) out.emplace_back(s.begin(), s.end());
    }
    return out;
  };
  lower = tuples(d - 1);
  upper = tuples(d);
  const std::size_t words = (lower.size() + 63) / 64 + 1;
  std::vector<std::vector<std::uint64_t>> rows(upper.size(), std::vector<std::uint64_t>(words));
  for (std::size_t r = 0; r < upper.size(); ++r) {
    for (std::size_t c = 0; c < lower.size(); ++c) {
      if (std::includes(upper[r].begin(), upper[r].end(), lower[c].begin(), lower[c].end())) {
        rows[r][c / 64] |= std::uint64_t{1} << (c % 64);
      }
    }
  }
  return rows;
}

/// Betti numbers by dense elimination.
inline BettiNumbers dense_betti(const SimplicialComplex& k) {
  std::array<std::size_t, 5> rank{};
  for (int d = 1; d <= 3; ++d) rank[d] = dense_z2_rank(dense_boundary(k, d));
  BettiNumbers b;
  for (int d = 0; d < 4; ++d) {
    b.b[d] = static_cast<long long>(k.size(d)) - static_cast<long long>(rank[d]) -
             static_cast<long long>(rank[d + 1]);
  }
  return b;
}

/// Random simplex lists on vertices 0..n−1, n ≤ max_vertices; simplices with a repeated
/// vertex are dropped.
inline rc::Gen<SimplexLists> random_simplex_lists(int max_vertices, int max_per_dim) {
  return rc::gen::exec([=] {
    const auto n = *rc::gen::inRange<VertexId>(1, static_cast<VertexId>(max_vertices) + 1);
    const auto vertex = rc::gen::inRange<VertexId>(0, n);
    SimplexLists lists;
    auto distinct = [](auto s) {
      std::sort(s.begin(), s.end());
      return std::adjacent_find(s.begin(), s.end()) == s.end();
    };
    const int counts[4] = {*rc::gen::inRange(0, 3), *rc::gen::inRange(0, max_per_dim),
                           *rc::gen::inRange(0, max_per_dim), *rc::gen::inRange(0, max_per_dim)};
    for (int i = 0; i < counts[0]; ++i) lists.vertices.push_back(*vertex);
    for (int i = 0; i < counts[1]; ++i) {
      const Edge e{*vertex, *vertex};
      if (distinct(e)) lists.edges.push_back(e);
    }
    for (int i = 0; i < counts[2]; ++i) {
      const Triangle t{*vertex, *vertex, *vertex};
      if (distinct(t)) lists.triangles.push_back(t);
    }
    for (int i = 0; i < counts[3]; ++i) {
      const Tetrahedron t{*vertex, *vertex, *vertex, *vertex};
      if (distinct(t)) lists.tetrahedra.push_back(t);
    }
    return lists;
  });
}

/// The lists with every vertex id replaced by map(id).
template <class Map>
SimplexLists relabelled(const SimplicialComplex& k, Map map) {
  SimplexLists out;
  for (const auto v : k.vertices()) out.vertices.push_back(map(v));
  for (auto s : k.edges()) {
    for (auto& v : s) v = map(v);
    out.edges.push_back(s);
  }
  for (auto s : k.triangles()) {
    for (auto& v : s) v = map(v);
    out.triangles.push_back(s);
  }
  for (auto s : k.tetrahedra()) {
    for (auto& v : s) v = map(v);
    out.tetrahedra.push_back(s);
  }
  return out;
}

/// A random injective relabelling of n vertices onto ids spread over [0, 2³²): a random
/// permutation, times an odd constant, plus an offset (both bijective mod 2³²).
inline rc::Gen<std::vector<VertexId>> random_injective_ids(std::size_t n) {
  return rc::gen::exec([n] {
    const auto seed = *rc::gen::arbitrary<std::uint32_t>();
    const auto offset = *rc::gen::arbitrary<std::uint32_t>();
    std::vector<VertexId> ids(n);
    std::iota(ids.begin(), ids.end(), VertexId{0});
    std::mt19937 engine(seed);
    std::shuffle(ids.begin(), ids.end(), engine);
    for (auto& v : ids) v = v * 2654435761u + offset;
    return ids;
  });
}

}  // namespace rstruct::complex::testing
