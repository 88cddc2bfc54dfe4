#pragma once
/// \file
/// Output of a medial axis (DESIGN.md §6):
///  - the `.ma` format of Q-MAT / Coverage Axis: a header line "nv ne nf", then nv lines
///    "v x y z r", ne lines "e i j" and nf lines "f i j k" (0-based; polygons are
///    fan-triangulated, every edge of the triangulation is listed once);
///  - PLY (ASCII): vertices with a `radius` property, the triangles as faces and every edge
///    as an `edge` element.
/// Both are written atomically (core/atomic_file.hpp), coordinates with 17 significant digits.

#include <filesystem>
#include <ostream>

#include "rstruct/medial/medial_axis.hpp"

namespace rstruct::medial {

/// Writes `axis` in the .ma format to `out`.
void write_ma(std::ostream& out, const MedialAxis& axis);
/// Writes `axis` in the .ma format to `path`. \throws IoError.
void write_ma(const std::filesystem::path& path, const MedialAxis& axis);
/// Writes `axis` as ASCII PLY to `path`. \throws IoError.
void write_medial_ply(const std::filesystem::path& path, const MedialAxis& axis);
/// Writes `axis` to `path`: PLY if the name ends in .ply (any case), .ma otherwise.
void write_medial_axis(const std::filesystem::path& path, const MedialAxis& axis);

}  // namespace rstruct::medial
