#include "rstruct/poles/covering_sets.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <thread>

#include "parallel_blocks.hpp"
#include "point_kd_tree.hpp"
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

/// Columns [begin, end): offsets relative to this block, rows appended to `rows`.
struct Block {
  std::vector<std::uint64_t> sizes;
  std::vector<std::uint32_t> rows;
};

void cover_block(const detail::PointKdTree& tree, std::span<const Ball> balls,
                 std::span<const Point3> points, std::size_t begin, std::size_t end,
                 Block& block) {
  std::vector<std::uint32_t> candidates;
  block.sizes.reserve(end - begin);
  for (std::size_t j = begin; j < end; ++j) {
    candidates.clear();
    tree.candidates_within(balls[j].c, balls[j].r, candidates);
    std::sort(candidates.begin(), candidates.end());
    const std::size_t before = block.rows.size();
    for (const std::uint32_t i : candidates) {
      if (covers(balls[j], points[i])) block.rows.push_back(i);
    }
    block.sizes.push_back(block.rows.size() - before);
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
  const detail::PointKdTree tree(points);
  const unsigned t = thread_count(threads, balls.size());
  std::vector<Block> blocks(t);
  const std::size_t chunk = (balls.size() + t - 1) / t;
  auto run = [&](unsigned k) {
    const std::size_t begin = std::min(balls.size(), k * chunk);
    const std::size_t end = std::min(balls.size(), begin + chunk);
    cover_block(tree, balls, points, begin, end, blocks[k]);
  };
  detail::run_blocks(t, run);
  std::size_t total = 0;
  for (const Block& block : blocks) total += block.rows.size();
  sets.rows.reserve(total);
  sets.column_offsets.reserve(balls.size() + 1);
  for (Block& block : blocks) {
    for (const std::uint64_t size : block.sizes) {
      sets.column_offsets.push_back(sets.column_offsets.back() + size);
    }
    sets.rows.insert(sets.rows.end(), block.rows.begin(), block.rows.end());
    block = Block{};
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
