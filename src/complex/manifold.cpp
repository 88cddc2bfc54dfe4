#include "rstruct/complex/manifold.hpp"

#include <string>

#include "rstruct/complex/coface_index.hpp"
#include "rstruct/core/error.hpp"

namespace rstruct::complex {
namespace {

std::string edge_text(const Edge& e) {
  // Appended piece by piece: GCC 12 warns (-Wrestrict, a false positive) on "(" + string.
  std::string text = "(";
  text += std::to_string(e[0]);
  text += ", ";
  text += std::to_string(e[1]);
  text += ")";
  return text;
}

/// The edge of triangle t other than `e` that contains vertex (index) v.
SimplexIndex other_edge_at(const SimplicialComplex& k, SimplexIndex t, SimplexIndex e,
                           SimplexIndex v) {
  for (const SimplexIndex f : k.triangle_faces(t)) {
    const auto& ends = k.edge_faces(f);
    if (f != e && (ends[0] == v || ends[1] == v)) return f;
  }
  return e;  // unreachable for a valid complex
}

/// Whether the link of vertex v is one cycle, given every edge has exactly two triangles:
/// the link is then 2-regular, so it is one cycle iff walking around v from one incident
/// edge visits every incident edge before returning.
bool link_is_one_cycle(const SimplicialComplex& k, const CofaceIndex& cof, SimplexIndex v) {
  const auto edges = cof.cofaces(0, v);
  if (edges.empty()) return false;
  const SimplexIndex start = edges[0];
  SimplexIndex e = start;
  SimplexIndex t = cof.cofaces(1, e)[0];
  std::size_t steps = 0;
  do {
    e = other_edge_at(k, t, e, v);
    const auto around = cof.cofaces(1, e);
    t = around[0] == t ? around[1] : around[0];
    ++steps;
  } while (e != start && steps <= edges.size());
  return e == start && steps == edges.size();
}

}  // namespace

ManifoldCheck check_closed_2_manifold(const SimplicialComplex& k) {
  ManifoldCheck result;
  auto note = [&result](const std::string& problem) {
    if (result.first_problem.empty()) result.first_problem = problem;
  };
  if (k.empty()) note("the complex is empty");
  result.tetrahedra = k.size(3);
  if (result.tetrahedra > 0) note(std::to_string(result.tetrahedra) + " tetrahedra");
  const CofaceIndex cof(k);
  for (SimplexIndex e = 0; e < k.size(1); ++e) {
    if (cof.degree(1, e) != 2) {
      ++result.edges_not_in_two_triangles;
      note("edge " + edge_text(k.edges()[e]) + " lies in " + std::to_string(cof.degree(1, e)) +
           " triangles");
    }
  }
  if (result.edges_not_in_two_triangles == 0) {
    for (SimplexIndex v = 0; v < k.size(0); ++v) {
      if (!link_is_one_cycle(k, cof, v)) {
        ++result.vertices_with_bad_link;
        note("the link of vertex " + std::to_string(k.vertices()[v]) + " is not one cycle");
      }
    }
  }
  result.is_closed_2_manifold = result.first_problem.empty();
  return result;
}

bool is_closed_2_manifold(const SimplicialComplex& complex) {
  return check_closed_2_manifold(complex).is_closed_2_manifold;
}

std::optional<std::vector<Triangle>> orient_triangles(const SimplicialComplex& k) {
  const CofaceIndex cof(k);
  for (SimplexIndex e = 0; e < k.size(1); ++e) {
    if (cof.degree(1, e) > 2) {
      throw InvalidInput("orient_triangles: edge " + edge_text(k.edges()[e]) + " lies in " +
                         std::to_string(cof.degree(1, e)) + " triangles");
    }
  }
  // sign[t] = +1: (a, b, c) induces a→b, b→c, c→a, i.e. face i (omitting vertex i) is
  // traversed in its sorted direction iff i is even. Neighbours t, u across their shared
  // edge (face i of t, face j of u) are consistent iff sign[u] = −sign[t]·(−1)^(i+j).
  std::vector<signed char> sign(k.size(2), 0);
  std::vector<SimplexIndex> stack;
  for (SimplexIndex seed = 0; seed < k.size(2); ++seed) {
    if (sign[seed] != 0) continue;
    sign[seed] = 1;
    stack.push_back(seed);
    while (!stack.empty()) {
      const SimplexIndex t = stack.back();
      stack.pop_back();
      for (int i = 0; i < 3; ++i) {
        const SimplexIndex e = k.triangle_faces(t)[i];
        for (const SimplexIndex u : cof.cofaces(1, e)) {
          if (u == t) continue;
          int j = 0;
          while (k.triangle_faces(u)[j] != e) ++j;
          const signed char want = static_cast<signed char>(((i + j) % 2 == 0) ? -sign[t] : sign[t]);
          if (sign[u] == 0) {
            sign[u] = want;
            stack.push_back(u);
          } else if (sign[u] != want) {
            return std::nullopt;
          }
        }
      }
    }
  }
  std::vector<Triangle> oriented(k.size(2));
  for (SimplexIndex t = 0; t < k.size(2); ++t) {
    const Triangle& s = k.triangles()[t];
    oriented[t] = sign[t] > 0 ? s : Triangle{s[0], s[2], s[1]};
  }
  return oriented;
}

}  // namespace rstruct::complex
