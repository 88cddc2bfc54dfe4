#include "rstruct/medial/medial_axis_io.hpp"

#include <algorithm>
#include <cctype>
#include <string>

#include "rstruct/core/atomic_file.hpp"

namespace rstruct::medial {

void write_ma(std::ostream& out, const MedialAxis& axis) {
  const auto edges = axis.all_edges();
  const auto tris = axis.triangles();
  // Fan diagonals are edges of the triangulated output too.
  std::vector<std::array<std::uint32_t, 2>> all = edges;
  for (const auto& t : tris) {
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t a = t[i], b = t[(i + 1) % 3];
      all.push_back({std::min(a, b), std::max(a, b)});
    }
  }
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  out.precision(17);
  out << axis.vertices.size() << ' ' << all.size() << ' ' << tris.size() << '\n';
  for (std::size_t v = 0; v < axis.vertices.size(); ++v) {
    const Point3& p = axis.vertices[v];
    out << "v " << p.x << ' ' << p.y << ' ' << p.z << ' ' << axis.radius[v] << '\n';
  }
  for (const auto& e : all) out << "e " << e[0] << ' ' << e[1] << '\n';
  for (const auto& t : tris) out << "f " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
}

void write_ma(const std::filesystem::path& path, const MedialAxis& axis) {
  AtomicFile file(path);
  write_ma(file.stream(), axis);
  file.commit();
}

void write_medial_ply(const std::filesystem::path& path, const MedialAxis& axis) {
  const auto edges = axis.all_edges();
  const auto tris = axis.triangles();
  AtomicFile file(path);
  std::ostream& out = file.stream();
  out.precision(17);
  out << "ply\nformat ascii 1.0\ncomment rstruct medial axis\n"
      << "element vertex " << axis.vertices.size() << '\n'
      << "property double x\nproperty double y\nproperty double z\nproperty double radius\n"
      << "element face " << tris.size() << '\n'
      << "property list uchar int vertex_indices\n"
      << "element edge " << edges.size() << '\n'
      << "property int vertex1\nproperty int vertex2\nend_header\n";
  for (std::size_t v = 0; v < axis.vertices.size(); ++v) {
    const Point3& p = axis.vertices[v];
    out << p.x << ' ' << p.y << ' ' << p.z << ' ' << axis.radius[v] << '\n';
  }
  for (const auto& t : tris) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  for (const auto& e : edges) out << e[0] << ' ' << e[1] << '\n';
  file.commit();
}

void write_medial_axis(const std::filesystem::path& path, const MedialAxis& axis) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".ply") {
    write_medial_ply(path, axis);
  } else {
    write_ma(path, axis);
  }
}

}  // namespace rstruct::medial
