#include "rstruct/poles/pole_set.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <string>
#include <thread>

#include "circumsphere.hpp"
#include "parallel_blocks.hpp"
#include "rstruct/core/error.hpp"
#include "rstruct/core/parallel.hpp"

namespace rstruct::poles {
namespace {

constexpr std::uint32_t kNoTet = 0xffffffffU;

void check_soup(const TetrahedronSoup& soup, unsigned threads) {
  if (soup.sample_count > soup.vertices.size()) {
    throw InvalidInput("poles: sample_count exceeds the number of vertices");
  }
  if (soup.tets.size() >= kNoTet) throw InvalidInput("poles: too many tetrahedra");
  const auto& rep = soup.representative;
  if (!rep.empty()) {
    if (rep.size() != soup.sample_count) {
      throw InvalidInput("poles: representative has the wrong size");
    }
    for (std::size_t s = 0; s < rep.size(); ++s) {
      if (rep[s] >= soup.sample_count || rep[rep[s]] != rep[s]) {
        throw InvalidInput("poles: sample " + std::to_string(s) + " has an invalid representative");
      }
    }
  }
  // The first tetrahedron with a vertex out of range (whatever the threads).
  std::atomic<std::size_t> bad{soup.tets.size()};
  parallel_chunks(soup.tets.size(), threads, std::size_t{1} << 16,
                  [&](std::size_t begin, std::size_t end, unsigned) {
                    for (std::size_t t = begin; t < end && t < bad.load(std::memory_order_relaxed); ++t) {
                      for (const std::uint32_t v : soup.tets[t]) {
                        if (v >= soup.vertices.size()) {
                          std::size_t seen = bad.load(std::memory_order_relaxed);
                          while (t < seen && !bad.compare_exchange_weak(seen, t)) {
                          }
                          return;
                        }
                      }
                    }
                  });
  if (const std::size_t t = bad.load(); t < soup.tets.size()) {
    std::uint32_t v = 0;
    for (const std::uint32_t u : soup.tets[t]) {
      if (u >= soup.vertices.size()) {
        v = u;
        break;
      }
    }
    throw InvalidInput("poles: tetrahedron " + std::to_string(t) + " has vertex " +
                       std::to_string(v) + " out of range");
  }
}

/// The first tetrahedron of range k when m tetrahedra are cut into `ranges` ranges.
std::uint32_t range_start(std::size_t m, unsigned ranges, unsigned k) {
  return static_cast<std::uint32_t>(m * k / ranges);
}

/// Per sample: the incident tetrahedra chosen as p⁺ and p⁻ (kNoTet if none), and the
/// vector p⁺ − s.
struct Choice {
  /// Per tetrahedron, its circumcentre's offset (Circumsphere::offset; the squared radius
  /// is its squared norm, computed again where needed: the same value, in three quarters
  /// of the memory), in one array per range of tetrahedra (see range_start), each
  /// allocated and filled by its range's thread. Smaller arrays fit more often in pages
  /// freed earlier (see analyse_poles).
  std::vector<std::vector<Vec3>> offsets;
  std::size_t tetrahedra = 0;
  static detail::Circumsphere sphere_of(const Vec3& offset) {
    return {offset, squared_norm(offset)};
  }
  /// The sphere of tetrahedron t (its range found by a scan: not for every tetrahedron).
  detail::Circumsphere sphere(std::uint32_t t) const {
    unsigned k = 0;
    while (k + 1 < ranges() && t >= range_start(tetrahedra, ranges(), k + 1)) ++k;
    return sphere_of(offsets[k][t - range_start(tetrahedra, ranges(), k)]);
  }
  unsigned ranges() const { return static_cast<unsigned>(offsets.size()); }
  std::vector<std::uint32_t> first, second;
  std::vector<double> first_r2, second_r2;
  std::vector<Vec3> first_direction;
};

/// Whether tetrahedron t wins a tie in the circumradius against `current` (kNoTet: no
/// tetrahedron yet): the one whose vertex ids, sorted, come first lexicographically. So
/// the choice does not depend on the order of the soup (the Delaunay triangulation's cell
/// numbering, which parallel insertion does not fix).
bool wins_tie(const TetrahedronSoup& soup, std::uint32_t t, std::uint32_t current) {
  if (current == kNoTet) return true;
  std::array<std::uint32_t, 4> a = soup.tets[t];
  std::array<std::uint32_t, 4> b = soup.tets[current];
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  return a < b;
}

/// Whether tetrahedron t (squared circumradius r2) comes before the current choice: the
/// larger circumradius, ties by wins_tie. An order of the tetrahedra, except for copies
/// of one tetrahedron, where the first in the soup stays.
bool better(const TetrahedronSoup& soup, double r2, std::uint32_t t, double current_r2,
            std::uint32_t current) {
  return r2 > current_r2 || (r2 == current_r2 && wins_tie(soup, t, current));
}

Vec3 direction(const TetrahedronSoup& soup, const detail::Circumsphere& cs, std::uint32_t t,
               std::uint32_t s) {
  return (soup.vertices[soup.tets[t][0]] - soup.vertices[s]) + cs.offset;
}

/// A choice per sample among some tetrahedra: the best one and its squared radius.
struct Best {
  std::uint32_t* tet;
  double* r2;
};

/// Circumspheres of the tetrahedra [begin, end), and among them each sample's p⁺
/// candidate.
void spheres_and_first_poles(const TetrahedronSoup& soup, Choice& choice, unsigned range,
                             std::uint32_t begin, std::uint32_t end, std::uint32_t n, Best best) {
  std::vector<Vec3>& offsets = choice.offsets[range];
  offsets.resize(end - begin);
  for (std::uint32_t t = begin; t < end; ++t) {
    const auto& q = soup.tets[t];
    const detail::Circumsphere cs = detail::circumsphere(
        soup.vertices[q[0]], soup.vertices[q[1]], soup.vertices[q[2]], soup.vertices[q[3]]);
    offsets[t - begin] = cs.offset;
    for (const std::uint32_t s : q) {
      if (s < n && better(soup, cs.squared_radius, t, best.r2[s], best.tet[s])) {
        best.r2[s] = cs.squared_radius;
        best.tet[s] = t;
      }
    }
  }
}

/// Among the tetrahedra [begin, end), each sample's p⁻ candidate (its p⁺ chosen).
void second_poles(const TetrahedronSoup& soup, const Choice& choice, unsigned range,
                  std::uint32_t begin, std::uint32_t end, std::uint32_t n, Best best) {
  const std::vector<Vec3>& offsets = choice.offsets[range];
  for (std::uint32_t t = begin; t < end; ++t) {
    const auto& q = soup.tets[t];
    const detail::Circumsphere cs = Choice::sphere_of(offsets[t - begin]);
    for (const std::uint32_t s : q) {
      if (s >= n || choice.first[s] == t ||
          !better(soup, cs.squared_radius, t, best.r2[s], best.tet[s])) {
        continue;
      }
      if (dot(direction(soup, cs, t, s), choice.first_direction[s]) < 0) {
        best.r2[s] = cs.squared_radius;
        best.tet[s] = t;
      }
    }
  }
}

/// Runs pass(k, begin, end, best) over the tetrahedra in `ranges` consecutive ranges
/// (range_start), range k on thread k, each with a choice per sample of its own (range 0
/// writes `tet`, `r2` directly), then keeps for each sample the best of the ranges'
/// choices, earlier ranges first: the same choice as one pass over all tetrahedra, since
/// `better` orders them (and keeps the first of equal copies).
template <class Pass>
void choose_in_ranges(const TetrahedronSoup& soup, unsigned ranges, std::vector<std::uint32_t>& tet,
                      std::vector<double>& r2, Pass&& pass) {
  const std::size_t n = tet.size();
  const std::size_t m = soup.tets.size();
  std::vector<std::vector<std::uint32_t>> tets(ranges - 1);
  std::vector<std::vector<double>> r2s(ranges - 1);
  detail::run_blocks(ranges, [&](unsigned k) {
    Best best{tet.data(), r2.data()};
    if (k > 0) {
      tets[k - 1].assign(n, kNoTet);
      r2s[k - 1].assign(n, -1.0);
      best = {tets[k - 1].data(), r2s[k - 1].data()};
    }
    pass(k, range_start(m, ranges, k), range_start(m, ranges, k + 1), best);
  });
  for (unsigned k = 1; k < ranges; ++k) {
    for (std::size_t s = 0; s < n; ++s) {
      const std::uint32_t t = tets[k - 1][s];
      if (t != kNoTet && better(soup, r2s[k - 1][s], t, r2[s], tet[s])) {
        tet[s] = t;
        r2[s] = r2s[k - 1][s];
      }
    }
  }
}

}  // namespace

PoleSet compute_poles(const TetrahedronSoup& soup, unsigned threads,
                      std::size_t tetrahedra_per_thread) {
  check_soup(soup, threads);
  const std::size_t n = soup.sample_count;
  Choice choice;
  choice.first.assign(n, kNoTet);
  choice.second.assign(n, kNoTet);
  choice.first_r2.assign(n, -1.0);
  choice.second_r2.assign(n, -1.0);
  choice.first_direction.resize(n);
  // Each thread takes one range of tetrahedra and chooses among them for every sample
  // (circumspheres too, in the first pass); the ranges' choices are then merged. Threads
  // that each read every tetrahedron for a range of samples were slower: compute_poles,
  // two threads, medians of interleaved runs: double torus 0.083 -> 0.061 s, 3·10^5 torus
  // samples 0.52 -> 0.41 s.
  const unsigned hardware = std::max(1U, std::thread::hardware_concurrency());
  const auto ranges = static_cast<unsigned>(std::max<std::size_t>(
      1, std::min<std::size_t>(threads != 0 ? threads : hardware,
                               soup.tets.size() / std::max<std::size_t>(1, tetrahedra_per_thread))));
  const auto samples = static_cast<std::uint32_t>(n);
  choice.offsets.resize(ranges);
  choice.tetrahedra = soup.tets.size();
  choose_in_ranges(soup, ranges, choice.first, choice.first_r2,
                   [&](unsigned k, std::uint32_t begin, std::uint32_t end, Best best) {
                     spheres_and_first_poles(soup, choice, k, begin, end, samples, best);
                   });
  parallel_chunks(n, ranges, std::size_t{1} << 14, [&](std::size_t begin, std::size_t end, unsigned) {
    for (auto s = static_cast<std::uint32_t>(begin); s < end; ++s) {
      const std::uint32_t t = choice.first[s];
      if (t != kNoTet) choice.first_direction[s] = direction(soup, choice.sphere(t), t, s);
    }
  });
  choose_in_ranges(soup, ranges, choice.second, choice.second_r2,
                   [&](unsigned k, std::uint32_t begin, std::uint32_t end, Best best) {
                     second_poles(soup, choice, k, begin, end, samples, best);
                   });

  // Distinct poles, numbered in the order of their owners (the smallest sample having
  // them as a pole), p⁺ before p⁻: not in the order of the soup. A sample owns its choice
  // t unless a smaller vertex of t chose t too, so each block of samples finds its new
  // poles on its own, then writes them from its offset; the others then take their
  // owner's number. (A table of every tetrahedron's pole, filled in one pass over the
  // samples, took 0.5 s for 10^6 torus samples: 20.6M tetrahedra.)
  const auto owned_by = [&](std::uint32_t t, std::uint32_t s, std::uint32_t& owner,
                            int& slot) {
    owner = s;
    slot = -1;
    for (const std::uint32_t u : soup.tets[t]) {
      if (u >= owner) continue;
      if (choice.first[u] == t) {
        owner = u;
        slot = 0;
      } else if (choice.second[u] == t) {
        owner = u;
        slot = 1;
      }
    }
    return owner == s;
  };
  std::vector<std::array<std::uint32_t, 2>> pole_ids(n, {kNoPole, kNoPole});
  std::vector<std::uint8_t> owns(n, 0);  // bit w: the sample owns its choice w (p⁺, p⁻)
  std::vector<std::size_t> block_offset(ranges + 1, 0);
  const auto block_begin = [&](unsigned k) { return static_cast<std::uint32_t>(n * k / ranges); };
  const auto chosen = [&](std::uint32_t s, int which) {
    return which == 0 ? choice.first[s] : choice.second[s];
  };
  detail::run_blocks(ranges, [&](unsigned k) {
    std::size_t count = 0;
    std::uint32_t owner = 0;
    int slot = 0;
    for (std::uint32_t s = block_begin(k); s < block_begin(k + 1); ++s) {
      for (int which = 0; which < 2; ++which) {
        const std::uint32_t t = chosen(s, which);
        if (t == kNoTet || !owned_by(t, s, owner, slot)) continue;
        owns[s] = static_cast<std::uint8_t>(owns[s] | (1u << which));
        ++count;
      }
    }
    block_offset[k + 1] = count;
  });
  for (unsigned k = 0; k < ranges; ++k) block_offset[k + 1] += block_offset[k];
  const std::size_t pole_count = block_offset[ranges];
  PoleSet poles;
  poles.sample_count = n;
  // Fresh pages, mostly (the soup and the spheres still hold the earlier stages' pages):
  // value-initialising them all on one thread took 0.23-0.25 s for the 1.7·10^6 poles of
  // 10^6 torus samples, with the other core idle. Two threads share them.
  const auto allocate = [&](unsigned k) {
    if (k == 0 || ranges == 1) {
      poles.centre.resize(pole_count);
      poles.owner.resize(pole_count);
      poles.label.assign(pole_count, PoleLabel::unlabelled);
    }
    if (k == 1 || ranges == 1) {
      poles.radius.resize(pole_count);
      poles.tet.resize(pole_count);
      poles.sites.resize(pole_count);
      poles.sample_poles.resize(n);
      poles.representative.resize(n);
    }
  };
  detail::run_blocks(std::min(ranges, 2U), allocate);
  detail::run_blocks(ranges, [&](unsigned k) {
    std::size_t next = block_offset[k];
    for (std::uint32_t s = block_begin(k); s < block_begin(k + 1); ++s) {
      for (int which = 0; which < 2; ++which) {
        if ((owns[s] >> which & 1u) == 0) continue;
        const std::uint32_t t = chosen(s, which);
        const detail::Circumsphere cs = choice.sphere(t);
        poles.centre[next] = soup.vertices[soup.tets[t][0]] + cs.offset;
        poles.radius[next] = std::sqrt(cs.squared_radius);
        poles.tet[next] = t;
        poles.sites[next] = soup.tets[t];
        poles.owner[next] = s;
        pole_ids[s][static_cast<std::size_t>(which)] = static_cast<std::uint32_t>(next++);
      }
    }
  });
  // Every owner's numbers are written: the choices owned by another sample take them.
  detail::run_blocks(ranges, [&](unsigned k) {
    std::uint32_t owner = 0;
    int slot = 0;
    for (std::uint32_t s = block_begin(k); s < block_begin(k + 1); ++s) {
      for (int which = 0; which < 2; ++which) {
        const std::uint32_t t = chosen(s, which);
        if (t == kNoTet || (owns[s] >> which & 1u) != 0) continue;
        owned_by(t, s, owner, slot);
        pole_ids[s][static_cast<std::size_t>(which)] =
            pole_ids[owner][static_cast<std::size_t>(slot)];
      }
    }
  });
  parallel_chunks(n, ranges, std::size_t{1} << 14, [&](std::size_t begin, std::size_t end, unsigned) {
    for (std::size_t s = begin; s < end; ++s) {
      const std::uint32_t r =
          soup.representative.empty() ? static_cast<std::uint32_t>(s) : soup.representative[s];
      poles.representative[s] = r;
      poles.sample_poles[s] = pole_ids[r];
    }
  });
  return poles;
}

bool PoleSet::is_valid() const {
  const std::size_t m = centre.size();
  if (radius.size() != m || tet.size() != m || sites.size() != m || owner.size() != m ||
      label.size() != m || sample_poles.size() != sample_count ||
      representative.size() != sample_count) {
    return false;
  }
  for (std::size_t p = 0; p < m; ++p) {
    if (!is_finite(centre[p]) || !std::isfinite(radius[p]) || !(radius[p] > 0)) return false;
    if (owner[p] >= sample_count) return false;
  }
  // One entry per pole: no tetrahedron twice.
  std::vector<std::uint32_t> tets(tet);
  std::sort(tets.begin(), tets.end());
  if (std::adjacent_find(tets.begin(), tets.end()) != tets.end()) return false;
  for (std::uint32_t s = 0; s < sample_count; ++s) {
    const auto [a, b] = sample_poles[s];
    const std::uint32_t r = representative[s];
    if (r >= sample_count || representative[r] != r) return false;
    if (a == kNoPole && b != kNoPole) return false;
    for (const std::uint32_t p : sample_poles[s]) {
      if (p == kNoPole) continue;
      if (p >= m) return false;
      if (std::find(sites[p].begin(), sites[p].end(), r) == sites[p].end()) return false;
      if (owner[p] > r) return false;
    }
    if (a != kNoPole && b != kNoPole) {
      if (a == b || radius[b] > radius[a]) return false;
    }
  }
  return true;
}

}  // namespace rstruct::poles
