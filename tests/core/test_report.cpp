#include "rstruct/core/report.hpp"

#include <catch2/catch.hpp>
#include <sstream>

TEST_CASE("stages are recorded in order with non-negative seconds") {
  rstruct::Report report;
  {
    rstruct::Report::Stage a(report, "first");
  }
  rstruct::Report::Stage b(report, "second");
  const double s = b.finish();
  b.finish();  // idempotent: recorded once
  REQUIRE(report.stages().size() == 2);
  CHECK(report.stages()[0].first == "first");
  CHECK(report.stages()[1].first == "second");
  CHECK(report.stages()[1].second == s);
  CHECK(s >= 0.0);
}

TEST_CASE("report JSON carries data, stages, warnings and memory") {
  rstruct::Report report;
  report.data()["points"] = 42;
  report.add_stage("x", 0.5);
  report.warn("careful");
  const auto j = report.to_json();
  CHECK(j["points"] == 42);
  CHECK(j["stages"][0]["stage"] == "x");
  CHECK(j["stages"][0]["seconds"] == 0.5);
  CHECK(j["warnings"][0] == "careful");
  CHECK(j["peak_memory_bytes"].get<std::size_t>() > 0);
  std::ostringstream out;
  report.print_stages(out);
  CHECK(out.str().find("total") != std::string::npos);
}
