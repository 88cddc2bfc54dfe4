#include "rstruct/setcover/instance.hpp"

#include <catch2/catch.hpp>
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
