#include "rstruct/triangulation/vertex_stars.hpp"

#include <algorithm>

#include "rstruct/core/assert.hpp"
#include "rstruct/core/parallel.hpp"

namespace rstruct::triangulation {

VertexStars::VertexStars(const RegularTriangulation3& rt, unsigned threads,
                         std::size_t cells_per_thread, Neighbors neighbors) {
  const std::size_t n = rt.number_of_points();
  // Stars: the cells are counted per vertex, then written in increasing id order (every
  // star ends up sorted). The writes land all over the array: with several threads each
  // writes the stars of one range of vertices (a range of the array) and reads every cell.
  // Threads splitting the cells instead wrote into the same stars, side by side, and the
  // cache lines went back and forth: no faster than one thread. Reading every cell twice
  // pays from about 4·2^20 cells per thread on (the default cells_per_thread): stars of
  // 10^6 samples on a torus, 2·10^7 cells, 3.58 -> 2.80 s; of 3·10^5 samples 0.74-0.81 ->
  // 0.67-0.71 s; of the double torus's 1.5·10^6 cells 0.093-0.101 -> 0.101-0.109 s.
  const std::size_t cap = rt.cell_capacity();
  cell_offsets_.assign(n + 1, 0);
  rt.for_each_cell([&](CellId c) {
    for (int i = 0; i < 4; ++i) {
      const VertexId v = rt.vertex(c, i);
      if (v != kInfiniteVertex) ++cell_offsets_[v + 1];
    }
  });
  for (std::size_t v = 0; v < n; ++v) cell_offsets_[v + 1] += cell_offsets_[v];
  cells_.resize(cell_offsets_[n]);
  {
    std::vector<std::size_t> fill(cell_offsets_.begin(), cell_offsets_.end() - 1);
    const unsigned pieces = thread_count(threads, cap, cells_per_thread);
    const std::size_t piece = (n + pieces - 1) / pieces;
    parallel_chunks(n, pieces, piece, [&](std::size_t first, std::size_t last, unsigned) {
      for (CellId c = 0; c < cap; ++c) {
        if (!rt.is_cell(c)) continue;
        for (int i = 0; i < 4; ++i) {
          const VertexId v = rt.vertex(c, i);
          if (v >= first && v < last && v != kInfiniteVertex) cells_[fill[v]++] = c;
        }
      }
    });
  }

  if (neighbors == Neighbors::build) build_neighbors(rt, threads);
}

void VertexStars::set_neighbors(const RegularTriangulation3& rt, std::vector<std::size_t> offsets,
                                std::vector<VertexId> lists) {
  RSTRUCT_ASSERT_MSG(offsets.size() == size() + 1 && offsets.back() == lists.size(),
                     "VertexStars::set_neighbors: offsets do not match the stars");
  neighbor_offsets_ = std::move(offsets);
  neighbors_ = std::move(lists);
  if constexpr (check_level() >= 2) {
    VertexStars built(rt, 1, kCellsPerThread, Neighbors::deferred);
    built.build_neighbors(rt, 1);
    RSTRUCT_ASSERT_MSG(built.neighbor_offsets_ == neighbor_offsets_ && built.neighbors_ == neighbors_,
                       "VertexStars::set_neighbors: the lists are not the stars' neighbours");
  }
}

void VertexStars::build_neighbors(const RegularTriangulation3& rt, unsigned threads) {
  const std::size_t n = size();
  // Neighbours: the other finite vertices of the star, sorted and deduplicated. Each
  // chunk of vertices fills its own list; the lists are then concatenated in order.
  constexpr std::size_t kChunk = 4096;
  constexpr std::size_t kAhead = 8;  // star cells are read this far ahead (scattered loads)
  const std::size_t chunks = (n + kChunk - 1) / kChunk;
  std::vector<std::vector<VertexId>> lists(chunks);
  std::vector<std::vector<std::uint32_t>> counts(chunks);
  // last[w][u] == v + 1 once worker w listed u for v: each neighbour is pushed once, and
  // only the distinct neighbours are sorted (a star lists each about five times).
  std::vector<std::vector<VertexId>> last(thread_count(threads, chunks, 1));
  parallel_chunks(chunks, threads, 1, [&](std::size_t begin, std::size_t end, unsigned w) {
    std::vector<VertexId> scratch;
    std::vector<VertexId>& seen = last[w];
    if (seen.empty()) seen.assign(n, 0);
    for (std::size_t k = begin; k < end; ++k) {
      const std::size_t first = k * kChunk;
      const std::size_t last = std::min(n, first + kChunk);
      std::vector<VertexId>& list = lists[k];
      std::vector<std::uint32_t>& count = counts[k];
      count.resize(last - first);
      for (std::size_t v = first; v < last; ++v) {
        scratch.clear();
        const auto mark = static_cast<VertexId>(v + 1);
        const auto star = cells(static_cast<VertexId>(v));
        for (std::size_t k = 0; k < std::min(star.size(), kAhead); ++k) rt.prefetch_cell(star[k]);
        for (std::size_t k = 0; k < star.size(); ++k) {
          if (k + kAhead < star.size()) rt.prefetch_cell(star[k + kAhead]);
          const CellId c = star[k];
          for (int i = 0; i < 4; ++i) {
            const VertexId u = rt.vertex(c, i);
            if (u != kInfiniteVertex && u != v && seen[u] != mark) {
              seen[u] = mark;
              scratch.push_back(u);
            }
          }
        }
        std::sort(scratch.begin(), scratch.end());
        count[v - first] = static_cast<std::uint32_t>(scratch.size());
        list.insert(list.end(), scratch.begin(), scratch.end());
      }
    }
  });
  neighbor_offsets_.assign(n + 1, 0);
  for (std::size_t k = 0; k < chunks; ++k) {
    for (std::size_t i = 0; i < counts[k].size(); ++i) {
      const std::size_t v = k * kChunk + i;
      neighbor_offsets_[v + 1] = neighbor_offsets_[v] + counts[k][i];
    }
  }
  neighbors_.reserve(neighbor_offsets_[n]);
  for (auto& list : lists) {
    neighbors_.insert(neighbors_.end(), list.begin(), list.end());
    std::vector<VertexId>().swap(list);
  }
}

}  // namespace rstruct::triangulation
