#pragma once
/// \file
/// Readers for the OR-Library set-covering formats (J. E. Beasley's OR-Library, issue 6).
///
/// Row format (scp files):   m n / c_1 … c_n / for each row i: k_i j_1 … j_{k_i}
/// Column format (rail files): m n / for each column j: c_j k_j i_1 … i_{k_j}
/// Indices in both files are 1-based; the Instance is 0-based.

#include <filesystem>
#include <iosfwd>
#include <string>

#include "rstruct/setcover/instance.hpp"

namespace rstruct::setcover {

enum class ScpFormat {
  kRows,     ///< OR-Library scp* files
  kColumns,  ///< OR-Library rail* files
};

/// Parses the row format. `name` is used in error messages.
/// \throws InvalidInput naming the file, line and element on malformed or truncated input,
/// an index out of range, a negative or non-finite cost, trailing data.
Instance read_scp_rows(std::istream& in, const std::string& name = "<stream>");

/// Parses the column format. \throws InvalidInput as read_scp_rows.
Instance read_scp_columns(std::istream& in, const std::string& name = "<stream>");

/// Format from the file name: names starting with "rail" are column format, others rows.
ScpFormat guess_scp_format(const std::filesystem::path& path);

/// Opens and parses a file. \throws IoError if it cannot be read; InvalidInput as above.
Instance read_scp_file(const std::filesystem::path& path, ScpFormat format);

}  // namespace rstruct::setcover
