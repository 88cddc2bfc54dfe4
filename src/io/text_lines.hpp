#pragma once
// Line-oriented scanning of text formats (ASCII PLY body, OFF, OBJ, XYZ): lines numbered
// from 1, blank-separated tokens, strict number parsing, and errors that name file and line.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>

namespace rstruct::io::detail {

/// True if every byte of `name` may appear in a PLY element or property name: no blanks,
/// no control characters (the reader and the writer apply the same rule).
bool is_ply_name(std::string_view name);

/// Printable, length-limited rendering of untrusted bytes for error messages.
std::string quoted(std::string_view bytes);

/// Iterates over the lines of a text buffer. Lines end at '\n'; a trailing '\r' is dropped.
class LineReader {
 public:
  /// `first_line` is the number of the buffer's first line (ASCII PLY bodies start after
  /// the header).
  LineReader(std::string_view text, std::string name, std::size_t first_line = 1);

  /// The next line (without terminator), or false at the end of the buffer.
  bool next(std::string_view& line);
  /// The next line that is not blank once `comment` and what follows it are removed
  /// (comment 0: none), or false at the end of the buffer.
  bool next_content(std::string_view& line, char comment);

  /// Number of the line last returned by next() (0 before the first call).
  std::size_t line_number() const { return line_number_; }
  /// An upper bound on the lines left (newlines left + 1), to check header counts against
  /// before allocating.
  std::size_t lines_left() const;
  /// Bytes not yet returned.
  std::size_t bytes_left() const { return pos_ < text_.size() ? text_.size() - pos_ : 0; }
  const std::string& name() const { return name_; }

  /// Throws InvalidInput "name:line: what".
  [[noreturn]] void fail(const std::string& what) const;

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  std::string name_;
  std::size_t line_number_;
};

/// Splits a line into tokens separated by blanks (space, tab, '\r', '\v', '\f') and, if
/// `comma_separates`, commas.
class Tokens {
 public:
  explicit Tokens(std::string_view line, bool comma_separates = false)
      : line_(line), comma_(comma_separates) {}
  /// The next token, or false when none is left.
  bool next(std::string_view& token);
  /// Counts the tokens left without consuming them.
  std::size_t count_left() const;

 private:
  bool is_separator(char c) const;
  std::string_view line_;
  std::size_t pos_ = 0;
  bool comma_;
};

/// Removes `comment` and everything after it (comment 0: nothing is removed).
std::string_view strip_comment(std::string_view line, char comment);

/// How parsing a number token went.
enum class NumberStatus { ok, not_a_number, out_of_range, not_finite };

/// Parses the whole token as a finite double ("+" sign allowed, no hexfloat).
NumberStatus parse_double(std::string_view token, double& value);
/// Parses the whole token as a decimal integer in [lo, hi].
NumberStatus parse_int(std::string_view token, std::int64_t lo, std::int64_t hi,
                       std::int64_t& value);

/// Throws InvalidInput via `where`: "what: <problem with token>".
[[noreturn]] void fail_double(NumberStatus status, std::string_view token,
                              const LineReader& where, const std::string& what);
[[noreturn]] void fail_int(NumberStatus status, std::string_view token, std::int64_t lo,
                           std::int64_t hi, const LineReader& where, const std::string& what);

/// `what` of an error message: a string, or a callable building it (so that the hot path
/// builds no strings).
template <class What>
std::string describe_what(const What& what) {
  if constexpr (std::is_invocable_v<const What&>) {
    return what();
  } else {
    return std::string(what);
  }
}

/// parse_double, throwing InvalidInput naming `what` (not a number, out of the range of
/// double, NaN/Inf).
template <class What>
double parse_finite_double(std::string_view token, const LineReader& where, const What& what) {
  double value = 0;
  const NumberStatus status = parse_double(token, value);
  if (status != NumberStatus::ok) fail_double(status, token, where, describe_what(what));
  return value;
}

/// parse_int, throwing InvalidInput naming `what`.
template <class What>
std::int64_t parse_integer(std::string_view token, std::int64_t lo, std::int64_t hi,
                           const LineReader& where, const What& what) {
  std::int64_t value = 0;
  const NumberStatus status = parse_int(token, lo, hi, value);
  if (status != NumberStatus::ok) fail_int(status, token, lo, hi, where, describe_what(what));
  return value;
}

/// Appends the shortest decimal form of `value` that reads back to the same double.
void append_double(std::string& out, double value);

}  // namespace rstruct::io::detail
