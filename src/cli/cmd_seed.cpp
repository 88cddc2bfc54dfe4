// `rstruct seed IN -o seed.ply` and `rstruct reconstruct IN -o mesh.ply`: the paper's
// seed polytope (coarse, ρ = 0.5, pruned with ρ̃ = 0.03) and scalable reconstruction
// (ρ = 0.24, no pruning unless --shrink is given): one pipeline, two sets of defaults.

#include <optional>

#include "cli/command.hpp"
#include "cli/seed_run.hpp"
#include "rstruct/core/error.hpp"
#include "rstruct/io/mesh_io.hpp"

namespace rstruct::cli {

namespace {

class SeedCommand : public Command {
 public:
  SeedCommand(double rho, double shrink, std::string title)
      : title_(std::move(title)) {
    options_.rho = rho;
    options_.rho_tilde = shrink;
  }

  void configure(CLI::App& app) override {
    app.add_option("input", input_, "Point sample (PLY, OFF, OBJ or XYZ)")->required();
    app.add_option("-o,--output", outputs_.mesh, "Output mesh (.ply, .off, .obj)")->required();
    app.add_option("--rho", options_.rho,
                   "Surface-ball radius factor: radius = rho * D^(s); [0.24, 0.56] carries "
                   "the topology guarantee (Lemma 5.6)")
        ->capture_default_str();
    app.add_option("--shrink", options_.rho_tilde,
                   "Shrunk-ball factor rho~ for pruning (0: keep every ball); <= 0.03 carries "
                   "the guarantee (Theorem 6.1)")
        ->capture_default_str();
    app.add_option("--map", outputs_.map, "Write the output vertex id of every sample");
    app.add_option("--balls", outputs_.balls, "Write the kept balls (PLY with radius)");
    app.add_option("--cover-iterations", options_.prune.iterations,
                   "Set-cover work budget: local-search iterations per search stream; the "
                   "cover is then the same on any machine and thread count (0: no work "
                   "limit, --cover-time alone ends the search)")
        ->capture_default_str();
    app.add_option("--cover-time", options_.prune.time_limit,
                   "Set-cover wall-clock limit in seconds: a safety cap on the work budget, "
                   "or the budget itself with --cover-iterations 0 (the cover then depends "
                   "on the machine)")
        ->capture_default_str();
    app.add_option("--seed", options_.prune.seed, "Seed of the set-cover solver")
        ->capture_default_str();
    app.add_flag("--strict", options_.require_clean_labels,
                 "Fail if the pole labeling is not clean");
    app.add_flag("--ascii", outputs_.ascii, "ASCII PLY output");
    app.add_option("--threads", options_.threads, "Threads (0: all cores)")
        ->capture_default_str();
  }

  int run(Context& context) override {
    require_range(options_.rho, 1e-6, 1.0, "--rho");
    require_range(options_.rho_tilde, 0.0, 1.0, "--shrink");
    require_range(options_.prune.time_limit, 0.0, 1e6, "--cover-time");
    require_range(static_cast<double>(options_.prune.iterations), 0.0, kMaxCoverIterations,
                  "--cover-iterations");
    TriangleMesh input;
    {
      Report::Stage stage(context.report, "read");
      input = io::read_mesh(input_);
    }
    context.report.data()["input"] = input_;
    context.info("read " + std::to_string(input.vertices.size()) + " samples from " + input_);
    const pipeline::SeedPolytope seed =
        run_seed(input.vertices, options_, outputs_, context, context.report, title_);
    return seed.vertex_sample.empty() ? 1 : 0;
  }

 private:
  std::string title_;
  std::string input_;
  pipeline::SeedOptions options_;
  SeedOutputs outputs_;
};

class ReconstructCommand : public SeedCommand {
 public:
  ReconstructCommand() : SeedCommand(0.24, 0.0, "reconstruction") {}
};

class SeedPolytopeCommand : public SeedCommand {
 public:
  SeedPolytopeCommand() : SeedCommand(0.5, 0.03, "seed polytope") {}
};

}  // namespace

RSTRUCT_REGISTER_COMMAND(SeedPolytopeCommand, "seed",
                         "Seed polytope: a small mesh with vertices in the sample and the "
                         "topology of the surface, plus the sample-to-vertex map");
RSTRUCT_REGISTER_COMMAND(ReconstructCommand, "reconstruct",
                         "Scalable reconstruction: the seed pipeline with smaller balls");

}  // namespace rstruct::cli
