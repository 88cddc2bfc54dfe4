// Wavefront OBJ: reader of `v` and `f` statements (every other statement of the format is
// tolerated and ignored) and writer of `v` and `f` lines.

#include <algorithm>
#include <array>
#include <limits>
#include <string>

#include "io/formats.hpp"
#include "io/text_lines.hpp"
#include "rstruct/core/error.hpp"

namespace rstruct::io::detail {

namespace {

// Statements of the OBJ specification (and common extensions) that carry nothing we read.
constexpr std::array<std::string_view, 38> kIgnored{
    "vt",    "vn",      "vp",       "l",        "p",      "o",       "g",      "s",
    "mg",    "mtllib",  "usemtl",   "maplib",   "usemap", "lod",     "shadow_obj",
    "trace_obj", "ctech", "stech", "bevel",    "c_interp", "d_interp", "cstype", "deg",
    "bmat",  "step",    "curv",     "curv2",    "surf",   "parm",    "trim",   "hole",
    "scrv",  "sp",      "end",      "con",      "call",   "csh",     "res"};

constexpr std::int64_t kMaxIndex = std::numeric_limits<std::uint32_t>::max();

struct ObjState {
  TriangleMesh mesh;
  // The largest 0-based positive index seen and where (positive indices may point forward;
  // they are checked once all vertices are known).
  std::int64_t max_index = -1;
  std::size_t max_index_line = 0;
};

void read_vertex(Tokens& tokens, ObjState& state, const LineReader& lines) {
  if (tokens.count_left() < 3) lines.fail("'v' needs x y z");
  if (state.mesh.vertices.size() >= static_cast<std::size_t>(kMaxIndex)) {
    lines.fail("more than 2^32 - 1 vertices are not supported");
  }
  Point3 p;
  std::string_view token;
  const auto what = [&] { return "vertex " + std::to_string(state.mesh.vertices.size() + 1); };
  for (std::size_t axis = 0; axis < 3; ++axis) {
    tokens.next(token);
    p[axis] = parse_finite_double(token, lines, what);
  }
  state.mesh.vertices.push_back(p);
}

std::uint32_t face_index(std::string_view token, ObjState& state, const LineReader& lines) {
  const std::string_view index_part = token.substr(0, token.find('/'));
  const std::int64_t index =
      parse_integer(index_part, -kMaxIndex, kMaxIndex, lines,
                    [&] { return "face vertex " + quoted(token); });
  const auto count = static_cast<std::int64_t>(state.mesh.vertices.size());
  if (index == 0) lines.fail("face vertex index 0 (OBJ indices start at 1)");
  if (index < 0) {
    if (-index > count) {
      lines.fail("relative face index " + std::to_string(index) + " but only " +
                 std::to_string(count) + " vertices precede it");
    }
    return static_cast<std::uint32_t>(count + index);
  }
  if (index - 1 > state.max_index) {
    state.max_index = index - 1;
    state.max_index_line = lines.line_number();
  }
  return static_cast<std::uint32_t>(index - 1);
}

void read_face(Tokens& tokens, ObjState& state, const LineReader& lines) {
  const std::size_t n = tokens.count_left();
  if (n < 3) lines.fail("face has " + std::to_string(n) + " vertices (at least 3 needed)");
  std::string_view token;
  std::uint32_t first = 0, previous = 0;
  for (std::size_t k = 0; k < n; ++k) {
    tokens.next(token);
    const std::uint32_t v = face_index(token, state, lines);
    if (k == 0) first = v;
    if (k >= 2) state.mesh.faces.push_back({first, previous, v});
    previous = v;
  }
}

}  // namespace

TriangleMesh read_obj(std::string_view bytes, const std::string& name) {
  LineReader lines(bytes, name);
  ObjState state;
  std::string_view line;
  while (lines.next_content(line, '#')) {
    Tokens tokens(line);
    std::string_view keyword;
    tokens.next(keyword);
    if (keyword == "v") {
      read_vertex(tokens, state, lines);
    } else if (keyword == "f" || keyword == "fo") {
      read_face(tokens, state, lines);
    } else if (std::find(kIgnored.begin(), kIgnored.end(), keyword) == kIgnored.end()) {
      lines.fail("unknown OBJ statement " + quoted(keyword));
    }
  }
  require_vertices(state.mesh, name);
  if (state.max_index >= static_cast<std::int64_t>(state.mesh.vertices.size())) {
    throw InvalidInput(name + ":" + std::to_string(state.max_index_line) + ": face vertex index " +
                       std::to_string(state.max_index + 1) + " but the file has only " +
                       std::to_string(state.mesh.vertices.size()) + " vertices");
  }
  return std::move(state.mesh);
}

void write_obj(std::string& out, const TriangleMesh& mesh) {
  out += "# written by rstruct\n";
  for (const Point3& p : mesh.vertices) {
    out += "v ";
    append_double(out, p.x);
    out += ' ';
    append_double(out, p.y);
    out += ' ';
    append_double(out, p.z);
    out += '\n';
  }
  for (const auto& f : mesh.faces) {
    out += "f " + std::to_string(f[0] + std::uint64_t{1}) + " " +
           std::to_string(f[1] + std::uint64_t{1}) + " " + std::to_string(f[2] + std::uint64_t{1}) +
           "\n";
  }
}

}  // namespace rstruct::io::detail
