#include "rstruct/setcover/instance.hpp"

#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "rstruct/core/error.hpp"

using rstruct::InvalidInput;
using rstruct::setcover::Instance;

TEST_CASE("columns and rows views agree, duplicates merged") {
  const Instance inst = Instance::from_columns(4, {{0, 2, 2}, {1, 3}, {3, 0}}, {2.0, 1.0, 3.0});
  REQUIRE(inst.is_valid());
  CHECK(inst.num_rows() == 4);
  CHECK(inst.num_cols() == 3);
  CHECK(inst.num_entries() == 6);
  CHECK(std::vector<std::int32_t>(inst.column(0).begin(), inst.column(0).end()) == std::vector<std::int32_t>{0, 2});
  CHECK(std::vector<std::int32_t>(inst.row(0).begin(), inst.row(0).end()) == std::vector<std::int32_t>{0, 2});
  CHECK(std::vector<std::int32_t>(inst.row(3).begin(), inst.row(3).end()) == std::vector<std::int32_t>{1, 2});
  CHECK_FALSE(inst.is_unicost());
  CHECK(inst.has_integer_costs());
  CHECK(inst.with_unit_costs().is_unicost());
  CHECK(inst.is_cover(std::vector<std::int32_t>{0, 1}));
  CHECK_FALSE(inst.is_cover(std::vector<std::int32_t>{1, 2}));
  CHECK(inst.cost_of(std::vector<std::int32_t>{0, 2}) == 5.0);
  CHECK(inst.first_uncoverable_row() == -1);
}

TEST_CASE("CSR construction equals column-list construction") {
  const std::vector<std::int64_t> start{0, 2, 2, 5};
  const std::vector<std::int32_t> rows{1, 0, 2, 1, 0};
  const Instance a = Instance::from_csr(3, start, rows);
  const Instance b = Instance::from_columns(3, {{0, 1}, {}, {0, 1, 2}});
  REQUIRE(a.is_valid());
  CHECK(a.is_unicost());
  for (std::int32_t j = 0; j < 3; ++j) {
    CHECK(std::vector<std::int32_t>(a.column(j).begin(), a.column(j).end()) ==
          std::vector<std::int32_t>(b.column(j).begin(), b.column(j).end()));
  }
}

TEST_CASE("uncoverable rows are detected") {
  const Instance inst = Instance::from_columns(3, {{0}, {2}});
  CHECK(inst.first_uncoverable_row() == 1);
}

TEST_CASE("bad instances are rejected with typed errors") {
  CHECK_THROWS_AS(Instance::from_columns(2, {{0, 2}}), InvalidInput);
  CHECK_THROWS_AS(Instance::from_columns(2, {{-1}}), InvalidInput);
  CHECK_THROWS_AS(Instance::from_columns(2, {{0}}, {-1.0}), InvalidInput);
  CHECK_THROWS_AS(Instance::from_columns(2, {{0}}, {std::nan("")}), InvalidInput);
  CHECK_THROWS_AS(Instance::from_columns(2, {{0}}, {std::numeric_limits<double>::infinity()}), InvalidInput);
  CHECK_THROWS_AS(Instance::from_columns(2, {{0}, {1}}, {1.0}), InvalidInput);
  const std::vector<std::int64_t> bad_start{0, 3, 2};
  const std::vector<std::int32_t> rows{0, 1};
  CHECK_THROWS_AS(Instance::from_csr(2, bad_start, rows), InvalidInput);  // ASan found the overread
  const std::vector<std::int64_t> short_start{0, 1};
  CHECK_THROWS_AS(Instance::from_csr(2, short_start, rows), InvalidInput);
  CHECK_THROWS_WITH(Instance::from_columns(2, {{0}, {5}}), Catch::Contains("column 1") && Catch::Contains("row 5"));
}

TEST_CASE("non-integer costs are classified") {
  const Instance inst = Instance::from_columns(1, {{0}, {0}}, {0.5, 2.0});
  CHECK_FALSE(inst.has_integer_costs());
  CHECK_FALSE(inst.is_unicost());
}

TEST_CASE("large instances: several threads check and transpose them as one does") {
  // 2^21 entries, above the size at which from_csr uses its threads: columns of random
  // length (some empty) over random rows, sorted, as the covering sets give them; then the
  // same with repeats and unsorted columns (the one-thread pass merges them), and with a
  // row out of range.
  std::uint64_t state = 99;
  const auto next = [&](std::uint64_t bound) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (state >> 33) % bound;
  };
  constexpr std::int32_t kRows = 300'000;
  std::vector<std::int64_t> start{0};
  std::vector<std::int32_t> rows;
  while (rows.size() < (std::size_t{1} << 21)) {
    std::vector<std::int32_t> column(next(40));
    for (auto& r : column) r = static_cast<std::int32_t>(next(kRows));
    std::sort(column.begin(), column.end());
    column.erase(std::unique(column.begin(), column.end()), column.end());
    rows.insert(rows.end(), column.begin(), column.end());
    start.push_back(static_cast<std::int64_t>(rows.size()));
  }
  const auto same = [](const Instance& a, const Instance& b) {
    if (a.num_rows() != b.num_rows() || a.num_cols() != b.num_cols() ||
        a.num_entries() != b.num_entries()) {
      return false;
    }
    for (std::int32_t j = 0; j < a.num_cols(); ++j) {
      if (!std::equal(a.column(j).begin(), a.column(j).end(), b.column(j).begin(), b.column(j).end())) {
        return false;
      }
    }
    for (std::int32_t i = 0; i < a.num_rows(); ++i) {
      if (!std::equal(a.row(i).begin(), a.row(i).end(), b.row(i).begin(), b.row(i).end())) return false;
    }
    return true;
  };
  const Instance one = Instance::from_csr(kRows, start, rows, {}, 1);
  REQUIRE(one.is_valid());
  REQUIRE(one.num_entries() == static_cast<std::int64_t>(rows.size()));
  for (const unsigned threads : {2u, 3u, 0u}) {
    INFO(threads << " threads");
    const Instance many = Instance::from_csr(kRows, start, rows, {}, threads);
    CHECK(many.is_valid());
    CHECK(same(one, many));
  }
  // Repeats and disorder in some columns.
  std::vector<std::int32_t> messy = rows;
  for (std::size_t j = 0; j + 1 < start.size(); j += 97) {
    const auto b = static_cast<std::size_t>(start[j]), e = static_cast<std::size_t>(start[j + 1]);
    if (e - b >= 2) {
      std::swap(messy[b], messy[e - 1]);
      messy[b + 1] = messy[b];
    }
  }
  const Instance messy_one = Instance::from_csr(kRows, start, messy, {}, 1);
  const Instance messy_two = Instance::from_csr(kRows, start, messy, {}, 2);
  CHECK(messy_one.is_valid());
  CHECK(messy_one.num_entries() < one.num_entries());
  CHECK(same(messy_one, messy_two));
  // A row out of range far into the entries: the same error.
  std::vector<std::int32_t> bad = rows;
  bad[bad.size() - 5] = kRows;
  CHECK_THROWS_WITH(Instance::from_csr(kRows, start, bad, {}, 2), Catch::Contains("outside [0, 300000)"));
  bad[bad.size() - 5] = -1;
  CHECK_THROWS_WITH(Instance::from_csr(kRows, start, bad, {}, 2), Catch::Contains("names row -1"));
}
