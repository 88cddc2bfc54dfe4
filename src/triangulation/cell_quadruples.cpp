// RegularTriangulation3::take_finite_cells: the finite cells' vertex quadruples, compacted
// in place over the cell array.

#include <algorithm>
#include <new>
#include <utility>

#include "rstruct/core/large_blocks.hpp"
#include "rstruct/core/parallel.hpp"
#include "rstruct/triangulation/regular_triangulation_3.hpp"

namespace rstruct::triangulation {

struct CellQuadruples::Storage {
  std::vector<RegularTriangulation3::Cell, HugePageAllocator<RegularTriangulation3::Cell>> cells;
};

CellQuadruples::CellQuadruples() = default;
CellQuadruples::CellQuadruples(CellQuadruples&& other) noexcept
    : storage_(std::move(other.storage_)),
      data_(std::exchange(other.data_, nullptr)),
      size_(std::exchange(other.size_, 0)) {}
CellQuadruples& CellQuadruples::operator=(CellQuadruples&& other) noexcept {
  storage_ = std::move(other.storage_);
  data_ = std::exchange(other.data_, nullptr);
  size_ = std::exchange(other.size_, 0);
  return *this;
}
// The quadruples, like the cells whose storage they reuse, are trivially destructible:
// releasing the storage ends their lifetimes.
CellQuadruples::~CellQuadruples() = default;

// A cell takes 32 bytes, a quadruple 16, so the k-th finite cell's quadruple, written at
// byte 16k, lies below the cell it comes from (byte 32c, c >= k). The cells are cut into
// chunks of kChunk ids; chunk j's quadruples go to [16 offset[j], 16 offset[j+1]), with
// offset[j+1] <= (j+1)·kChunk, so below byte 16 (j+1) kChunk: into the cells of chunks
// below (j+1)/2 only (and, for chunk 0, into cells it has read already: the k-th is
// written after the c-th cell is read, 16k + 16 <= 32c + 16, and k <= c). The chunks are
// therefore compacted in waves, [0, 1), [1, 2), [2, 4), [4, 8), ...: every chunk of a wave
// writes only over chunks of earlier waves, all read, and the writes of one wave are
// disjoint. Each chunk is read cell by cell, every cell before anything is written over it.
namespace {

/// q sorted increasingly, by a sorting network (five compare-exchanges; std::sort on four
/// ids was about a third of the pole analysis's pass over the cells).
std::array<VertexId, 4> sorted(std::array<VertexId, 4> q) {
  const auto exchange = [&](std::size_t i, std::size_t j) {
    const VertexId a = q[i], b = q[j];
    q[i] = std::min(a, b);
    q[j] = std::max(a, b);
  };
  exchange(0, 1);
  exchange(2, 3);
  exchange(0, 2);
  exchange(1, 3);
  exchange(1, 2);
  return q;
}

}  // namespace

CellQuadruples RegularTriangulation3::take_finite_cells(unsigned threads) {
  return take_finite_cells(threads, nullptr, false);
}

CellQuadruples RegularTriangulation3::take_finite_cells(unsigned threads, const VertexId* rename,
                                                        bool sort_each) {
  constexpr std::size_t kChunk = std::size_t{1} << 16;
  const std::size_t cap = cells_.size();
  const std::size_t chunks = (cap + kChunk - 1) / kChunk;
  const Cell* cells = cells_.data();
  const auto finite = [](const Cell& k) {
    return (k.v[0] != kFreeMark) & (k.v[0] != kInfiniteVertex) & (k.v[1] != kInfiniteVertex) &
           (k.v[2] != kInfiniteVertex) & (k.v[3] != kInfiniteVertex);
  };
  std::vector<std::size_t> offset(chunks + 1, 0);
  parallel_chunks(chunks, threads, 1, [&](std::size_t j, std::size_t, unsigned) {
    const std::size_t end = std::min(cap, (j + 1) * kChunk);
    std::size_t count = 0;
    for (std::size_t c = j * kChunk; c < end; ++c) count += finite(cells[c]) ? 1 : 0;
    offset[j + 1] = count;
  });
  for (std::size_t j = 0; j < chunks; ++j) offset[j + 1] += offset[j];

  CellQuadruples result;
  result.storage_ = std::make_unique<CellQuadruples::Storage>();
  result.storage_->cells = std::move(cells_);
  result.size_ = offset[chunks];
  static_assert(sizeof(Cell) == 2 * sizeof(std::array<VertexId, 4>));
  static_assert(alignof(Cell) >= alignof(std::array<VertexId, 4>));
  std::byte* const base = reinterpret_cast<std::byte*>(result.storage_->cells.data());
  const auto compact = [&](std::size_t j) {
    const auto* in = reinterpret_cast<const Cell*>(base) + j * kChunk;
    const auto* end = reinterpret_cast<const Cell*>(base) + std::min(cap, (j + 1) * kChunk);
    std::byte* const first_out = base + offset[j] * sizeof(std::array<VertexId, 4>);
    std::byte* out = first_out;
    for (; in != end; ++in) {
      const Cell k = *in;  // read whole before anything is written over it
      if (!finite(k)) continue;
      std::array<VertexId, 4> q{k.v[0], k.v[1], k.v[2], k.v[3]};
      if (rename != nullptr) {
        for (VertexId& v : q) v = rename[v];
      }
      ::new (static_cast<void*>(out)) std::array<VertexId, 4>{q};
      out += sizeof(std::array<VertexId, 4>);
    }
    // Sorted in a second loop over the chunk's quadruples (in the cache now): in the same
    // loop, the network (which GCC compiles to branches there, hard to predict) kept the
    // renaming's loads from overlapping (10^6 torus samples, one thread: 0.65 s against
    // 0.14-0.16 s for both loops).
    if (sort_each) {
      auto* q = std::launder(reinterpret_cast<std::array<VertexId, 4>*>(first_out));
      const auto count = static_cast<std::size_t>(out - first_out) / sizeof(std::array<VertexId, 4>);
      for (std::size_t i = 0; i < count; ++i) q[i] = sorted(q[i]);
    }
  };
  for (std::size_t first = 0; first < chunks; first = std::max<std::size_t>(1, 2 * first)) {
    const std::size_t last = std::min(chunks, std::max<std::size_t>(1, 2 * first));
    parallel_chunks(last - first, threads, 1,
                    [&](std::size_t i, std::size_t, unsigned) { compact(first + i); });
  }
  result.data_ = std::launder(reinterpret_cast<std::array<VertexId, 4>*>(base));
  // The cells past the quadruples are no longer needed: their pages go back to the
  // allocator (for the next stage's arrays) while the quadruples are in use.
  (void)shrink_large_block(base, result.storage_->cells.capacity() * sizeof(Cell),
                           result.size_ * sizeof(std::array<VertexId, 4>));

  cells_ = {};
  vertex_cell_ = {};
  free_head_ = kNoCell;
  free_count_ = 0;
  infinite_count_ = 0;
  return result;
}

}  // namespace rstruct::triangulation
