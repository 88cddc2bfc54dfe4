// `rstruct alpha BALLS -o OUT.txt`: the weighted α filtration of a union of balls
// (complex/alpha_filtration.hpp): every simplex of the balls' regular triangulation with
// the smallest α at which it belongs to the dual complex of the balls grown to weights
// r² + α, in filtration order. Its sublevel set at α = 0 is the dual complex K that
// `rstruct seed` collapses (issue 7's optional output).
//
// Input: an .xyzr file (x y z r per line, as `rstruct medial --balls-in`), a PLY with a
// vertex property `radius` or `weight` (the `--balls` output of `rstruct seed`), or an XYZ
// file whose 4th column is the weight. Output: text, '#' comment lines, then one simplex
// per line, "alpha dim v0 [v1 [v2 [v3]]]" (0-based input indices, increasing), sorted by
// alpha, then dimension: every face comes before its cofaces. The alpha values are
// floating-point constructions with the exact sign (alpha_filtration.hpp).

#include <array>
#include <charconv>
#include <filesystem>
#include <string>
#include <vector>

#include "cli/command.hpp"
#include "io/text_lines.hpp"
#include "rstruct/complex/alpha_filtration.hpp"
#include "rstruct/complex/orthosphere_predicates.hpp"
#include "rstruct/core/atomic_file.hpp"
#include "rstruct/core/error.hpp"
#include "rstruct/core/stopwatch.hpp"
#include "rstruct/io/mesh_io.hpp"
#include "rstruct/medial/xyzr_format.hpp"
#include "rstruct/triangulation/regular_triangulation_3.hpp"

namespace rstruct::cli {

namespace {

using complex::AlphaFiltration;
using complex::SimplicialComplex;
using complex::VertexId;
using triangulation::RegularTriangulation3;

class AlphaCommand : public Command {
 public:
  void configure(CLI::App& app) override {
    app.add_option("input", input_,
                   "Balls: .xyzr (x y z r per line), PLY with a vertex property `radius` or "
                   "`weight` (radius r means weight r^2), or XYZ with the weight as 4th column")
        ->required();
    app.add_option("-o,--output", output_,
                   "Output text file: one simplex per line, 'alpha dim v0 ...', in filtration "
                   "order (alpha <= 0: the dual complex K of the balls)")
        ->required();
    app.add_option("--format", format_,
                   "Input format (xyzr, ply, off, obj, xyz) instead of the input's extension");
    app.add_option("--threads", threads_,
                   "Threads of the triangulation and the filtration (0: all cores; the output "
                   "does not depend on the count)")
        ->capture_default_str();
  }

  int run(Context& context) override {
    Report::Stage read_stage(context.report, "read");
    std::vector<Point3> centres;
    std::vector<double> weights;
    read_balls(centres, weights);
    read_stage.finish();
    const std::size_t n = centres.size();

    Report::Stage triangulation_stage(context.report, "regular triangulation");
    triangulation::TriangulationOptions options;
    options.threads = threads_;
    const RegularTriangulation3 rt(std::move(centres), std::move(weights), options);
    triangulation_stage.finish();

    Report::Stage filtration_stage(context.report, "alpha filtration");
    complex::reset_orthosphere_predicate_counters();
    const AlphaFiltration f = complex::alpha_filtration(rt, threads_);
    const complex::OrthospherePredicateCounters evaluations =
        complex::orthosphere_predicate_counters();
    filtration_stage.finish();

    Report::Stage write_stage(context.report, "write");
    const std::array<std::size_t, 4> in_k = write(f, n, rt);
    write_stage.finish();

    const SimplicialComplex& r = f.triangulation;
    auto& data = context.report.data();
    data["input"] = input_;
    data["output"] = output_;
    data["balls"] = n;
    data["vertices"] = rt.number_of_vertices();
    data["hidden_balls"] = rt.hidden_points().size();
    data["duplicates"] = rt.duplicate_points().size();
    data["simplices"] = {r.size(0), r.size(1), r.size(2), r.size(3)};
    data["dual_complex_simplices"] = {in_k[0], in_k[1], in_k[2], in_k[3]};
    data["orthosphere_evaluations"] = {{"filtered", evaluations.filtered},
                                       {"exact", evaluations.exact}};
    data["peak_memory_bytes"] = peak_memory_bytes();
    context.info(std::to_string(n) + " balls: " + std::to_string(rt.number_of_vertices()) +
                 " vertices (" + std::to_string(rt.hidden_points().size()) + " hidden, " +
                 std::to_string(rt.duplicate_points().size()) + " duplicates merged); " +
                 std::to_string(r.total_size()) + " simplices (" + std::to_string(r.size(0)) +
                 ", " + std::to_string(r.size(1)) + ", " + std::to_string(r.size(2)) + ", " +
                 std::to_string(r.size(3)) + "), of which the dual complex (alpha <= 0) has " +
                 std::to_string(in_k[0] + in_k[1] + in_k[2] + in_k[3]));
    context.info("wrote " + output_);
    return 0;
  }

 private:
  void read_balls(std::vector<Point3>& centres, std::vector<double>& weights) const {
    const bool xyzr = format_ == "xyzr" ||
                      (format_.empty() && std::filesystem::path(input_).extension() == ".xyzr");
    if (xyzr) {
      for (const Ball& b : medial::read_xyzr(input_)) {
        centres.push_back(b.c);
        weights.push_back(b.r * b.r);
      }
      return;
    }
    io::ReadOptions read_options;
    if (!format_.empty()) read_options.format = io::parse_format(format_);
    const io::Format format = read_options.format == io::Format::automatic
                                  ? io::format_from_extension(input_)
                                  : read_options.format;
    if (format == io::Format::xyz) read_options.xyz_fourth_column = "weight";
    TriangleMesh mesh = io::read_mesh(input_, read_options);
    weights = weights_from_properties(mesh, input_, "alpha");
    centres = std::move(mesh.vertices);
  }

  /// Writes the filtration; returns the number of simplices with α ≤ 0 per dimension.
  std::array<std::size_t, 4> write(const AlphaFiltration& f, std::size_t balls,
                                   const RegularTriangulation3& rt) const {
    const SimplicialComplex& r = f.triangulation;
    std::array<std::size_t, 4> in_k{};
    AtomicFile file(output_);
    std::ostream& out = file.stream();
    out << "# rstruct alpha: weighted alpha filtration of " << balls << " balls ("
        << rt.number_of_vertices() << " vertices, " << rt.hidden_points().size()
        << " hidden, " << rt.duplicate_points().size() << " duplicates merged)\n"
        << "# alpha: the least growth of the weights (r^2 + alpha) at which the simplex is "
           "in the dual complex of the balls; alpha <= 0: the dual complex K itself\n"
        << "# alpha dim v0 [v1 [v2 [v3]]] (0-based input indices), faces before cofaces\n";
    // Lines built in a buffer written in large pieces (see AlphaFiltration::order()).
    std::string chunk;
    const auto put_vertices = [&](auto&& vertices) {
      for (const VertexId v : vertices) {
        chunk += ' ';
        char digits[16];
        const auto end = std::to_chars(digits, digits + sizeof digits, v).ptr;
        chunk.append(digits, end);
      }
    };
    for (const auto& [d, i] : f.order()) {
      const double a = f.alpha[d][i];
      if (a <= 0) ++in_k[d];
      io::detail::append_double(chunk, a);
      chunk += ' ';
      chunk += static_cast<char>('0' + d);
      switch (d) {
        case 0: put_vertices(std::array<VertexId, 1>{r.vertices()[i]}); break;
        case 1: put_vertices(r.edges()[i]); break;
        case 2: put_vertices(r.triangles()[i]); break;
        default: put_vertices(r.tetrahedra()[i]); break;
      }
      chunk += '\n';
      if (chunk.size() > (1u << 20)) {
        out.write(chunk.data(), static_cast<std::streamsize>(chunk.size()));
        chunk.clear();
      }
    }
    out.write(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    file.commit();
    return in_k;
  }

  std::string input_;
  std::string output_;
  std::string format_;
  unsigned threads_ = 0;
};

}  // namespace

RSTRUCT_REGISTER_COMMAND(AlphaCommand, "alpha",
                         "Weighted alpha filtration of a union of balls (dual complex at every "
                         "alpha)");

}  // namespace rstruct::cli
