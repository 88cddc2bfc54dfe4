// Format dispatch, file access and the writers' precondition check.

#include "rstruct/io/mesh_io.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>

#include "io/formats.hpp"
#include "io/text_lines.hpp"
#include "rstruct/core/atomic_file.hpp"
#include "rstruct/core/error.hpp"

namespace rstruct::io {

namespace {

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

// The whole file; IoError on any failure.
std::string read_file(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw IoError("cannot read '" + path.string() + "': it is a directory");
  }
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"),
                                                             &std::fclose);
  if (!file) throw IoError("cannot open '" + path.string() + "': " + std::strerror(errno));
  std::string bytes;
  char buffer[1 << 16];
  std::size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, file.get())) > 0) bytes.append(buffer, n);
  if (std::ferror(file.get())) {
    throw IoError("error while reading '" + path.string() + "': " + std::strerror(errno));
  }
  return bytes;
}

Format resolve(Format format, const std::filesystem::path& path) {
  return format == Format::automatic ? format_from_extension(path) : format;
}

void validate_properties(const TriangleMesh& mesh) {
  const auto& props = mesh.vertex_properties;
  for (std::size_t k = 0; k < props.size(); ++k) {
    const std::string& name = props[k].first;
    if (!detail::is_ply_name(name) || name == "x" || name == "y" || name == "z") {
      throw InvalidInput("cannot write vertex property named '" + name +
                         "': names must be non-empty, without blanks or control characters, "
                         "and not x, y, z");
    }
    for (std::size_t j = 0; j < k; ++j) {
      if (props[j].first == name) throw InvalidInput("duplicate vertex property '" + name + "'");
    }
    if (props[k].second.size() != mesh.vertices.size()) {
      throw InvalidInput("vertex property '" + name + "' has " +
                         std::to_string(props[k].second.size()) + " values for " +
                         std::to_string(mesh.vertices.size()) + " vertices");
    }
    for (std::size_t i = 0; i < props[k].second.size(); ++i) {
      if (!std::isfinite(props[k].second[i])) {
        throw InvalidInput("vertex property '" + name + "' of vertex " + std::to_string(i) +
                           " is NaN or infinite");
      }
    }
  }
}

}  // namespace

namespace detail {

void require_vertices(const TriangleMesh& mesh, const std::string& name) {
  if (mesh.vertices.empty()) throw InvalidInput(name + ": contains no vertices (empty input)");
}

void validate_for_writing(const TriangleMesh& mesh) {
  if (mesh.vertices.size() > std::numeric_limits<std::uint32_t>::max()) {
    throw InvalidInput("cannot write more than 2^32 - 1 vertices");
  }
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    if (!is_finite(mesh.vertices[i])) {
      throw InvalidInput("vertex " + std::to_string(i) + " has a NaN or infinite coordinate");
    }
  }
  validate_properties(mesh);
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    for (std::uint32_t v : mesh.faces[f]) {
      if (v >= mesh.vertices.size()) {
        throw InvalidInput("face " + std::to_string(f) + " refers to vertex " + std::to_string(v) +
                           " of " + std::to_string(mesh.vertices.size()));
      }
    }
  }
}

}  // namespace detail

Format format_from_extension(const std::filesystem::path& path) {
  const std::string ext = lower(path.extension().string());
  if (ext == ".ply") return Format::ply;
  if (ext == ".off") return Format::off;
  if (ext == ".obj") return Format::obj;
  if (ext == ".xyz") return Format::xyz;
  throw InvalidInput("cannot tell the format of '" + path.string() + "' from its extension " +
                     (ext.empty() ? std::string("(none)") : "'" + ext + "'") +
                     ": use .ply, .off, .obj or .xyz, or give --format");
}

Format parse_format(const std::string& name) {
  const std::string n = lower(name);
  if (n == "ply") return Format::ply;
  if (n == "off") return Format::off;
  if (n == "obj") return Format::obj;
  if (n == "xyz") return Format::xyz;
  throw InvalidInput("unknown format '" + name + "' (expected ply, off, obj or xyz)");
}

std::string format_name(Format format) {
  switch (format) {
    case Format::ply: return "ply";
    case Format::off: return "off";
    case Format::obj: return "obj";
    case Format::xyz: return "xyz";
    case Format::automatic: break;
  }
  return "automatic";
}

TriangleMesh read_mesh(const std::filesystem::path& path, const ReadOptions& options) {
  const Format format = resolve(options.format, path);
  const std::string bytes = read_file(path);
  return read_mesh_from_memory(bytes, format, options, path.string());
}

TriangleMesh read_mesh_from_memory(std::string_view bytes, Format format,
                                   const ReadOptions& options,
                                   const std::string& name_for_messages) {
  switch (format) {
    case Format::ply: return detail::read_ply(bytes, name_for_messages);
    case Format::off: return detail::read_off(bytes, name_for_messages);
    case Format::obj: return detail::read_obj(bytes, name_for_messages);
    case Format::xyz: return detail::read_xyz(bytes, name_for_messages, options.xyz_fourth_column);
    case Format::automatic: break;
  }
  throw InvalidInput(name_for_messages + ": the format must be given to read from memory");
}

std::string write_mesh_to_string(const TriangleMesh& mesh, const WriteOptions& options) {
  detail::validate_for_writing(mesh);
  std::string out;
  switch (options.format) {
    case Format::ply: detail::write_ply(out, mesh, options.ascii); return out;
    case Format::off: detail::write_off(out, mesh); return out;
    case Format::obj: detail::write_obj(out, mesh); return out;
    case Format::xyz: detail::write_xyz(out, mesh); return out;
    case Format::automatic: break;
  }
  throw InvalidInput("the format must be given to write to memory");
}

void write_mesh(const std::filesystem::path& path, const TriangleMesh& mesh,
                const WriteOptions& options) {
  WriteOptions resolved = options;
  resolved.format = resolve(options.format, path);
  const std::string bytes = write_mesh_to_string(mesh, resolved);
  AtomicFile file(path, /*binary=*/true);
  file.stream().write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  file.commit();
}

}  // namespace rstruct::io
