#include "rstruct/medial/xyzr_format.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "rstruct/core/error.hpp"

namespace rstruct::medial {

namespace {

bool is_separator(char c) { return c == ' ' || c == '\t' || c == ',' || c == '\r'; }

[[noreturn]] void fail(std::string_view name, std::size_t line, const std::string& what) {
  throw InvalidInput(std::string(name) + ":" + std::to_string(line) + ": " + what);
}

}  // namespace

std::vector<Ball> parse_xyzr(std::string_view text, std::string_view name) {
  std::vector<Ball> balls;
  std::size_t line_number = 0;
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    ++line_number;
    std::size_t i = 0;
    while (i < line.size() && is_separator(line[i])) ++i;
    if (i == line.size() || line[i] == '#') continue;
    double v[4];
    int count = 0;
    while (i < line.size()) {
      if (count == 4) fail(name, line_number, "expected 4 numbers 'x y z r', found more");
      const char* first = line.data() + i;
      const char* last = line.data() + line.size();
      if (*first == '+') ++first;
      const auto [ptr, ec] = std::from_chars(first, last, v[count]);
      if (ec != std::errc() || (ptr != last && !is_separator(*ptr))) {
        std::size_t stop = i;
        while (stop < line.size() && !is_separator(line[stop])) ++stop;
        fail(name, line_number, "not a number: '" + std::string(line.substr(i, stop - i)) + "'");
      }
      ++count;
      i = static_cast<std::size_t>(ptr - line.data());
      while (i < line.size() && is_separator(line[i])) ++i;
    }
    if (count != 4) {
      fail(name, line_number, "expected 4 numbers 'x y z r', found " + std::to_string(count));
    }
    for (double x : v) {
      if (!std::isfinite(x)) fail(name, line_number, "numbers must be finite");
    }
    if (!(v[3] > 0)) fail(name, line_number, "the radius must be positive");
    balls.push_back({{v[0], v[1], v[2]}, v[3]});
  }
  return balls;
}

std::vector<Ball> read_xyzr(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError("cannot open '" + path.string() + "'");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw IoError("cannot read '" + path.string() + "'");
  return parse_xyzr(buffer.str(), path.string());
}

}  // namespace rstruct::medial
