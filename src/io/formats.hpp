#pragma once
// The per-format readers and writers behind rstruct/io/mesh_io.hpp. Readers take the whole
// file in memory; writers append to a string. `name` is used in error messages.

#include <string>
#include <string_view>

#include "rstruct/geometry/triangle_mesh.hpp"

namespace rstruct::io::detail {

TriangleMesh read_ply(std::string_view bytes, const std::string& name);
TriangleMesh read_off(std::string_view bytes, const std::string& name);
TriangleMesh read_obj(std::string_view bytes, const std::string& name);
/// `fourth_column`: see ReadOptions::xyz_fourth_column.
TriangleMesh read_xyz(std::string_view bytes, const std::string& name,
                      const std::string& fourth_column);

void write_ply(std::string& out, const TriangleMesh& mesh, bool ascii);
void write_off(std::string& out, const TriangleMesh& mesh);
void write_obj(std::string& out, const TriangleMesh& mesh);
void write_xyz(std::string& out, const TriangleMesh& mesh);

/// Throws InvalidInput "name: ... (empty input)" if the mesh has no vertices.
void require_vertices(const TriangleMesh& mesh, const std::string& name);

/// Checks write_mesh's preconditions (finite values, sizes, names, face indices).
/// \throws InvalidInput naming the first violation.
void validate_for_writing(const TriangleMesh& mesh);

}  // namespace rstruct::io::detail
