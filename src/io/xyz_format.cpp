// XYZ point lists: one point per line, "x y z [more columns]", separated by blanks or
// commas, '#' comments. The writer puts the property names in a leading comment.

#include <limits>
#include <string>

#include "io/formats.hpp"
#include "io/text_lines.hpp"
#include "rstruct/core/error.hpp"

namespace rstruct::io::detail {

TriangleMesh read_xyz(std::string_view bytes, const std::string& name,
                      const std::string& fourth_column) {
  LineReader lines(bytes, name);
  TriangleMesh mesh;
  std::vector<double> fourth;
  const std::size_t columns = fourth_column.empty() ? 3 : 4;
  std::string_view line;
  while (lines.next_content(line, '#')) {
    Tokens tokens(line, /*comma_separates=*/true);
    if (tokens.count_left() < columns) {
      lines.fail(columns == 3 ? "expected x y z"
                              : "expected x y z " + fourth_column + " (4 columns)");
    }
    if (mesh.vertices.size() >= std::numeric_limits<std::uint32_t>::max()) {
      lines.fail("more than 2^32 - 1 points are not supported");
    }
    const std::size_t index = mesh.vertices.size();
    const auto what = [index] { return "point " + std::to_string(index); };
    std::string_view token;
    Point3 p;
    for (std::size_t axis = 0; axis < 3; ++axis) {
      tokens.next(token);
      p[axis] = parse_finite_double(token, lines, what);
    }
    mesh.vertices.push_back(p);
    if (columns == 4) {
      tokens.next(token);
      fourth.push_back(parse_finite_double(token, lines, [&] { return what() + " " + fourth_column; }));
    }
  }
  require_vertices(mesh, name);
  if (columns == 4) mesh.vertex_properties.emplace_back(fourth_column, std::move(fourth));
  return mesh;
}

void write_xyz(std::string& out, const TriangleMesh& mesh) {
  out += "# x y z";
  for (const auto& [property_name, values] : mesh.vertex_properties) out += " " + property_name;
  out += '\n';
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Point3& p = mesh.vertices[i];
    append_double(out, p.x);
    out += ' ';
    append_double(out, p.y);
    out += ' ';
    append_double(out, p.z);
    for (const auto& [property_name, values] : mesh.vertex_properties) {
      out += ' ';
      append_double(out, values[i]);
    }
    out += '\n';
  }
}

}  // namespace rstruct::io::detail
