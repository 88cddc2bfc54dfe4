#include "rstruct/setcover/read_instance.hpp"

#include <catch2/catch.hpp>
#include <sstream>

#include "rstruct/core/error.hpp"

using namespace rstruct::setcover;
using rstruct::InvalidInput;
using rstruct::IoError;

namespace {
Instance rows_from(const std::string& text) {
  std::istringstream in(text);
  return read_scp_rows(in, "test");
}
Instance columns_from(const std::string& text) {
  std::istringstream in(text);
  return read_scp_columns(in, "test");
}
}  // namespace

TEST_CASE("row format: costs, then columns per row, 1-based") {
  const Instance inst = rows_from(" 3 4\n 1 2 3 4\n 2 1 2\n 1 3\n 2 3 4\n");
  REQUIRE(inst.is_valid());
  CHECK(inst.num_rows() == 3);
  CHECK(inst.num_cols() == 4);
  CHECK(inst.cost(3) == 4.0);
  CHECK(std::vector<std::int32_t>(inst.row(2).begin(), inst.row(2).end()) == std::vector<std::int32_t>{2, 3});
  CHECK(std::vector<std::int32_t>(inst.column(2).begin(), inst.column(2).end()) == std::vector<std::int32_t>{1, 2});
}

TEST_CASE("column format: cost, count, rows per column") {
  const Instance inst = columns_from("3 2\n1.5 2 1 3\n2 1 2\n");
  REQUIRE(inst.is_valid());
  CHECK(inst.cost(0) == 1.5);
  CHECK_FALSE(inst.has_integer_costs());
  CHECK(std::vector<std::int32_t>(inst.column(0).begin(), inst.column(0).end()) == std::vector<std::int32_t>{0, 2});
}

TEST_CASE("malformed files give InvalidInput naming the line") {
  CHECK_THROWS_AS(rows_from(""), InvalidInput);
  CHECK_THROWS_AS(rows_from("2 2\n1 1\n1 1\n"), InvalidInput);          // truncated
  CHECK_THROWS_WITH(rows_from("2 2\n1 1\n1 1\n1 3\n"), Catch::Contains("test:4"));  // column 3 > 2
  CHECK_THROWS_AS(rows_from("1 2\n1 -1\n1 1\n"), InvalidInput);        // negative cost
  CHECK_THROWS_AS(rows_from("1 1\n1\n1 1\n7\n"), InvalidInput);        // trailing data
  CHECK_THROWS_AS(rows_from("1 1\nx\n1 1\n"), InvalidInput);
  CHECK_THROWS_AS(rows_from("1 1\nnan\n1 1\n"), InvalidInput);
  CHECK_THROWS_AS(columns_from("2 1\n1 3 1 2 2\n"), InvalidInput);    // count > rows
  CHECK_THROWS_AS(columns_from("2 1\n1 1 0\n"), InvalidInput);        // row 0 (1-based)
  CHECK_THROWS_AS(columns_from("100000000 1\n1 1 1\n"), InvalidInput);  // rows without entries
}

TEST_CASE("OR-Library scp41 reads with its published size") {
  const Instance inst = read_scp_file(RSTRUCT_SCP_DATA "/scp41.txt", ScpFormat::kRows);
  CHECK(inst.num_rows() == 200);
  CHECK(inst.num_cols() == 1000);
  CHECK(inst.has_integer_costs());
  CHECK(inst.is_valid());
  CHECK(guess_scp_format("rail507.txt") == ScpFormat::kColumns);
  CHECK(guess_scp_format("dir/scp41.txt") == ScpFormat::kRows);
  CHECK_THROWS_AS(read_scp_file("/nonexistent/scp.txt", ScpFormat::kRows), IoError);
}
