// `rstruct convert IN -o OUT`: reads a point set or mesh in one format and writes it in
// another, reporting vertex, face and exact-duplicate counts (duplicates removed with
// --dedup). Formats come from the extensions unless --format / --output-format are given.

#include <string>

#include "cli/command.hpp"
#include "rstruct/core/error.hpp"
#include "rstruct/io/mesh_io.hpp"

namespace rstruct::cli {

namespace {

class ConvertCommand : public Command {
 public:
  void configure(CLI::App& app) override {
    app.add_option("input", input_, "Input file (.ply, .off, .obj, .xyz)")->required();
    app.add_option("-o,--output", output_, "Output file (.ply, .off, .obj, .xyz)")->required();
    app.add_option("--format", input_format_,
                   "Input format (ply, off, obj, xyz) instead of the input's extension");
    app.add_option("--output-format", output_format_,
                   "Output format (ply, off, obj, xyz) instead of the output's extension");
    app.add_flag("--ascii", ascii_, "Write ASCII PLY instead of binary little endian");
    app.add_flag("--dedup", dedup_, "Remove exact duplicate vertices (the first one is kept)");
    app.add_option("--xyz-column", xyz_column_,
                   "XYZ input: read the 4th column (required on every line) as this vertex "
                   "property, e.g. weight or radius");
  }

  int run(Context& context) override {
    io::ReadOptions read_options;
    if (!input_format_.empty()) read_options.format = io::parse_format(input_format_);
    read_options.xyz_fourth_column = xyz_column_;
    io::WriteOptions write_options;
    write_options.format = output_format_.empty() ? io::format_from_extension(output_)
                                                  : io::parse_format(output_format_);
    write_options.ascii = ascii_;

    Report::Stage read_stage(context.report, "read");
    TriangleMesh mesh = io::read_mesh(input_, read_options);
    read_stage.finish();
    auto& data = context.report.data();
    data["input"] = input_;
    data["output"] = output_;
    data["vertices_read"] = mesh.vertices.size();
    data["faces_read"] = mesh.faces.size();

    Report::Stage dedup_stage(context.report, "duplicates");
    const std::size_t duplicates = dedup_ ? io::remove_duplicate_vertices(mesh)
                                          : io::count_duplicate_vertices(mesh);
    dedup_stage.finish();
    data["duplicate_vertices"] = duplicates;
    data["duplicates_removed"] = dedup_ && duplicates > 0;
    context.info("read " + std::to_string(data["vertices_read"].get<std::size_t>()) +
                 " vertices, " + std::to_string(mesh.faces.size()) + " faces from " + input_);
    if (duplicates > 0) {
      context.info(std::to_string(duplicates) + " exact duplicate vertices " +
                   (dedup_ ? "removed (first of each kept)" : "found (use --dedup to remove)"));
    }
    warn_about_dropped_data(context, mesh, write_options.format);

    Report::Stage write_stage(context.report, "write");
    io::write_mesh(output_, mesh, write_options);
    write_stage.finish();
    data["vertices_written"] = mesh.vertices.size();
    data["faces_written"] = write_options.format == io::Format::xyz ? 0 : mesh.faces.size();
    context.info("wrote " + std::to_string(mesh.vertices.size()) + " vertices to " + output_ +
                 " (" + io::format_name(write_options.format) + ")");
    return 0;
  }

 private:
  static void warn_about_dropped_data(Context& context, const TriangleMesh& mesh,
                                      io::Format format) {
    if (format == io::Format::xyz && !mesh.faces.empty()) {
      context.warn("XYZ output keeps no faces: " + std::to_string(mesh.faces.size()) +
                   " faces dropped");
    }
    if ((format == io::Format::off || format == io::Format::obj) &&
        !mesh.vertex_properties.empty()) {
      context.warn(io::format_name(format) + " output keeps no vertex properties: " +
                   std::to_string(mesh.vertex_properties.size()) + " dropped");
    }
  }

  std::string input_;
  std::string output_;
  std::string input_format_;
  std::string output_format_;
  std::string xyz_column_;
  bool ascii_ = false;
  bool dedup_ = false;
};

}  // namespace

RSTRUCT_REGISTER_COMMAND(ConvertCommand, "convert",
                         "Convert a point set or mesh between PLY, OFF, OBJ and XYZ");

}  // namespace rstruct::cli
