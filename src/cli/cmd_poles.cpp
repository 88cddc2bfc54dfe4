// `rstruct poles IN -o poles.ply`: poles of a point sample, their inner/outer labels and
// the pole distance D̂ (issue 5; paper §2, §5; DESIGN.md §1).

#include <cstdint>
#include <limits>
#include <sstream>
#include <string>

#include "cli/command.hpp"
#include "rstruct/core/error.hpp"
#include "rstruct/io/mesh_io.hpp"
#include "rstruct/poles/pole_analysis.hpp"

namespace rstruct::cli {
namespace {

double label_code(poles::PoleLabel label) {
  switch (label) {
    case poles::PoleLabel::inner: return 1;
    case poles::PoleLabel::outer: return 2;
    case poles::PoleLabel::unlabelled: return 0;
  }
  return 0;
}

/// Poles as vertices with radius, label (0 unlabelled, 1 inner, 2 outer) and owner sample.
TriangleMesh pole_mesh(const poles::PoleSet& poles) {
  TriangleMesh mesh;
  mesh.vertices = poles.centre;
  std::vector<double> radius(poles.radius), label, owner;
  label.reserve(poles.size());
  owner.reserve(poles.size());
  for (std::uint32_t p = 0; p < poles.size(); ++p) {
    label.push_back(label_code(poles.label[p]));
    owner.push_back(poles.owner[p]);
  }
  mesh.vertex_properties = {{"radius", std::move(radius)},
                            {"label", std::move(label)},
                            {"owner", std::move(owner)}};
  return mesh;
}

/// Samples with D̂ and the indices of their inner and outer poles (−1: none).
TriangleMesh sample_mesh(const std::vector<Point3>& samples, const poles::PoleAnalysis& a) {
  TriangleMesh mesh;
  mesh.vertices = samples;
  std::vector<double> inner, outer;
  for (std::uint32_t s = 0; s < samples.size(); ++s) {
    const std::uint32_t i = a.poles.pole_of(s, poles::PoleLabel::inner);
    const std::uint32_t o = a.poles.pole_of(s, poles::PoleLabel::outer);
    inner.push_back(i == poles::kNoPole ? -1.0 : i);
    outer.push_back(o == poles::kNoPole ? -1.0 : o);
  }
  mesh.vertex_properties = {{"dhat", a.dhat.distance},
                            {"inner_pole", std::move(inner)},
                            {"outer_pole", std::move(outer)}};
  return mesh;
}

class PolesCommand final : public Command {
 public:
  void configure(CLI::App& app) override {
    app.add_option("input", input_, "Point sample (PLY, OFF, OBJ or XYZ)")->required();
    app.add_option("-o,--output", output_,
                   "Poles as PLY vertices with properties radius, label (0 unlabelled, "
                   "1 inner, 2 outer) and owner (a sample whose pole it is)")
        ->required();
    app.add_option("--samples-out", samples_out_,
                   "Also write the samples with properties dhat (pole distance D̂), "
                   "inner_pole and outer_pole (pole indices, -1 if none)");
    app.add_option("--box-scale", options_.box_scale,
                   "Half-width of the bounding-box sites' box in units of the sample's "
                   "largest extent (>= 2)")
        ->capture_default_str();
    app.add_option("--same-min-cos", options_.labeling.same_min_cos,
                   "Labeling: two polar spheres through a common sample meeting at angle φ "
                   "with cos φ >= this are on the same side")
        ->capture_default_str();
    app.add_option("--opposite-min-cos", options_.labeling.opposite_min_cos,
                   "Labeling: ... with -cos φ >= this are on opposite sides")
        ->capture_default_str();
    app.add_flag("--allow-unlabelled", allow_unlabelled_,
                 "Exit with 0 even if some poles are unlabelled or contradictory");
    app.add_option("--threads", options_.threads, "Threads for D̂ (0: all cores)")
        ->capture_default_str();
  }

  int run(Context& context) override {
    require_range(options_.labeling.same_min_cos, -1, 1, "--same-min-cos");
    require_range(options_.labeling.opposite_min_cos, -1, 1, "--opposite-min-cos");
    require_range(options_.box_scale, 2, std::numeric_limits<double>::max(), "--box-scale");
    TriangleMesh input;
    {
      Report::Stage stage(context.report, "read");
      input = io::read_mesh(input_);
    }
    context.report.data()["input"] = {{"path", input_}, {"points", input.vertices.size()}};
    context.info("read " + std::to_string(input.vertices.size()) + " points from " + input_);
    const poles::PoleAnalysis analysis =
        poles::analyse_poles(input.vertices, options_, &context.report);
    {
      Report::Stage stage(context.report, "write");
      io::write_mesh(output_, pole_mesh(analysis.poles));
      if (!samples_out_.empty()) io::write_mesh(samples_out_, sample_mesh(input.vertices, analysis));
    }
    const poles::LabelingStats& l = analysis.labeling;
    std::ostringstream summary;
    summary << analysis.poles.size() << " poles (" << l.inner << " inner, " << l.outer
            << " outer, " << l.unlabelled << " unlabelled) from " << analysis.tetrahedra
            << " Delaunay tetrahedra";
    if (analysis.duplicate_samples > 0) {
      summary << "; " << analysis.duplicate_samples << " duplicate samples share poles";
    }
    context.info(summary.str());
    if (!context.quiet) context.report.print_stages(std::cerr);
    if (l.is_clean()) return 0;
    std::ostringstream problem;
    problem << "labeling is not clean: " << l.unlabelled << " unlabelled poles (" << l.ties
            << " ties), " << l.contradictory << " contradictory poles, "
            << l.inconsistent_samples << " samples whose two poles got the same label, "
            << l.samples_without_inner
            << " samples without an inner pole (is the input an r-sample of a closed "
               "surface?); "
            << output_ << " was written with these labels";
    context.warn(problem.str());
    return allow_unlabelled_ ? 0 : 1;
  }

 private:
  std::string input_, output_, samples_out_;
  poles::PoleAnalysisOptions options_;
  bool allow_unlabelled_ = false;
};

}  // namespace
}  // namespace rstruct::cli

RSTRUCT_REGISTER_COMMAND(rstruct::cli::PolesCommand, "poles",
                         "Poles of a point sample, inner/outer labels and pole distance D̂");
