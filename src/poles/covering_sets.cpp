#include "rstruct/poles/covering_sets.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <thread>

#include "parallel_blocks.hpp"
#include "point_tree.hpp"
#include "spatial_order.hpp"
#include "rstruct/core/error.hpp"
#include "rstruct/predicates/predicates.hpp"

namespace rstruct::poles {
namespace {

void check_inputs(std::span<const Ball> balls, std::span<const Point3> points) {
  if (points.size() >= std::numeric_limits<std::uint32_t>::max()) {
    throw InvalidInput("covering sets: too many points (" + std::to_string(points.size()) +
                       "), at most 2^32 - 2 are supported");
  }
  for (std::size_t j = 0; j < balls.size(); ++j) {
    if (!is_finite(balls[j].c) || !std::isfinite(balls[j].r) || balls[j].r < 0) {
      std::ostringstream message;
      message << "covering sets: ball " << j << " has a non-finite centre or an invalid radius "
              << balls[j].r;
      throw InvalidInput(message.str());
    }
  }
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!is_finite(points[i])) {
      throw InvalidInput("covering sets: point " + std::to_string(i) + " is not finite");
    }
  }
}

bool covers(const Ball& ball, const Point3& p) {
  return predicates::side_of_ball(p, ball.c, ball.r) != Sign::positive;
}

/// The columns at positions [begin, end) of `order`: their rows appended to `rows`, and for
/// each such column j its size and its start in `rows` recorded in size[j], start[j].
struct Block {
  std::vector<std::uint32_t> rows;
};

void cover_block(const detail::PointTree& tree, std::span<const Ball> balls,
                 std::span<const Point3> points, std::span<const std::uint32_t> order,
                 Block& block, std::vector<std::uint64_t>& size,
                 std::vector<std::uint64_t>& start) {
  std::vector<std::uint32_t> candidates;
  for (const std::uint32_t j : order) {
    candidates.clear();
    tree.candidates_within(balls[j].c, balls[j].r, candidates);
    std::sort(candidates.begin(), candidates.end());
    start[j] = block.rows.size();
    for (const std::uint32_t i : candidates) {
      if (covers(balls[j], points[i])) block.rows.push_back(i);
    }
    size[j] = block.rows.size() - start[j];
  }
}

unsigned thread_count(unsigned requested, std::size_t work) {
  unsigned threads = requested != 0 ? requested : std::max(1U, std::thread::hardware_concurrency());
  // Below a few thousand columns the thread start-up costs more than it saves.
  const std::size_t useful = std::max<std::size_t>(1, work / 4096);
  return static_cast<unsigned>(std::min<std::size_t>(threads, useful));
}

}  // namespace

bool CoveringSets::is_valid() const {
  if (column_offsets.empty() || column_offsets.front() != 0) return false;
  if (column_offsets.back() != rows.size()) return false;
  for (std::size_t j = 0; j + 1 < column_offsets.size(); ++j) {
    if (column_offsets[j] > column_offsets[j + 1]) return false;
    const auto col = column(j);
    for (std::size_t k = 0; k < col.size(); ++k) {
      if (col[k] >= row_count) return false;
      if (k > 0 && col[k - 1] >= col[k]) return false;
    }
  }
  return true;
}

std::size_t CoveringSets::uncovered_row_count() const {
  std::vector<char> covered(row_count, 0);
  for (const std::uint32_t i : rows) covered[i] = 1;
  return static_cast<std::size_t>(std::count(covered.begin(), covered.end(), 0));
}

CoveringSets covering_sets(std::span<const Ball> balls, std::span<const Point3> points,
                           unsigned threads) {
  check_inputs(balls, points);
  CoveringSets sets;
  sets.row_count = static_cast<std::uint32_t>(points.size());
  sets.column_offsets.assign(1, 0);
  if (balls.empty()) return sets;
  if (points.empty()) {
    sets.column_offsets.assign(balls.size() + 1, 0);
    return sets;
  }
  // The points' tree, built on the threads of the queries. It replaced a nanoflann tree
  // (leaves of 12 points, one thread): 10^6 torus samples (bench_seed --torus 1000000
  // --levels 0.5:0.03), 2 and 3 interleaved runs: tree 0.136-0.145 -> 0.031-0.042 s, tree
  // and queries 0.90-1.07 -> 0.65-0.83 s, the covering sets stage 1.06-1.23 -> 0.85-1.02
  // s; leaves of 128 or 256 points instead of 64 were no faster.
  const unsigned t = thread_count(threads, balls.size());
  const detail::PointTree tree(points, detail::PointTree::kDefaultLeafSize,
                               detail::PointTree::Scan::best, t,
                               detail::PointTree::Bounds::boxes);
  // Columns in Morton order of their centres, so that consecutive searches stay local;
  // the result is assembled in column order afterwards.
  std::vector<Point3> centres(balls.size());
  for (std::size_t j = 0; j < balls.size(); ++j) centres[j] = balls[j].c;
  const std::vector<std::uint32_t> order = detail::morton_order(centres);
  centres = {};
  std::vector<Block> blocks(t);
  std::vector<std::uint64_t> size(balls.size()), start(balls.size());
  std::vector<std::uint32_t> block_of(balls.size());
  const std::size_t chunk = (balls.size() + t - 1) / t;
  detail::run_blocks(t, [&](unsigned k) {
    const std::size_t begin = std::min(balls.size(), k * chunk);
    const std::size_t end = std::min(balls.size(), begin + chunk);
    const std::span<const std::uint32_t> mine(order.data() + begin, end - begin);
    for (const std::uint32_t j : mine) block_of[j] = k;
    cover_block(tree, balls, points, mine, blocks[k], size, start);
  });
  sets.column_offsets.resize(balls.size() + 1);
  for (std::size_t j = 0; j < balls.size(); ++j) {
    sets.column_offsets[j + 1] = sets.column_offsets[j] + size[j];
  }
  sets.rows.resize(sets.column_offsets.back());
  for (std::size_t j = 0; j < balls.size(); ++j) {
    const auto& source = blocks[block_of[j]].rows;
    std::copy_n(source.begin() + static_cast<std::ptrdiff_t>(start[j]), size[j],
                sets.rows.begin() + static_cast<std::ptrdiff_t>(sets.column_offsets[j]));
  }
  return sets;
}

CoveringSets covering_sets_brute_force(std::span<const Ball> balls,
                                       std::span<const Point3> points) {
  check_inputs(balls, points);
  CoveringSets sets;
  sets.row_count = static_cast<std::uint32_t>(points.size());
  for (const Ball& ball : balls) {
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (covers(ball, points[i])) sets.rows.push_back(static_cast<std::uint32_t>(i));
    }
    sets.column_offsets.push_back(sets.rows.size());
  }
  return sets;
}

}  // namespace rstruct::poles
