#include "rstruct/setcover/read_instance.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <istream>
#include <limits>
#include <vector>

#include "rstruct/core/error.hpp"

namespace rstruct::setcover {

namespace {

/// Whitespace-separated tokens with the line they came from, for error messages.
class TokenReader {
 public:
  TokenReader(std::istream& in, std::string name) : in_(in), name_(std::move(name)) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw InvalidInput(name_ + ":" + std::to_string(line_) + ": " + what);
  }

  /// Next token, or fails with "expected <what>" at end of input.
  std::string next(const std::string& what) {
    std::string token;
    int c = 0;
    while ((c = in_.get()) != EOF && std::isspace(c)) {
      if (c == '\n') ++line_;
    }
    if (c == EOF) fail("unexpected end of file, expected " + what);
    token.push_back(static_cast<char>(c));
    while ((c = in_.peek()) != EOF && !std::isspace(c)) {
      token.push_back(static_cast<char>(in_.get()));
      if (token.size() > 64) fail("token too long while reading " + what);
    }
    return token;
  }

  long long integer(const std::string& what, long long lo, long long hi) {
    const std::string t = next(what);
    char* end = nullptr;
    errno = 0;
    const long long v = std::strtoll(t.c_str(), &end, 10);
    if (errno != 0 || end != t.c_str() + t.size()) fail("expected an integer " + what + ", got '" + t + "'");
    if (v < lo || v > hi) {
      fail(what + " " + t + " outside [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    }
    return v;
  }

  double cost(const std::string& what) {
    const std::string t = next(what);
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(t.c_str(), &end);
    if (end != t.c_str() + t.size() || !std::isfinite(v) || v < 0.0) {
      fail("expected a finite cost >= 0 for " + what + ", got '" + t + "'");
    }
    return v;
  }

  void expect_end() {
    int c = 0;
    while ((c = in_.get()) != EOF) {
      if (c == '\n') ++line_;
      if (!std::isspace(c)) fail("unexpected data after the last record");
    }
  }

 private:
  std::istream& in_;
  std::string name_;
  long long line_ = 1;
};

constexpr long long kMaxDim = 100'000'000;

}  // namespace

Instance read_scp_rows(std::istream& in, const std::string& name) {
  TokenReader reader(in, name);
  const auto m = static_cast<std::int32_t>(reader.integer("number of rows", 0, kMaxDim));
  const auto n = static_cast<std::int32_t>(reader.integer("number of columns", 0, kMaxDim));
  std::vector<double> costs;
  costs.reserve(static_cast<std::size_t>(std::min<std::int32_t>(n, 1 << 20)));
  for (std::int32_t j = 0; j < n; ++j) costs.push_back(reader.cost("column " + std::to_string(j + 1)));
  std::vector<std::vector<std::int32_t>> columns(static_cast<std::size_t>(n));
  for (std::int32_t i = 0; i < m; ++i) {
    const std::string where = "row " + std::to_string(i + 1);
    const long long k = reader.integer("column count of " + where, 0, n);
    for (long long t = 0; t < k; ++t) {
      const auto j = reader.integer("column index in " + where, 1, n);
      columns[static_cast<std::size_t>(j - 1)].push_back(i);
    }
  }
  reader.expect_end();
  return Instance::from_columns(m, columns, std::move(costs));
}

Instance read_scp_columns(std::istream& in, const std::string& name) {
  TokenReader reader(in, name);
  const auto m = static_cast<std::int32_t>(reader.integer("number of rows", 0, kMaxDim));
  const auto n = static_cast<std::int32_t>(reader.integer("number of columns", 0, kMaxDim));
  std::vector<double> costs;
  std::vector<std::int64_t> start{0};
  std::vector<std::int32_t> rows;
  for (std::int32_t j = 0; j < n; ++j) {
    const std::string where = "column " + std::to_string(j + 1);
    costs.push_back(reader.cost(where));
    const long long k = reader.integer("row count of " + where, 0, m);
    for (long long t = 0; t < k; ++t) {
      rows.push_back(static_cast<std::int32_t>(reader.integer("row index in " + where, 1, m) - 1));
    }
    start.push_back(static_cast<std::int64_t>(rows.size()));
  }
  reader.expect_end();
  // The header alone fixes the row count here; refuse to allocate rows that cannot all be
  // covered (fewer entries than rows) rather than build a huge instance with no cover.
  if (static_cast<std::int64_t>(rows.size()) < m) {
    reader.fail(std::to_string(m) + " rows but only " + std::to_string(rows.size()) +
                " entries: some row is covered by no column");
  }
  return Instance::from_csr(m, start, rows, std::move(costs));
}

ScpFormat guess_scp_format(const std::filesystem::path& path) {
  return path.filename().string().rfind("rail", 0) == 0 ? ScpFormat::kColumns : ScpFormat::kRows;
}

Instance read_scp_file(const std::filesystem::path& path, ScpFormat format) {
  std::ifstream in(path);
  if (!in) throw IoError("cannot open set-cover file " + path.string());
  return format == ScpFormat::kRows ? read_scp_rows(in, path.string())
                                    : read_scp_columns(in, path.string());
}

}  // namespace rstruct::setcover
