#include "rstruct/setcover/verifier.hpp"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <rapidcheck/catch.h>
#include <sstream>

#include "rstruct/core/error.hpp"
#include "rstruct/setcover/solver.hpp"
#include "small_instances.hpp"

using namespace rstruct::setcover;
using rstruct::setcover::testing::gen_small_instance;
using rstruct::setcover::testing::SmallInstance;

namespace {

SolverOptions options() {
  SolverOptions o;
  o.time_limit = 30.0;
  o.max_local_search_iterations = 20'000;
  return o;
}

Verdict check(const SmallInstance& s, const std::string& text) {
  std::istringstream in(text);
  return verify_certificate(s.rows, s.columns, s.costs, in);
}

}  // namespace

TEST_CASE("tampered certificates are rejected") {
  rc::prop("removing a cover column or raising a multiplier breaks the certificate", [] {
    const SmallInstance s = *gen_small_instance();
    const Instance inst = s.build();
    const Solution sol = solve(inst, options());
    RC_ASSERT(check(s, certificate_text(sol.certificate)).valid);
    if (!sol.certificate.cover.empty()) {
      Certificate t = sol.certificate;
      const auto k = *rc::gen::inRange<std::size_t>(0, t.cover.size());
      t.cover.erase(t.cover.begin() + static_cast<std::ptrdiff_t>(k));
      RC_ASSERT_FALSE(check(s, certificate_text(t)).valid);
    }
    // A row covered by at least two columns: raising its multiplier far lowers L(u) below
    // the claimed bound.
    std::vector<std::int32_t> shared;
    for (std::int32_t i = 0; i < inst.num_rows(); ++i) {
      if (inst.row(i).size() >= 2) shared.push_back(i);
    }
    if (!shared.empty()) {
      Certificate t = sol.certificate;
      const std::int32_t i = *rc::gen::elementOf(shared);
      t.multipliers[i] += 1000 * t.scale;
      RC_ASSERT_FALSE(check(s, certificate_text(t)).valid);
    }
  });
}

TEST_CASE("claims are checked, structure is checked") {
  SmallInstance s;
  s.rows = 2;
  s.columns = {{0}, {1}, {0, 1}};
  s.costs = {1, 1, 3};
  const Solution sol = solve(s.build(), options());
  REQUIRE(sol.cost == 2);
  REQUIRE(sol.lower_bound == 2);
  const Certificate good = sol.certificate;
  CHECK(check(s, certificate_text(good)).valid);
  CHECK(check(s, certificate_text(good)).summary().rfind("VALID cost 2 bound 2", 0) == 0);

  Certificate t = good;
  t.bound_claim = "3";
  CHECK_FALSE(check(s, certificate_text(t)).valid);
  t = good;
  t.bound_claim = "1";  // a weaker claim is still true
  CHECK(check(s, certificate_text(t)).valid);
  t = good;
  t.cost_claim = "1";
  CHECK_FALSE(check(s, certificate_text(t)).valid);
  t = good;
  t.cover.push_back(t.cover.front());  // duplicate column
  CHECK_FALSE(check(s, certificate_text(t)).valid);
  t = good;
  t.multipliers[0] = -1;
  CHECK_FALSE(check(s, certificate_text(t)).valid);
  t = good;
  t.num_rows = 3;
  CHECK_FALSE(check(s, certificate_text(t)).valid);
  CHECK_FALSE(check(s, "garbage").valid);
  CHECK_FALSE(check(s, certificate_text(good) + " extra").valid);
  std::string text = certificate_text(good);
  CHECK_FALSE(check(s, text.substr(0, text.size() / 2)).valid);
}

TEST_CASE("ceiling only with integer costs") {
  SmallInstance s;
  s.rows = 3;
  s.columns = {{0, 1}, {1, 2}, {0, 2}};
  s.costs = {1, 1, 1};  // LP optimum 1.5, integer optimum 2
  Certificate c;
  c.num_rows = 3;
  c.num_cols = 3;
  c.cover = {0, 1};
  c.multipliers = {c.scale / 2, c.scale / 2, c.scale / 2};  // u = 1/2: L = 3/2
  c.cost_claim = "2";
  c.bound_claim = "2";
  Verdict v = check(s, certificate_text(c));
  CHECK(v.valid);
  CHECK(v.bound == "2");
  s.costs = {1.5, 1.5, 1.5};  // LP 2.25, no rounding allowed
  c.multipliers = {3 * c.scale / 4, 3 * c.scale / 4, 3 * c.scale / 4};
  c.cost_claim = "3";
  c.bound_claim = "9/4";
  v = check(s, certificate_text(c));
  CHECK(v.valid);
  CHECK(v.bound == "9/4");
  c.bound_claim = "3";
  CHECK_FALSE(check(s, certificate_text(c)).valid);
}

TEST_CASE("file verification reads the instance itself, decimal costs exactly") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path();
  const fs::path inst_path = dir / "rstruct_test_verifier.scp";
  const fs::path cert_path = dir / "rstruct_test_verifier.cert";
  {
    std::ofstream out(inst_path);
    out << "2 3\n0.1 0.2 0.25\n2 1 3\n2 2 3\n";
  }
  Certificate c;
  c.num_rows = 2;
  c.num_cols = 3;
  c.cover = {2};
  c.multipliers = {c.scale / 16, 3 * c.scale / 16};  // all reduced costs >= 0, L = 1/4
  c.cost_claim = "1/4";
  c.bound_claim = "1/4";
  {
    std::ofstream out(cert_path);
    write_certificate(out, c);
  }
  const Verdict v = verify_certificate_files(inst_path, cert_path, VerifierInputFormat::kRows);
  CHECK(v.valid);
  CHECK(v.cost == "1/4");
  CHECK(v.bound == "1/4");
  CHECK(v.gap == 0.0);
  CHECK_THROWS_AS(verify_certificate_files(dir / "nonexistent.scp", cert_path, VerifierInputFormat::kRows),
                  rstruct::IoError);
  fs::remove(inst_path);
  fs::remove(cert_path);
}
