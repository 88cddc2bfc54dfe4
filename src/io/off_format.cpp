// OFF (Object File Format, Geomview): reader and writer. ASCII only; the optional
// keyword may carry the ST/C/N prefixes (their extra columns are ignored), comments start
// with '#', and the edge count of the counts line is optional and ignored.

#include <limits>
#include <string>

#include "io/formats.hpp"
#include "io/text_lines.hpp"
#include "rstruct/core/error.hpp"

namespace rstruct::io::detail {

namespace {

constexpr std::int64_t kMaxVertices = std::numeric_limits<std::uint32_t>::max();
constexpr std::int64_t kMaxCount = std::numeric_limits<std::int64_t>::max();

// True if `token` is an OFF keyword (fails on unsupported variants).
bool is_off_keyword(std::string_view token, const LineReader& lines) {
  if (token.size() < 3 || token.substr(token.size() - 3) != "OFF") return false;
  for (char c : token.substr(0, token.size() - 3)) {
    if (c == '4' || c == 'n') lines.fail("unsupported OFF variant " + quoted(token) + " (only 3D)");
    if (c != 'S' && c != 'T' && c != 'C' && c != 'N') return false;
  }
  return true;
}

struct OffCounts {
  std::int64_t vertices = 0;
  std::int64_t faces = 0;
};

OffCounts read_counts(LineReader& lines) {
  std::string_view line;
  if (!lines.next_content(line, '#')) {
    throw InvalidInput(lines.name() + ": no content (empty input)");
  }
  Tokens tokens(line);
  std::string_view token;
  tokens.next(token);
  const bool is_number = (token[0] >= '0' && token[0] <= '9') || token[0] == '+' || token[0] == '-';
  if (is_off_keyword(token, lines)) {
    if (tokens.count_left() == 0) {  // counts on the next content line
      if (!lines.next_content(line, '#')) lines.fail("missing the counts line 'nv nf ne'");
      tokens = Tokens(line);
    } else {
      std::string_view word;
      Tokens peek = tokens;
      peek.next(word);
      if (word == "BINARY") lines.fail("binary OFF is not supported");
    }
    if (!tokens.next(token)) lines.fail("missing the counts line 'nv nf ne'");
  } else if (!is_number) {
    lines.fail("not an OFF file: found " + quoted(token));
  }
  const std::size_t rest = tokens.count_left();
  if (rest < 1 || rest > 2) lines.fail("counts line must be 'nv nf' or 'nv nf ne'");
  OffCounts counts;
  counts.vertices = parse_integer(token, 0, kMaxVertices, lines, "vertex count");
  tokens.next(token);
  counts.faces = parse_integer(token, 0, kMaxCount, lines, "face count");
  if (tokens.next(token)) parse_integer(token, 0, kMaxCount, lines, "edge count");
  return counts;
}

void check_counts_fit(const OffCounts& counts, const LineReader& lines) {
  // Every vertex and face takes a line; a vertex at least "0 0 0\n", a face "3 0 0 0\n".
  const auto left = static_cast<std::uint64_t>(lines.bytes_left()) + 1;
  const auto nv = static_cast<std::uint64_t>(counts.vertices);
  const auto nf = static_cast<std::uint64_t>(counts.faces);
  const bool fits = nv <= lines.lines_left() && nf <= lines.lines_left() - nv &&
                    nf <= left / 8 && nv * 6 <= left - nf * 8;
  if (!fits) {
    lines.fail("header declares " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
               " faces, more than the remaining " + std::to_string(lines.lines_left()) +
               " lines can hold (truncated file or bad count)");
  }
}

void read_off_face(std::string_view line, std::uint64_t index, TriangleMesh& mesh,
                   const LineReader& lines) {
  Tokens tokens(line);
  std::string_view token;
  tokens.next(token);
  const auto what = [index] { return "face " + std::to_string(index); };
  const std::int64_t n = parse_integer(token, 0, kMaxCount, lines, [&] { return what() + " size"; });
  if (n < 3) lines.fail(what() + " has " + std::to_string(n) + " vertices (at least 3 needed)");
  if (static_cast<std::uint64_t>(n) > tokens.count_left()) {
    lines.fail(what() + " declares " + std::to_string(n) + " vertices but lists fewer");
  }
  const auto nv = static_cast<std::int64_t>(mesh.vertices.size());
  std::uint32_t first = 0, previous = 0;
  for (std::int64_t k = 0; k < n; ++k) {
    tokens.next(token);
    const auto v = static_cast<std::uint32_t>(
        parse_integer(token, 0, nv - 1, lines, [&] { return what() + " vertex index"; }));
    if (k == 0) first = v;
    if (k >= 2) mesh.faces.push_back({first, previous, v});
    previous = v;
  }
}

}  // namespace

TriangleMesh read_off(std::string_view bytes, const std::string& name) {
  LineReader lines(bytes, name);
  const OffCounts counts = read_counts(lines);
  if (counts.vertices == 0) lines.fail("vertex count is 0 (empty input)");
  check_counts_fit(counts, lines);
  TriangleMesh mesh;
  mesh.vertices.reserve(static_cast<std::size_t>(counts.vertices));
  std::string_view line;
  for (std::int64_t i = 0; i < counts.vertices; ++i) {
    if (!lines.next_content(line, '#')) {
      lines.fail("unexpected end of file after " + std::to_string(i) + " of " +
                 std::to_string(counts.vertices) + " vertices (truncated)");
    }
    Tokens tokens(line);
    if (tokens.count_left() < 3) lines.fail("vertex " + std::to_string(i) + " needs x y z");
    Point3 p;
    std::string_view token;
    for (std::size_t axis = 0; axis < 3; ++axis) {
      tokens.next(token);
      p[axis] = parse_finite_double(token, lines, [i] { return "vertex " + std::to_string(i); });
    }
    mesh.vertices.push_back(p);
  }
  for (std::int64_t f = 0; f < counts.faces; ++f) {
    if (!lines.next_content(line, '#')) {
      lines.fail("unexpected end of file after " + std::to_string(f) + " of " +
                 std::to_string(counts.faces) + " faces (truncated)");
    }
    read_off_face(line, static_cast<std::uint64_t>(f), mesh, lines);
  }
  return mesh;
}

void write_off(std::string& out, const TriangleMesh& mesh) {
  out += "OFF\n# written by rstruct\n";
  out += std::to_string(mesh.vertices.size()) + " " + std::to_string(mesh.faces.size()) + " 0\n";
  for (const Point3& p : mesh.vertices) {
    append_double(out, p.x);
    out += ' ';
    append_double(out, p.y);
    out += ' ';
    append_double(out, p.z);
    out += '\n';
  }
  for (const auto& f : mesh.faces) {
    out += "3 " + std::to_string(f[0]) + " " + std::to_string(f[1]) + " " +
           std::to_string(f[2]) + "\n";
  }
}

}  // namespace rstruct::io::detail
