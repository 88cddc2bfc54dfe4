#pragma once
/// \file
/// Reading and writing point sets and triangle meshes: PLY (ASCII, binary little and big
/// endian), OFF, OBJ and XYZ. This is the input stage of the pipeline (DESIGN.md §0): a
/// point set S in R³ given as the vertices of one of these files; faces, when present, are
/// read too (fan-triangulated) and named per-vertex scalar properties are kept.
///
/// Readers are strict: malformed content throws rstruct::InvalidInput with a message that
/// names the file and the line (text) or byte offset and element index (binary): NaN/Inf,
/// truncation, element counts larger than the file can hold (checked against the file size
/// before anything is allocated), wrong property types, bad face indices, empty input.
/// Failures to open or read a file throw rstruct::IoError.
///
/// Writers print doubles in the shortest form that reads back to the same bits
/// (std::to_chars), or as raw IEEE binary64 in binary PLY, so every round trip is exact.
/// Files are written through rstruct::AtomicFile: they appear whole or not at all.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "rstruct/geometry/triangle_mesh.hpp"

namespace rstruct::io {

/// A file format. `automatic` means: from the file name's extension.
enum class Format { automatic, ply, off, obj, xyz };

/// The format named by a path's extension (.ply, .off, .obj, .xyz; case-insensitive).
/// \throws InvalidInput for any other extension (the message suggests --format).
Format format_from_extension(const std::filesystem::path& path);

/// Parses "ply", "off", "obj", "xyz" (case-insensitive). \throws InvalidInput otherwise.
Format parse_format(const std::string& name);

/// Lower-case name of a format ("ply", ..., "automatic").
std::string format_name(Format format);

struct ReadOptions {
  Format format = Format::automatic;
  /// XYZ only: if non-empty, the 4th column is required on every line and stored as this
  /// vertex property (e.g. "weight" or "radius"); otherwise extra columns are ignored.
  std::string xyz_fourth_column;
};

/// Reads a point set or mesh from a file. The format is `options.format`, or the one named
/// by the extension when that is `automatic`.
///
/// - PLY: element `vertex` with float or double x, y, z; its other scalar properties
///   become vertex_properties (as doubles, in header order); element `face` with a list
///   property `vertex_indices` or `vertex_index` of integers, polygons fan-triangulated;
///   every other element and property is skipped. ASCII bodies hold one element instance
///   per line (blank lines are skipped).
/// - OFF: optional `OFF`/`COFF`/`NOFF`/`STOFF`... keyword, `#` comments, counts line
///   (`nv nf [ne]`), vertices (extra columns such as colours ignored), faces (`n i1 .. in`,
///   trailing colour ignored).
/// - OBJ: `v` (extra w / colour columns ignored) and `f` (`i`, `i/t`, `i//n`, `i/t/n`,
///   negative = relative); `vt`, `vn`, `vp`, `l`, `p`, `o`, `g`, `s`, `mtllib`, `usemtl`
///   and the other statements of the OBJ specification are tolerated and ignored.
/// - XYZ: one point per line, `x y z` separated by blanks or commas; see ReadOptions.
///
/// \throws InvalidInput on malformed content (message: file, line or byte offset, what).
/// \throws IoError when the file cannot be opened or read.
TriangleMesh read_mesh(const std::filesystem::path& path, const ReadOptions& options = {});

/// Same as read_mesh on bytes already in memory. `format` must not be `automatic`.
/// `name_for_messages` replaces the file name in error messages.
TriangleMesh read_mesh_from_memory(std::string_view bytes, Format format,
                                   const ReadOptions& options = {},
                                   const std::string& name_for_messages = "<memory>");

struct WriteOptions {
  Format format = Format::automatic;
  /// PLY only: ASCII instead of binary little endian.
  bool ascii = false;
};

/// Writes `mesh` atomically. PLY keeps faces and every vertex property (as double, or as
/// int for integer-valued "label"/"vertex_id"/"id"/"index"); OFF and OBJ keep faces but no
/// properties; XYZ writes `x y z` followed by one column per property, no faces.
/// \pre mesh is well formed: finite coordinates and properties, property vectors of
///      vertices.size() entries, distinct property names that are PLY tokens and not
///      x/y/z, face indices < vertices.size(). \throws InvalidInput otherwise.
/// \throws IoError if the file cannot be written.
void write_mesh(const std::filesystem::path& path, const TriangleMesh& mesh,
                const WriteOptions& options = {});

/// Same as write_mesh into a string (`options.format` must not be `automatic`).
std::string write_mesh_to_string(const TriangleMesh& mesh, const WriteOptions& options);

/// Removes exact duplicate vertices, keeping the first of each group (and its property
/// values); faces are re-indexed (a face may become degenerate; it is kept). Two vertices
/// are duplicates when their coordinates compare equal as doubles, i.e. bitwise equal
/// except that 0.0 and -0.0 are the same point. Returns how many vertices were removed;
/// if `old_to_new` is given it receives the new index of every old vertex.
std::size_t remove_duplicate_vertices(TriangleMesh& mesh,
                                      std::vector<std::uint32_t>* old_to_new = nullptr);

/// How many vertices remove_duplicate_vertices would remove (the mesh is not changed).
std::size_t count_duplicate_vertices(const TriangleMesh& mesh);

}  // namespace rstruct::io
