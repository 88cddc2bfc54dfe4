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

TEST_CASE("stages record the CPU seconds of the process") {
  rstruct::Report report;
  {
    rstruct::Report::Stage busy(report, "busy");
    volatile double x = 0;
    const rstruct::Stopwatch clock;
    while (clock.cpu_seconds() < 0.02) x = x + 1;
  }
  report.add_stage("unmeasured", 0.1);
  REQUIRE(report.stage_cpu_seconds().size() == 2);
  CHECK(report.stage_cpu_seconds()[0] >= 0.02);
  CHECK(report.stage_cpu_seconds()[1] < 0);
  const auto j = report.to_json();
  CHECK(j["stages"][0]["cpu_seconds"].get<double>() >= 0.02);
  CHECK_FALSE(j["stages"][1].contains("cpu_seconds"));
  CHECK(j["total_cpu_seconds"].get<double>() >= 0.02);
}
