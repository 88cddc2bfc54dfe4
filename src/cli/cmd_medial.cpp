// `rstruct medial IN -o axis.ma`: stable medial axis of a point sample (paper §3, §5.1,
// Table 2): inner polar balls enlarged by ε, pruned by set cover, and the exact medial axis
// of the union of the kept balls. `rstruct medial --balls-in balls.xyzr -o axis.ma`: the
// medial axis of any union of balls.

#include <cstdio>
#include <iostream>
#include <sstream>

#include "cli/command.hpp"
#include "rstruct/core/error.hpp"
#include "rstruct/io/mesh_io.hpp"
#include "rstruct/medial/medial_axis_io.hpp"
#include "rstruct/medial/stable_medial_axis.hpp"
#include "rstruct/medial/xyzr_format.hpp"

namespace rstruct::cli {

namespace {

std::string betti_text(const complex::BettiNumbers& b) {
  std::ostringstream s;
  s << "(" << b[0] << ", " << b[1] << ", " << b[2] << ")";
  return s.str();
}

class MedialCommand : public Command {
 public:
  void configure(CLI::App& app) override {
    app.add_option("input", input_, "Point sample of a closed surface (PLY, OFF, OBJ or XYZ)");
    app.add_option("--balls-in", balls_in_,
                   "Compute the medial axis of this union of balls instead (x y z r per line)");
    app.add_option("-o,--output", output_, "Output medial axis (.ma, or .ply)")->required();
    auto* eps = app.add_option("--eps", options_.eps,
                               "Absolute enlargement of the inner polar balls");
    app.add_option("--eps-rel", options_.eps_rel,
                   "Enlargement relative to the bounding-box diagonal")
        ->capture_default_str()
        ->excludes(eps);
    app.add_option("--balls", balls_out_, "Write the kept balls (PLY with radius)");
    app.add_option("--cover-time", options_.cover_time_limit,
                   "Seconds for the set-cover solver (default: proportional to the instance)");
    app.add_option("--seed", options_.seed, "Seed of the set-cover solver")
        ->capture_default_str();
  }

  int run(Context& context) override {
    if (input_.empty() == balls_in_.empty()) {
      throw InvalidInput("medial: give either a sample file or --balls-in FILE");
    }
    if (options_.eps >= 0) require_range(options_.eps, 0.0, 1e300, "--eps");
    require_range(options_.eps_rel, 0.0, 10.0, "--eps-rel");
    if (options_.cover_time_limit >= 0) {
      require_range(options_.cover_time_limit, 0.0, 1e6, "--cover-time");
    }
    auto& d = context.report.data();
    medial::StableMedialAxis out;
    if (!balls_in_.empty()) {
      std::vector<Ball> balls;
      {
        Report::Stage stage(context.report, "read");
        balls = medial::read_xyzr(balls_in_);
      }
      d["input"] = balls_in_;
      context.info("read " + std::to_string(balls.size()) + " balls from " + balls_in_);
      out = medial::medial_axis_of_balls(balls, &context.report);
    } else {
      TriangleMesh input;
      {
        Report::Stage stage(context.report, "read");
        input = io::read_mesh(input_);
      }
      d["input"] = input_;
      context.info("read " + std::to_string(input.vertices.size()) + " samples from " + input_);
      out = medial::stable_medial_axis(input.vertices, options_, &context.report);
    }
    {
      Report::Stage stage(context.report, "output");
      medial::write_medial_axis(output_, out.axis);
      if (!balls_out_.empty()) write_balls(out);
    }
    record(context, out);
    if (!context.quiet) print_table(out);
    if (out.violations > 0) {
      context.warn(std::to_string(out.violations) +
                   " outer poles lie inside enlarged inner polar balls (DMAT'_in meets A_out, "
                   "paper §5.1): epsilon is too large for a topology guarantee");
    }
    if (out.betti_axis != out.axis_stats.betti_k) {
      context.warn("the medial axis has Betti numbers " + betti_text(out.betti_axis) +
                   " but the union of balls has " + betti_text(out.axis_stats.betti_k));
    }
    return 0;
  }

 private:
  void write_balls(const medial::StableMedialAxis& out) const {
    TriangleMesh mesh;
    std::vector<double> radius;
    for (const Ball& b : out.kept_balls) {
      mesh.vertices.push_back(b.c);
      radius.push_back(b.r);
    }
    mesh.vertex_properties = {{"radius", std::move(radius)}};
    io::write_mesh(balls_out_, mesh);
  }

  void record(Context& context, const medial::StableMedialAxis& out) const {
    auto& d = context.report.data();
    const auto& s = out.axis_stats;
    if (!input_.empty()) {
      d["parameters"] = {{"eps", out.eps},
                         {"eps_rel", options_.eps >= 0 ? out.eps / out.bbox_diagonal
                                                       : options_.eps_rel},
                         {"cover_time_limit", out.cover_time_limit}};
      d["samples"] = out.samples;
      d["polar_balls"] = out.inner_poles;
      d["cover"] = {{"size", out.prune.cost}, {"certified_lower_bound", out.prune.lower_bound},
                    {"gap", out.prune.gap}, {"optimal", out.prune.optimal},
                    {"matrix_entries", out.prune.entries}};
      d["outer_pole_check"] = {{"outer_poles_tested", out.outer_poles},
                               {"box_poles_not_tested", out.box_poles},
                               {"violations", out.violations}};
    }
    d["kept_balls"] = out.kept_balls.size();
    d["union"] = {{"hidden_balls", s.hidden_balls}, {"dual_complex_simplices", s.k_counts},
                  {"betti", s.betti_k.b}, {"boundary_vertices", s.boundary_vertices},
                  {"singular_edges", s.singular_edges},
                  {"singular_vertices", s.singular_vertices}};
    d["medial_axis"] = {{"vertices", out.axis.vertices.size()},
                        {"edges", out.axis.all_edges().size()},
                        {"faces", out.axis.faces.size()},
                        {"triangles", out.axis.triangles().size()},
                        {"betti", out.betti_axis.b}};
    d["seconds"] = {{"polar_balls", out.polar_seconds}, {"pruning", out.pruning_seconds},
                    {"outer_pole_check", out.check_seconds}, {"medial_axis", out.medial_seconds}};
  }

  void print_table(const medial::StableMedialAxis& out) const {
    char line[256];
    std::cerr << "stable medial axis\n";
    if (!input_.empty()) {
      std::snprintf(line, sizeof line, "  %-26s %8.3f s   %zu inner polar balls, eps %.4g\n",
                    "polar balls", out.polar_seconds, out.inner_poles, out.eps);
      std::cerr << line;
      std::snprintf(line, sizeof line,
                    "  %-26s %8.3f s   cover %.0f balls, certified bound %.2f, gap %.2f%%\n",
                    "pruning (set cover)", out.pruning_seconds, out.prune.cost,
                    out.prune.lower_bound, 100 * out.prune.gap);
      std::cerr << line;
      std::snprintf(line, sizeof line,
                    "  %-26s %8.3f s   %zu of %zu outer poles inside DMAT'_in (%zu at infinity "
                    "not tested)\n",
                    "check DMAT'_in vs A_out", out.check_seconds, out.violations,
                    out.outer_poles, out.box_poles);
      std::cerr << line;
    }
    std::snprintf(line, sizeof line, "  %-26s %8.3f s   %zu balls -> %zu vertices, %zu faces\n",
                  "medial axis", out.medial_seconds, out.kept_balls.size(),
                  out.axis.vertices.size(), out.axis.faces.size());
    std::cerr << line;
    std::snprintf(line, sizeof line, "  %-26s %8.3f s\n", "total",
                  out.polar_seconds + out.pruning_seconds + out.check_seconds +
                      out.medial_seconds);
    std::cerr << line;
    std::cerr << "  Betti numbers: union " << betti_text(out.axis_stats.betti_k)
              << ", medial axis " << betti_text(out.betti_axis) << "\n";
  }

  std::string input_;
  std::string balls_in_;
  std::string output_;
  std::string balls_out_;
  medial::StableMedialAxisOptions options_;
};

}  // namespace

RSTRUCT_REGISTER_COMMAND(MedialCommand, "medial",
                         "Stable medial axis of a sample (pruned polar balls), or the medial "
                         "axis of a union of balls (--balls-in)");

}  // namespace rstruct::cli
