#include "rstruct/complex/simplicial_complex.hpp"

#include <algorithm>
#include <exception>
#include <limits>
#include <string>
#include <thread>

#include "rstruct/core/error.hpp"
#include "rstruct/core/parallel.hpp"

namespace rstruct::complex {
namespace {

constexpr SimplexIndex kRemoved = std::numeric_limits<SimplexIndex>::max();

template <std::size_t K>
std::string tuple_text(const std::array<VertexId, K>& s) {
  std::string out = "(";
  for (std::size_t i = 0; i < K; ++i) out += (i ? ", " : "") + std::to_string(s[i]);
  return out + ")";
}

const char* list_name(std::size_t k) {
  static const char* const names[] = {"vertex", "vertex", "edge", "triangle", "tetrahedron"};
  return names[k];
}

/// The tuple sorted increasingly; throws if a vertex repeats.
template <std::size_t K>
std::array<VertexId, K> normalized(std::array<VertexId, K> s, std::size_t position) {
  std::sort(s.begin(), s.end());
  for (std::size_t i = 0; i + 1 < K; ++i) {
    if (s[i] == s[i + 1]) {
      throw InvalidInput(std::string(list_name(K)) + " #" + std::to_string(position) + " " +
                         tuple_text(s) + " repeats vertex " + std::to_string(s[i]));
    }
  }
  return s;
}

/// Sorts records lexicographically by key(record) (a vertex tuple): a counting sort on the
/// first vertex, then a comparison sort inside each bucket (buckets are small: the
/// simplices sharing their lowest vertex). Falls back to one comparison sort when the ids
/// are too sparse for the counting array.
template <class Record, class KeyOf>
void sort_by_key(std::vector<Record>& records, KeyOf key) {
  const auto less = [&key](const Record& a, const Record& b) { return key(a) < key(b); };
  if (records.size() < 64) {
    std::sort(records.begin(), records.end(), less);
    return;
  }
  VertexId max_first = 0;
  for (const auto& r : records) max_first = std::max(max_first, key(r)[0]);
  if (max_first > 4 * records.size()) {
    std::sort(records.begin(), records.end(), less);
    return;
  }
  std::vector<std::size_t> start(static_cast<std::size_t>(max_first) + 2, 0);
  for (const auto& r : records) ++start[key(r)[0] + 1];
  for (std::size_t b = 1; b < start.size(); ++b) start[b] += start[b - 1];
  std::vector<Record> out(records.size());
  std::vector<std::size_t> fill(start.begin(), start.end() - 1);
  for (const auto& r : records) out[fill[key(r)[0]]++] = r;
  for (std::size_t b = 0; b + 1 < start.size(); ++b) {
    if (start[b + 1] - start[b] > 1) {
      std::sort(out.begin() + static_cast<std::ptrdiff_t>(start[b]),
                out.begin() + static_cast<std::ptrdiff_t>(start[b + 1]), less);
    }
  }
  records.swap(out);
}

template <std::size_t K>
std::vector<std::array<VertexId, K>> normalized_unique(
    const std::vector<std::array<VertexId, K>>& in) {
  std::vector<std::array<VertexId, K>> out(in.size());
  for (std::size_t i = 0; i < in.size(); ++i) out[i] = normalized(in[i], i);
  sort_by_key(out, [](const std::array<VertexId, K>& s) -> const std::array<VertexId, K>& {
    return s;
  });
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

template <std::size_t K>
std::array<VertexId, K - 1> without(const std::array<VertexId, K>& s, std::size_t i) {
  std::array<VertexId, K - 1> f{};
  for (std::size_t j = 0, o = 0; j < K; ++j) {
    if (j != i) f[o++] = s[j];
  }
  return f;
}

template <std::size_t K>
struct FaceRecord {
  std::array<VertexId, K> key;
  std::uint64_t ref;  // coface * (K + 1) + slot, or kNoRef for a listed simplex
};
constexpr std::uint64_t kNoRef = std::numeric_limits<std::uint64_t>::max();

/// The sorted, duplicate-free union of `listed` and the faces of `cofaces` (K-tuples),
/// and the face indices of every coface (face i omits vertex i).
template <std::size_t K>
std::vector<std::array<VertexId, K>> faces_with_incidence(
    const std::vector<std::array<VertexId, K + 1>>& cofaces,
    const std::vector<std::array<VertexId, K>>& listed,
    std::vector<std::array<SimplexIndex, K + 1>>& coface_faces) {
  std::vector<FaceRecord<K>> records;
  records.reserve(cofaces.size() * (K + 1) + listed.size());
  for (std::size_t c = 0; c < cofaces.size(); ++c) {
    for (std::size_t i = 0; i <= K; ++i) records.push_back({without(cofaces[c], i), c * (K + 1) + i});
  }
  for (const auto& s : listed) records.push_back({s, kNoRef});
  sort_by_key(records, [](const FaceRecord<K>& r) -> const std::array<VertexId, K>& {
    return r.key;
  });
  std::vector<std::array<VertexId, K>> faces;
  coface_faces.assign(cofaces.size(), {});
  for (const auto& r : records) {
    if (faces.empty() || faces.back() != r.key) {
      if (faces.size() >= kRemoved) throw InvalidInput("complex: too many simplices");
      faces.push_back(r.key);
    }
    if (r.ref != kNoRef) {
      coface_faces[r.ref / (K + 1)][r.ref % (K + 1)] = static_cast<SimplexIndex>(faces.size() - 1);
    }
  }
  return faces;
}

template <std::size_t K>
std::optional<SimplexIndex> find_in(const std::vector<std::array<VertexId, K>>& list,
                                    std::array<VertexId, K> s) {
  std::sort(s.begin(), s.end());
  const auto it = std::lower_bound(list.begin(), list.end(), s);
  if (it == list.end() || *it != s) return std::nullopt;
  return static_cast<SimplexIndex>(it - list.begin());
}

/// Keeps the flagged entries of `list`, returns the old → new index map (kRemoved if
/// dropped).
template <class T>
std::vector<SimplexIndex> filter(std::vector<T>& list, const std::vector<bool>& keep) {
  std::vector<SimplexIndex> remap(list.size(), kRemoved);
  std::size_t o = 0;
  for (std::size_t i = 0; i < list.size(); ++i) {
    if (!keep[i]) continue;
    remap[i] = static_cast<SimplexIndex>(o);
    list[o++] = list[i];
  }
  list.resize(o);
  return remap;
}

template <std::size_t K, class Cofaces>
void remap_faces(std::vector<std::array<SimplexIndex, K>>& faces,
                 const std::vector<SimplexIndex>& face_remap, const Cofaces& cofaces) {
  for (std::size_t c = 0; c < faces.size(); ++c) {
    for (std::size_t i = 0; i < K; ++i) {
      const SimplexIndex n = face_remap[faces[c][i]];
      if (n == kRemoved) {
        throw InvalidInput(std::string("subcomplex: ") + list_name(K) + " " +
                           tuple_text(cofaces[c]) + " is kept but its face " +
                           tuple_text(without(cofaces[c], i)) + " is not");
      }
      faces[c][i] = n;
    }
  }
}

template <std::size_t K>
bool strictly_sorted(const std::vector<std::array<VertexId, K>>& list) {
  for (std::size_t i = 0; i < list.size(); ++i) {
    for (std::size_t j = 0; j + 1 < K; ++j) {
      if (list[i][j] >= list[i][j + 1]) return false;
    }
    if (i > 0 && !(list[i - 1] < list[i])) return false;
  }
  return true;
}

template <std::size_t K, class FaceList>
bool faces_match(const std::vector<std::array<VertexId, K>>& list,
                 const std::vector<std::array<SimplexIndex, K>>& faces, const FaceList& lower) {
  if (faces.size() != list.size()) return false;
  for (std::size_t c = 0; c < list.size(); ++c) {
    for (std::size_t i = 0; i < K; ++i) {
      if (faces[c][i] >= lower.size()) return false;
      const auto f = without(list[c], i);
      if constexpr (K == 2) {
        if (lower[faces[c][i]] != f[0]) return false;
      } else {
        if (lower[faces[c][i]] != f) return false;
      }
    }
  }
  return true;
}

}  // namespace

SimplicialComplex SimplicialComplex::closure_of(const SimplexLists& simplices) {
  SimplicialComplex k;
  k.tetrahedra_ = normalized_unique(simplices.tetrahedra);
  k.triangles_ = faces_with_incidence<3>(k.tetrahedra_, normalized_unique(simplices.triangles),
                                         k.tetrahedron_faces_);
  k.edges_ = faces_with_incidence<2>(k.triangles_, normalized_unique(simplices.edges),
                                     k.triangle_faces_);
  std::vector<std::array<VertexId, 1>> listed(simplices.vertices.size());
  for (std::size_t i = 0; i < listed.size(); ++i) listed[i] = {simplices.vertices[i]};
  const auto vertices = faces_with_incidence<1>(k.edges_, listed, k.edge_faces_);
  k.vertices_.resize(vertices.size());
  for (std::size_t i = 0; i < vertices.size(); ++i) k.vertices_[i] = vertices[i][0];
  return k;
}

SimplicialComplex SimplicialComplex::closure_of(std::span<const Tetrahedron> tetrahedra) {
  SimplexLists lists;
  lists.tetrahedra.assign(tetrahedra.begin(), tetrahedra.end());
  return closure_of(lists);
}

SimplicialComplex SimplicialComplex::closure_of(std::span<const Triangle> triangles) {
  SimplexLists lists;
  lists.triangles.assign(triangles.begin(), triangles.end());
  return closure_of(lists);
}

SimplicialComplex SimplicialComplex::closure_of(std::span<const Edge> edges) {
  SimplexLists lists;
  lists.edges.assign(edges.begin(), edges.end());
  return closure_of(lists);
}

namespace {

/// Index of a tuple in a sorted, duplicate-free list of K-tuples: the range of tuples with
/// the same first vertex comes from a table by first vertex (when the ids are dense
/// enough for one: at most 4 entries per tuple), then a binary search inside it.
template <std::size_t K>
class SortedLookup {
 public:
  explicit SortedLookup(const std::vector<std::array<VertexId, K>>& list) : list_(list) {
    if (list.empty() || list.back()[0] > 4 * list.size() + 1024) return;
    start_.assign(static_cast<std::size_t>(list.back()[0]) + 2, 0);
    for (const auto& s : list) ++start_[s[0] + 1];
    for (std::size_t v = 1; v < start_.size(); ++v) start_[v] += start_[v - 1];
  }
  /// The index of s, or kRemoved if s is not in the list.
  SimplexIndex find(const std::array<VertexId, K>& s) const {
    auto begin = list_.begin();
    auto end = list_.end();
    if (!start_.empty()) {
      if (std::size_t{s[0]} + 1 >= start_.size()) return kRemoved;
      end = begin + static_cast<std::ptrdiff_t>(start_[s[0] + 1]);
      begin += static_cast<std::ptrdiff_t>(start_[s[0]]);
    }
    const auto it = std::lower_bound(begin, end, s);
    return it != end && *it == s ? static_cast<SimplexIndex>(it - list_.begin()) : kRemoved;
  }

 private:
  const std::vector<std::array<VertexId, K>>& list_;
  std::vector<std::uint32_t> start_;
};

/// coface_faces[c][i] = the index in `lower` of face i of cofaces[c]; throws naming a
/// coface and its face missing from `lower`. In parallel chunks.
template <std::size_t C, class Lookup>
void link_faces(const std::vector<std::array<VertexId, C>>& cofaces, const Lookup& lower,
                std::vector<std::array<SimplexIndex, C>>& coface_faces, unsigned threads) {
  coface_faces.resize(cofaces.size());
  parallel_chunks(cofaces.size(), threads, std::size_t{1} << 15,
                  [&](std::size_t b, std::size_t e, unsigned /*worker*/) {
                    for (std::size_t c = b; c < e; ++c) {
                      for (std::size_t i = 0; i < C; ++i) {
                        const auto f = without(cofaces[c], i);
                        const SimplexIndex index = lower.find(f);
                        if (index == kRemoved) {
                          throw InvalidInput(std::string("complex not closed: ") +
                                             list_name(C) + " " + tuple_text(cofaces[c]) +
                                             " has face " + tuple_text(f) +
                                             " that is not listed");
                        }
                        coface_faces[c][i] = index;
                      }
                    }
                  });
}

}  // namespace

// The lists are sorted (the triangles, usually the longest, on a second thread) and
// every face is then looked up in the sorted list below it, in parallel chunks: no sort
// of all the faces of all the cofaces, as closure_of needs (the dual complex of a
// 85,237-ball double torus: 0.23 s for closure_of, one thread).
SimplicialComplex SimplicialComplex::from_closed_lists(const SimplexLists& simplices,
                                                       unsigned threads) {
  SimplicialComplex k;
  std::vector<std::array<VertexId, 1>> vertices(simplices.vertices.size());
  const auto sort_others = [&] {
    k.tetrahedra_ = normalized_unique(simplices.tetrahedra);
    k.edges_ = normalized_unique(simplices.edges);
    for (std::size_t i = 0; i < vertices.size(); ++i) vertices[i] = {simplices.vertices[i]};
    vertices = normalized_unique(vertices);
  };
  if (thread_count(threads, 2) >= 2) {
    std::exception_ptr error;
    std::thread triangles([&] {
      try {
        k.triangles_ = normalized_unique(simplices.triangles);
      } catch (...) {
        error = std::current_exception();
      }
    });
    try {
      sort_others();
    } catch (...) {
      triangles.join();
      throw;
    }
    triangles.join();
    if (error) std::rethrow_exception(error);
  } else {
    k.triangles_ = normalized_unique(simplices.triangles);
    sort_others();
  }
  k.vertices_.resize(vertices.size());
  for (std::size_t i = 0; i < vertices.size(); ++i) k.vertices_[i] = vertices[i][0];
  link_faces(k.tetrahedra_, SortedLookup<3>(k.triangles_), k.tetrahedron_faces_, threads);
  link_faces(k.triangles_, SortedLookup<2>(k.edges_), k.triangle_faces_, threads);
  link_faces(k.edges_, SortedLookup<1>(vertices), k.edge_faces_, threads);
  return k;
}

SimplicialComplex SimplicialComplex::subcomplex(
    const std::array<std::vector<bool>, 4>& keep) const {
  for (int d = 0; d < 4; ++d) {
    if (keep[d].size() != size(d)) {
      throw InvalidInput("subcomplex: flag vector of dimension " + std::to_string(d) +
                         " has size " + std::to_string(keep[d].size()) + ", expected " +
                         std::to_string(size(d)));
    }
  }
  SimplicialComplex k = *this;
  const auto vertex_map = filter(k.vertices_, keep[0]);
  const auto edge_map = filter(k.edges_, keep[1]);
  const auto triangle_map = filter(k.triangles_, keep[2]);
  filter(k.tetrahedra_, keep[3]);
  filter(k.edge_faces_, keep[1]);
  filter(k.triangle_faces_, keep[2]);
  filter(k.tetrahedron_faces_, keep[3]);
  remap_faces(k.edge_faces_, vertex_map, k.edges_);
  remap_faces(k.triangle_faces_, edge_map, k.triangles_);
  remap_faces(k.tetrahedron_faces_, triangle_map, k.tetrahedra_);
  return k;
}

int SimplicialComplex::dimension() const {
  for (int d = 3; d >= 0; --d) {
    if (size(d) > 0) return d;
  }
  return -1;
}

std::size_t SimplicialComplex::size(int d) const {
  switch (d) {
    case 0: return vertices_.size();
    case 1: return edges_.size();
    case 2: return triangles_.size();
    case 3: return tetrahedra_.size();
    default: return 0;
  }
}

std::span<const SimplexIndex> SimplicialComplex::faces(int d, SimplexIndex i) const {
  switch (d) {
    case 1: return edge_faces_.at(i);
    case 2: return triangle_faces_.at(i);
    case 3: return tetrahedron_faces_.at(i);
    default: throw InvalidInput("faces: dimension " + std::to_string(d) + " not in 1..3");
  }
}

std::optional<SimplexIndex> SimplicialComplex::find_vertex(VertexId v) const {
  const auto it = std::lower_bound(vertices_.begin(), vertices_.end(), v);
  if (it == vertices_.end() || *it != v) return std::nullopt;
  return static_cast<SimplexIndex>(it - vertices_.begin());
}
std::optional<SimplexIndex> SimplicialComplex::find(Edge e) const { return find_in(edges_, e); }
std::optional<SimplexIndex> SimplicialComplex::find(Triangle t) const {
  return find_in(triangles_, t);
}
std::optional<SimplexIndex> SimplicialComplex::find(Tetrahedron t) const {
  return find_in(tetrahedra_, t);
}

long long SimplicialComplex::euler_characteristic() const {
  return static_cast<long long>(size(0)) - static_cast<long long>(size(1)) +
         static_cast<long long>(size(2)) - static_cast<long long>(size(3));
}

bool SimplicialComplex::is_valid() const {
  for (std::size_t i = 1; i < vertices_.size(); ++i) {
    if (vertices_[i - 1] >= vertices_[i]) return false;
  }
  return strictly_sorted(edges_) && strictly_sorted(triangles_) && strictly_sorted(tetrahedra_) &&
         faces_match(edges_, edge_faces_, vertices_) &&
         faces_match(triangles_, triangle_faces_, edges_) &&
         faces_match(tetrahedra_, tetrahedron_faces_, triangles_);
}

}  // namespace rstruct::complex
