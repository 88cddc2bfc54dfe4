#pragma once
/// \file
/// Reader of a union of balls as text: one ball "x y z r" per line. Blank lines and lines
/// starting with '#' are skipped; numbers are separated by spaces, tabs or commas.

#include <filesystem>
#include <string_view>
#include <vector>

#include "rstruct/geometry/vec3.hpp"

namespace rstruct::medial {

/// Parses the text of an .xyzr file; `name` is used in messages.
/// \throws InvalidInput naming the line (1-based) if a line does not hold exactly four
///   numbers, a number is not finite, or a radius is not positive.
std::vector<Ball> parse_xyzr(std::string_view text, std::string_view name = "<text>");

/// Reads an .xyzr file. \throws IoError if it cannot be read; InvalidInput as parse_xyzr.
std::vector<Ball> read_xyzr(const std::filesystem::path& path);

}  // namespace rstruct::medial
