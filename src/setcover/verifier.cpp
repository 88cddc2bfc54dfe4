// Independent certificate checker: deliberately shares no code with the solver, the
// reduction or the instance readers (STYLE.md: a checker never shares the approximations of
// the code it checks). Everything is exact: costs as rationals read from their decimal text,
// multipliers as integers, sums in GMP.
#include "rstruct/setcover/verifier.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <gmpxx.h>
#include <istream>
#include <sstream>

#include "rstruct/core/error.hpp"

namespace rstruct::setcover {

namespace {

struct ExactInstance {
  std::int64_t num_rows = 0;
  std::vector<std::vector<std::int64_t>> columns;  // 0-based rows
  std::vector<mpq_class> costs;
};

/// "12", "12.5", "1e3", "1.5E-2" as an exact rational; false on anything else.
bool parse_decimal(const std::string& text, mpq_class& out) {
  std::size_t p = 0;
  std::string digits;
  long long frac = 0;
  while (p < text.size() && std::isdigit(static_cast<unsigned char>(text[p]))) digits += text[p++];
  if (p < text.size() && text[p] == '.') {
    ++p;
    while (p < text.size() && std::isdigit(static_cast<unsigned char>(text[p]))) {
      digits += text[p++];
      ++frac;
    }
  }
  if (digits.empty() || digits.size() > 400) return false;
  long long exponent = 0;
  if (p < text.size() && (text[p] == 'e' || text[p] == 'E')) {
    ++p;
    bool neg = false;
    if (p < text.size() && (text[p] == '+' || text[p] == '-')) neg = text[p++] == '-';
    std::string e;
    while (p < text.size() && std::isdigit(static_cast<unsigned char>(text[p]))) e += text[p++];
    if (e.empty() || e.size() > 3) return false;
    exponent = neg ? -std::stoll(e) : std::stoll(e);
  }
  if (p != text.size()) return false;
  mpz_class num(digits, 10);
  const long long shift = exponent - frac;
  mpz_class ten_pow;
  mpz_ui_pow_ui(ten_pow.get_mpz_t(), 10, static_cast<unsigned long>(shift < 0 ? -shift : shift));
  out = shift >= 0 ? mpq_class(num * ten_pow) : mpq_class(num, ten_pow);
  out.canonicalize();
  return true;
}

/// "p" or "p/q" (optionally negative) as a rational; false otherwise.
bool parse_rational(const std::string& text, mpq_class& out) {
  if (text.empty() || text.size() > 2000) return false;
  const std::size_t slash = text.find('/');
  auto is_int = [](const std::string& s, bool allow_sign) {
    std::size_t k = (allow_sign && !s.empty() && s[0] == '-') ? 1 : 0;
    if (k >= s.size()) return false;
    return std::all_of(s.begin() + static_cast<std::ptrdiff_t>(k), s.end(),
                       [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; });
  };
  const std::string a = text.substr(0, slash);
  const std::string b = slash == std::string::npos ? "1" : text.substr(slash + 1);
  if (!is_int(a, true) || !is_int(b, false)) return false;
  mpz_class den(b, 10);
  if (den == 0) return false;
  out = mpq_class(mpz_class(a, 10), den);
  out.canonicalize();
  return true;
}

class Tokens {
 public:
  explicit Tokens(std::istream& in) : in_(in) {}
  bool next(std::string& t) { return static_cast<bool>(in_ >> t); }
  bool integer(long long lo, long long hi, long long& v) {
    std::string t;
    if (!next(t) || t.empty() || t.size() > 19) return false;
    if (!std::all_of(t.begin(), t.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; })) return false;
    v = std::stoll(t);
    return v >= lo && v <= hi;
  }

 private:
  std::istream& in_;
};

ExactInstance parse_instance(std::istream& in, VerifierInputFormat format, const std::string& name) {
  Tokens tok(in);
  auto bad = [&](const std::string& what) { throw InvalidInput("verifier: " + name + ": " + what); };
  long long m = 0, n = 0;
  if (!tok.integer(0, 100'000'000, m) || !tok.integer(0, 100'000'000, n)) bad("bad header");
  ExactInstance inst;
  inst.num_rows = m;
  std::string t;
  if (format == VerifierInputFormat::kRows) {
    for (long long j = 0; j < n; ++j) {
      mpq_class c;
      if (!tok.next(t) || !parse_decimal(t, c)) bad("bad cost of column " + std::to_string(j + 1));
      inst.costs.push_back(c);
    }
    inst.columns.resize(static_cast<std::size_t>(n));
    for (long long i = 0; i < m; ++i) {
      long long k = 0;
      if (!tok.integer(0, n, k)) bad("bad count of row " + std::to_string(i + 1));
      for (long long q = 0; q < k; ++q) {
        long long j = 0;
        if (!tok.integer(1, n, j)) bad("bad column in row " + std::to_string(i + 1));
        inst.columns[static_cast<std::size_t>(j - 1)].push_back(i);
      }
    }
  } else {
    for (long long j = 0; j < n; ++j) {
      mpq_class c;
      long long k = 0;
      if (!tok.next(t) || !parse_decimal(t, c)) bad("bad cost of column " + std::to_string(j + 1));
      if (!tok.integer(0, m, k)) bad("bad count of column " + std::to_string(j + 1));
      inst.costs.push_back(c);
      inst.columns.emplace_back();
      for (long long q = 0; q < k; ++q) {
        long long i = 0;
        if (!tok.integer(1, m, i)) bad("bad row in column " + std::to_string(j + 1));
        inst.columns.back().push_back(i - 1);
      }
    }
  }
  if (tok.next(t)) bad("trailing data");
  return inst;
}

struct ParsedCertificate {
  long long rows = 0, cols = 0;
  bool unicost = false;
  mpz_class scale;
  std::vector<long long> cover;  // 1-based as written
  std::vector<mpz_class> u;
  mpq_class cost_claim, bound_claim;
};

/// Parses the certificate; returns an error message, empty on success.
std::string parse_certificate(std::istream& in, ParsedCertificate& c) {
  Tokens tok(in);
  std::string t, v;
  auto word = [&](const char* expected) { return tok.next(t) && t == expected; };
  if (!word("rstruct-setcover-certificate") || !word("1")) return "not a version 1 certificate";
  long long uni = 0;
  if (!word("rows") || !tok.integer(0, 100'000'000, c.rows) || !word("columns") ||
      !tok.integer(0, 100'000'000, c.cols) || !word("unicost") || !tok.integer(0, 1, uni)) {
    return "bad size line";
  }
  c.unicost = uni == 1;
  if (!word("scale") || !tok.next(v) || !parse_rational(v, c.bound_claim)) return "bad scale";
  if (c.bound_claim.get_den() != 1 || c.bound_claim <= 0) return "scale must be a positive integer";
  c.scale = c.bound_claim.get_num();
  long long k = 0;
  if (!word("cover") || !tok.integer(0, c.cols, k)) return "bad cover size";
  for (long long q = 0; q < k; ++q) {
    long long j = 0;
    if (!tok.integer(1, c.cols, j)) return "bad column index in cover (entry " + std::to_string(q + 1) + ")";
    c.cover.push_back(j);
  }
  long long mu = 0;
  if (!word("multipliers") || !tok.integer(0, 100'000'000, mu) || mu != c.rows) return "bad multiplier count";
  for (long long i = 0; i < mu; ++i) {
    mpq_class x;
    if (!tok.next(v) || !parse_rational(v, x) || x.get_den() != 1) return "multiplier " + std::to_string(i + 1) + " is not an integer";
    if (x < 0) return "multiplier " + std::to_string(i + 1) + " is negative";
    c.u.push_back(x.get_num());
  }
  if (!word("claim") || !word("cost") || !tok.next(v) || !parse_rational(v, c.cost_claim)) return "bad cost claim";
  if (!word("bound") || !tok.next(v) || !parse_rational(v, c.bound_claim)) return "bad bound claim";
  if (!word("end") || tok.next(t)) return "missing 'end' or trailing data";
  return {};
}

mpz_class ceil_of(const mpq_class& q) {
  mpz_class r;
  mpz_cdiv_q(r.get_mpz_t(), q.get_num_mpz_t(), q.get_den_mpz_t());
  return r;
}

/// L(u) = Σ U_i / S + Σ_j min(0, c_j − Σ_{i∈S_j} U_i / S), computed as (L·S) / S.
mpq_class lagrangian_bound(const ExactInstance& inst, const std::vector<mpq_class>& costs,
                           const ParsedCertificate& c) {
  mpq_class scaled(0);
  for (const mpz_class& x : c.u) scaled += x;
  mpz_class col_sum;
  for (std::size_t j = 0; j < costs.size(); ++j) {
    col_sum = 0;
    for (long long i : inst.columns[j]) col_sum += c.u[static_cast<std::size_t>(i)];
    mpq_class r = costs[j] * c.scale - col_sum;
    if (r < 0) scaled += r;
  }
  mpq_class bound = scaled / c.scale;
  bound.canonicalize();
  return bound;
}

Verdict check(ExactInstance inst, std::istream& certificate) {
  // A column is a set: a row listed twice counts once.
  for (auto& col : inst.columns) {
    std::sort(col.begin(), col.end());
    col.erase(std::unique(col.begin(), col.end()), col.end());
  }
  Verdict v;
  ParsedCertificate c;
  if (std::string err = parse_certificate(certificate, c); !err.empty()) {
    v.problems.push_back("certificate: " + err);
    return v;
  }
  const auto n = static_cast<long long>(inst.columns.size());
  if (c.rows != inst.num_rows || c.cols != n) {
    v.problems.push_back("certificate is for " + std::to_string(c.rows) + " x " + std::to_string(c.cols) +
                         ", instance is " + std::to_string(inst.num_rows) + " x " + std::to_string(n));
    return v;
  }
  std::vector<mpq_class> costs = inst.costs;
  if (c.unicost) costs.assign(static_cast<std::size_t>(n), mpq_class(1));
  v.integer_costs = std::all_of(costs.begin(), costs.end(), [](const mpq_class& q) { return q.get_den() == 1; });
  // Coverage and cost.
  std::vector<char> used(static_cast<std::size_t>(n), 0);
  std::vector<char> covered(static_cast<std::size_t>(inst.num_rows), 0);
  mpq_class cost(0);
  for (long long j1 : c.cover) {
    const auto j = static_cast<std::size_t>(j1 - 1);
    if (used[j]) v.problems.push_back("column " + std::to_string(j1) + " appears twice in the cover");
    used[j] = 1;
    cost += costs[j];
    for (long long i : inst.columns[j]) covered[static_cast<std::size_t>(i)] = 1;
  }
  for (long long i = 0; i < inst.num_rows; ++i) {
    if (!covered[static_cast<std::size_t>(i)]) {
      if (v.uncovered_rows++ == 0) v.problems.push_back("row " + std::to_string(i + 1) + " is not covered");
    }
  }
  mpq_class bound = lagrangian_bound(inst, costs, c);
  if (v.integer_costs) bound = mpq_class(ceil_of(bound));
  // Non-integer costs: the claim may come from binary doubles of the decimal costs; it must
  // agree within the stated margin 2^-40 · cost (integer costs: exactly).
  mpq_class margin(0);
  if (!v.integer_costs) margin = cost / mpq_class(mpz_class(1) << 40);
  if (abs(c.cost_claim - cost) > margin) v.problems.push_back("claimed cost " + c.cost_claim.get_str() + " differs from the cover's cost " + cost.get_str());
  if (c.bound_claim > bound) v.problems.push_back("claimed bound " + c.bound_claim.get_str() + " exceeds the recomputed bound " + bound.get_str());
  v.cost = cost.get_str();
  v.bound = bound.get_str();
  v.cost_value = cost.get_d();
  v.bound_value = bound.get_d();
  v.gap = cost > 0 ? mpq_class((cost - bound) / cost).get_d() : 0.0;
  v.valid = v.problems.empty();
  return v;
}

}  // namespace

std::string Verdict::summary() const {
  std::ostringstream out;
  if (!valid) {
    out << "INVALID: " << (problems.empty() ? std::string("unknown") : problems.front());
    return out.str();
  }
  out << "VALID cost " << cost << " bound " << bound << " gap " << 100.0 * gap << "%";
  return out.str();
}

Verdict verify_certificate_files(const std::filesystem::path& instance,
                                 const std::filesystem::path& certificate,
                                 VerifierInputFormat format) {
  std::ifstream in(instance);
  if (!in) throw IoError("verifier: cannot open instance " + instance.string());
  ExactInstance inst = parse_instance(in, format, instance.string());
  std::ifstream cert(certificate);
  if (!cert) throw IoError("verifier: cannot open certificate " + certificate.string());
  return check(std::move(inst), cert);
}

Verdict verify_certificate(std::int64_t num_rows, const std::vector<std::vector<std::int32_t>>& columns,
                           const std::vector<double>& costs, std::istream& certificate) {
  ExactInstance inst;
  inst.num_rows = num_rows;
  for (std::size_t j = 0; j < columns.size(); ++j) {
    inst.columns.emplace_back();
    for (std::int32_t i : columns[j]) {
      if (i < 0 || i >= num_rows) throw InvalidInput("verifier: column " + std::to_string(j) + " has a row out of range");
      inst.columns.back().push_back(i);
    }
    if (costs.empty()) {
      inst.costs.emplace_back(1);
    } else {
      if (j >= costs.size() || !std::isfinite(costs[j]) || costs[j] < 0) throw InvalidInput("verifier: bad cost of column " + std::to_string(j));
      inst.costs.emplace_back(costs[j]);
    }
  }
  if (!costs.empty() && costs.size() != columns.size()) throw InvalidInput("verifier: cost count differs from column count");
  return check(std::move(inst), certificate);
}

}  // namespace rstruct::setcover
