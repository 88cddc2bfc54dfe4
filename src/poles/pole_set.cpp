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

/// Per sample: the incident tetrahedra chosen as p⁺ and p⁻ (kNoTet if none), and the
/// vector p⁺ − s.
struct Choice {
  /// Per tetrahedron, its circumcentre's offset (Circumsphere::offset; the squared radius
  /// is its squared norm, computed again where needed: the same value, in three quarters
  /// of the memory), in one array per chunk of `chunk` tetrahedra, each allocated and
  /// filled by the thread that takes the chunk. Arrays of a few MiB fit more often in
  /// pages freed earlier than one of the whole soup's size (see analyse_poles).
  std::vector<std::vector<Vec3>> offsets;
  std::size_t chunk = 1;
  static detail::Circumsphere sphere_of(const Vec3& offset) {
    return {offset, squared_norm(offset)};
  }
  detail::Circumsphere sphere(std::uint32_t t) const {
    return sphere_of(offsets[t / chunk][t % chunk]);
  }
  std::vector<std::uint32_t> first, second;
  std::vector<double> first_r2, second_r2;
  std::vector<Vec3> first_direction;
};

/// Whether tetrahedron t wins a tie in the circumradius against `current` (kNoTet: no
/// tetrahedron yet): the one whose vertex ids, sorted, come first lexicographically. So
/// the choice does not depend on the order of the soup (the Delaunay triangulation's cell
/// numbering, which parallel insertion does not fix). Between copies of one tetrahedron,
/// the first in the soup.
bool wins_tie(const TetrahedronSoup& soup, std::uint32_t t, std::uint32_t current) {
  if (current == kNoTet) return true;
  std::array<std::uint32_t, 4> a = soup.tets[t];
  std::array<std::uint32_t, 4> b = soup.tets[current];
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  return a < b || (a == b && t < current);
}

/// Whether tetrahedron t (squared circumradius r2) comes before the current choice: the
/// larger circumradius, ties by wins_tie. A strict order of the tetrahedra, so the choice
/// does not depend on the order in which they are seen.
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

/// The vertices of a tetrahedron some places ahead, and their samples' choices so far, are
/// asked for before they are needed (the soup's order is the triangulation's cell order:
/// its vertices are scattered over the samples).
constexpr std::uint32_t kAhead = 16;
void prefetch_tet(const TetrahedronSoup& soup, const std::array<std::uint32_t, 4>& q,
                  std::uint32_t n, Best best) {
  for (const std::uint32_t s : q) {
    __builtin_prefetch(&soup.vertices[s]);
    if (s < n) {
      __builtin_prefetch(&best.r2[s]);
      __builtin_prefetch(&best.tet[s]);
    }
  }
}

/// Circumspheres of the tetrahedra [begin, end), and among them each sample's p⁺
/// candidate.
void spheres_and_first_poles(const TetrahedronSoup& soup, Choice& choice, std::size_t chunk,
                             std::uint32_t begin, std::uint32_t end, std::uint32_t n, Best best) {
  std::vector<Vec3>& offsets = choice.offsets[chunk];
  offsets.resize(end - begin);
  for (std::uint32_t t = begin; t < end; ++t) {
    if (t + kAhead < end) prefetch_tet(soup, soup.tets[t + kAhead], n, best);
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
void second_poles(const TetrahedronSoup& soup, const Choice& choice, std::size_t chunk,
                  std::uint32_t begin, std::uint32_t end, std::uint32_t n, Best best) {
  const std::vector<Vec3>& offsets = choice.offsets[chunk];
  for (std::uint32_t t = begin; t < end; ++t) {
    if (t + kAhead < end) prefetch_tet(soup, soup.tets[t + kAhead], n, best);
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

/// Runs pass(j, begin, end, best) over the tetrahedra, cut into chunks of `chunk`, on
/// `workers` threads, each taking the next chunk when it is done with one (a fixed range
/// per thread left a core idle for a fifth of the pass: one thread's offsets landed in
/// fresh pages, the other's in pages freed earlier), each thread with a choice per sample
/// of its own (thread 0 writes `tet`, `r2` directly); then keeps for each sample the best
/// of the threads' choices: the same choice as one pass over all tetrahedra in any order,
/// since `better` is a strict order.
template <class Pass>
void choose_in_chunks(const TetrahedronSoup& soup, unsigned workers, std::size_t chunk,
                      std::vector<std::uint32_t>& tet, std::vector<double>& r2, Pass&& pass) {
  const std::size_t n = tet.size();
  const std::size_t m = soup.tets.size();
  const std::size_t chunks = (m + chunk - 1) / chunk;
  std::vector<std::vector<std::uint32_t>> tets(workers - 1);
  std::vector<std::vector<double>> r2s(workers - 1);
  std::atomic<std::size_t> next{0};
  detail::run_blocks(workers, [&](unsigned k) {
    Best best{tet.data(), r2.data()};
    if (k > 0) {
      tets[k - 1].assign(n, kNoTet);
      r2s[k - 1].assign(n, -1.0);
      best = {tets[k - 1].data(), r2s[k - 1].data()};
    }
    for (std::size_t j = next.fetch_add(1, std::memory_order_relaxed); j < chunks;
         j = next.fetch_add(1, std::memory_order_relaxed)) {
      pass(j, static_cast<std::uint32_t>(j * chunk),
           static_cast<std::uint32_t>(std::min(m, (j + 1) * chunk)), best);
    }
  });
  for (unsigned k = 1; k < workers; ++k) {
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
  // Each thread takes chunks of tetrahedra and chooses among them for every sample
  // (circumspheres too, in the first pass); the threads' choices are then merged. Threads
  // that each read every tetrahedron for a range of samples were slower: compute_poles,
  // two threads, medians of interleaved runs: double torus 0.083 -> 0.061 s, 3·10^5 torus
  // samples 0.52 -> 0.41 s. About 16 chunks per thread, of at most 2^19 tetrahedra (12
  // MiB of offsets).
  const unsigned hardware = std::max(1U, std::thread::hardware_concurrency());
  const auto workers = static_cast<unsigned>(std::max<std::size_t>(
      1, std::min<std::size_t>(threads != 0 ? threads : hardware,
                               soup.tets.size() / std::max<std::size_t>(1, tetrahedra_per_thread))));
  const auto samples = static_cast<std::uint32_t>(n);
  const std::size_t m = soup.tets.size();
  choice.chunk = std::clamp<std::size_t>(m / (std::size_t{16} * workers), 1, std::size_t{1} << 19);
  choice.offsets.resize((m + choice.chunk - 1) / choice.chunk);
  choose_in_chunks(soup, workers, choice.chunk, choice.first, choice.first_r2,
                   [&](std::size_t j, std::uint32_t begin, std::uint32_t end, Best best) {
                     spheres_and_first_poles(soup, choice, j, begin, end, samples, best);
                   });
  parallel_chunks(n, workers, std::size_t{1} << 14, [&](std::size_t begin, std::size_t end, unsigned) {
    for (auto s = static_cast<std::uint32_t>(begin); s < end; ++s) {
      const std::uint32_t t = choice.first[s];
      if (t != kNoTet) choice.first_direction[s] = direction(soup, choice.sphere(t), t, s);
    }
  });
  choose_in_chunks(soup, workers, choice.chunk, choice.second, choice.second_r2,
                   [&](std::size_t j, std::uint32_t begin, std::uint32_t end, Best best) {
                     second_poles(soup, choice, j, begin, end, samples, best);
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
  std::vector<std::size_t> block_offset(workers + 1, 0);
  const auto block_begin = [&](unsigned k) { return static_cast<std::uint32_t>(n * k / workers); };
  const auto chosen = [&](std::uint32_t s, int which) {
    return which == 0 ? choice.first[s] : choice.second[s];
  };
  detail::run_blocks(workers, [&](unsigned k) {
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
  for (unsigned k = 0; k < workers; ++k) block_offset[k + 1] += block_offset[k];
  const std::size_t pole_count = block_offset[workers];
  PoleSet poles;
  poles.sample_count = n;
  // Fresh pages, mostly (the soup and the spheres still hold the earlier stages' pages):
  // value-initialising them all on one thread took 0.23-0.25 s for the 1.7·10^6 poles of
  // 10^6 torus samples, with the other core idle. Two threads share them.
  const auto allocate = [&](unsigned k) {
    if (k == 0 || workers == 1) {
      poles.centre.resize(pole_count);
      poles.owner.resize(pole_count);
      poles.label.assign(pole_count, PoleLabel::unlabelled);
    }
    if (k == 1 || workers == 1) {
      poles.radius.resize(pole_count);
      poles.tet.resize(pole_count);
      poles.sites.resize(pole_count);
      poles.sample_poles.resize(n);
      poles.representative.resize(n);
    }
  };
  detail::run_blocks(std::min(workers, 2U), allocate);
  detail::run_blocks(workers, [&](unsigned k) {
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
  detail::run_blocks(workers, [&](unsigned k) {
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
  parallel_chunks(n, workers, std::size_t{1} << 14, [&](std::size_t begin, std::size_t end, unsigned) {
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
