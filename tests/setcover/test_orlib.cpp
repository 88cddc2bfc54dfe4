// OR-Library instances (Beasley): scp41 (optimum 429, unicost best known 38) and scp61
// (optimum 138). Work limits, not time, end the search, so results are deterministic.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "rstruct/setcover/read_instance.hpp"
#include "rstruct/setcover/solver.hpp"
#include "rstruct/setcover/verifier.hpp"

using namespace rstruct::setcover;

namespace {

const std::string kData = RSTRUCT_SCP_DATA;

Verdict verify_on_disk(const std::string& instance, const Certificate& cert) {
  const auto path = std::filesystem::temp_directory_path() / ("rstruct_test_orlib_" + std::to_string(cert.cover.size()) + ".cert");
  {
    std::ofstream out(path);
    write_certificate(out, cert);
  }
  const Verdict v = verify_certificate_files(instance, path, VerifierInputFormat::kRows);
  std::filesystem::remove(path);
  return v;
}

SolverOptions budget(std::int64_t ls_iterations) {
  SolverOptions o;
  o.time_limit = 120.0;
  o.max_local_search_iterations = ls_iterations;
  return o;
}

}  // namespace

TEST_CASE("scp41 weighted: optimal 429, certified") {
  const Instance inst = read_scp_file(kData + "/scp41.txt", ScpFormat::kRows);
  const Solution sol = solve(inst, budget(200'000));
  CHECK(sol.cost == 429);
  CHECK(sol.lower_bound == 429);
  CHECK(sol.optimal);
  const Verdict v = verify_on_disk(kData + "/scp41.txt", sol.certificate);
  CHECK(v.valid);
  CHECK(v.cost == "429");
  CHECK(v.bound == "429");
}

TEST_CASE("scp41 unicost: best known 38, deterministic for a seed") {
  const Instance inst = read_scp_file(kData + "/scp41.txt", ScpFormat::kRows).with_unit_costs();
  const Solution a = solve(inst, budget(300'000));
  CHECK(a.cost <= 38);
  CHECK(a.lower_bound <= a.cost);
  CHECK(a.lower_bound >= 30);  // the Lagrangian (LP) bound of this instance is about 33
  const Solution b = solve(inst, budget(300'000));
  CHECK(a.columns == b.columns);
  CHECK(a.certificate.multipliers == b.certificate.multipliers);
  const Verdict v = verify_on_disk(kData + "/scp41.txt", a.certificate);
  CHECK(v.valid);
  CHECK(v.bound_value == a.lower_bound);
}

TEST_CASE("scp61 weighted: optimum 138, bound within the LP gap") {
  const Instance inst = read_scp_file(kData + "/scp61.txt", ScpFormat::kRows);
  const Solution sol = solve(inst, budget(300'000));
  CHECK(sol.cost == 138);
  CHECK(sol.lower_bound <= 138);
  CHECK(sol.lower_bound >= 131);  // LP optimum 133.14
  CHECK(verify_on_disk(kData + "/scp61.txt", sol.certificate).valid);
}
