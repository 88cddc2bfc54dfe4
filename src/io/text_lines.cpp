#include "io/text_lines.hpp"

#include <charconv>
#include <cmath>
#include <cstring>
#include <system_error>

#include "rstruct/core/error.hpp"

namespace rstruct::io::detail {

bool is_ply_name(std::string_view name) {
  if (name.empty()) return false;
  for (char ch : name) {
    const auto c = static_cast<unsigned char>(ch);
    if (c <= 0x20 || c == 0x7f) return false;
  }
  return true;
}

std::string quoted(std::string_view bytes) {
  constexpr std::size_t kMaxShown = 40;
  std::string out = "'";
  const std::size_t n = bytes.size() < kMaxShown ? bytes.size() : kMaxShown;
  for (std::size_t i = 0; i < n; ++i) {
    const auto c = static_cast<unsigned char>(bytes[i]);
    if (c >= 0x20 && c < 0x7f && c != '\'' && c != '\\') {
      out += static_cast<char>(c);
    } else {
      static const char* const kHex = "0123456789abcdef";
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 15];
    }
  }
  if (bytes.size() > kMaxShown) out += "...";
  out += "'";
  return out;
}

LineReader::LineReader(std::string_view text, std::string name, std::size_t first_line)
    : text_(text), name_(std::move(name)), line_number_(first_line - 1) {}

bool LineReader::next(std::string_view& line) {
  if (pos_ >= text_.size()) return false;
  const std::size_t end = text_.find('\n', pos_);
  const std::size_t stop = end == std::string_view::npos ? text_.size() : end;
  line = text_.substr(pos_, stop - pos_);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  pos_ = end == std::string_view::npos ? text_.size() : end + 1;
  ++line_number_;
  return true;
}

bool LineReader::next_content(std::string_view& line, char comment) {
  while (next(line)) {
    line = strip_comment(line, comment);
    std::string_view token;
    if (Tokens(line).next(token)) return true;
  }
  return false;
}

std::size_t LineReader::lines_left() const {
  if (pos_ >= text_.size()) return 0;
  const char* begin = text_.data() + pos_;
  const char* const end = text_.data() + text_.size();
  std::size_t lines = 1;
  while (const void* hit = std::memchr(begin, '\n', static_cast<std::size_t>(end - begin))) {
    ++lines;
    begin = static_cast<const char*>(hit) + 1;
  }
  return lines;
}

void LineReader::fail(const std::string& what) const {
  throw InvalidInput(name_ + ":" + std::to_string(line_number_) + ": " + what);
}

bool Tokens::is_separator(char c) const {
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f' || (comma_ && c == ',');
}

bool Tokens::next(std::string_view& token) {
  while (pos_ < line_.size() && is_separator(line_[pos_])) ++pos_;
  if (pos_ >= line_.size()) return false;
  const std::size_t start = pos_;
  while (pos_ < line_.size() && !is_separator(line_[pos_])) ++pos_;
  token = line_.substr(start, pos_ - start);
  return true;
}

std::size_t Tokens::count_left() const {
  Tokens copy = *this;
  std::size_t n = 0;
  std::string_view token;
  while (copy.next(token)) ++n;
  return n;
}

std::string_view strip_comment(std::string_view line, char comment) {
  if (comment == 0) return line;
  const std::size_t hash = line.find(comment);
  return hash == std::string_view::npos ? line : line.substr(0, hash);
}

namespace {

// std::from_chars rejects a leading '+', which text files do contain.
std::string_view without_plus(std::string_view token) {
  if (token.size() > 1 && token[0] == '+' && token[1] != '-' && token[1] != '+') {
    token.remove_prefix(1);
  }
  return token;
}

}  // namespace

NumberStatus parse_double(std::string_view token, double& value) {
  const std::string_view digits = without_plus(token);
  const char* const end = digits.data() + digits.size();
  const auto [ptr, ec] = std::from_chars(digits.data(), end, value);
  if (ec == std::errc::result_out_of_range) return NumberStatus::out_of_range;
  if (ec != std::errc() || ptr != end) return NumberStatus::not_a_number;
  return std::isfinite(value) ? NumberStatus::ok : NumberStatus::not_finite;
}

NumberStatus parse_int(std::string_view token, std::int64_t lo, std::int64_t hi,
                       std::int64_t& value) {
  const std::string_view digits = without_plus(token);
  const char* const end = digits.data() + digits.size();
  const auto [ptr, ec] = std::from_chars(digits.data(), end, value);
  if (ec == std::errc::result_out_of_range) return NumberStatus::out_of_range;
  if (ec != std::errc() || ptr != end) return NumberStatus::not_a_number;
  return value < lo || value > hi ? NumberStatus::out_of_range : NumberStatus::ok;
}

void fail_double(NumberStatus status, std::string_view token, const LineReader& where,
                 const std::string& what) {
  switch (status) {
    case NumberStatus::out_of_range:
      where.fail(what + ": number " + quoted(token) + " is out of the range of double");
    case NumberStatus::not_finite:
      where.fail(what + ": non-finite value " + quoted(token) + " (NaN/Inf are not allowed)");
    default: where.fail(what + ": expected a number, found " + quoted(token));
  }
}

void fail_int(NumberStatus status, std::string_view token, std::int64_t lo, std::int64_t hi,
              const LineReader& where, const std::string& what) {
  if (status == NumberStatus::out_of_range) {
    where.fail(what + ": integer " + quoted(token) + " is outside [" + std::to_string(lo) + ", " +
               std::to_string(hi) + "]");
  }
  where.fail(what + ": expected an integer, found " + quoted(token));
}

void append_double(std::string& out, double value) {
  char buffer[64];
  const auto [ptr, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
  // 64 bytes always hold the shortest form of a double (at most 24 characters).
  out.append(buffer, ec == std::errc() ? ptr : buffer);
}

}  // namespace rstruct::io::detail
