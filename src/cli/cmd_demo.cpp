// `rstruct demo`: the main job on an embedded default, nothing downloaded. It generates
// the paper's double torus input (Figure 11: 85,237 samples of a genus-2 surface) and runs
// the seed pipeline at three levels of detail, from every sample kept to a coarse seed
// polytope, printing the Table 1 breakdown, the Betti numbers of each output, and writing
// meshes that open in MeshLab/ParaView. The Delaunay triangulation, poles and D̂ are
// computed once for all levels; with --nested (default) a level whose shrink factor is at
// least the previous level's prunes among the balls that level kept: their smaller shrunk
// balls already cover every sample, so the larger ones do too.

#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>

#include "cli/command.hpp"
#include "cli/seed_run.hpp"
#include "rstruct/core/error.hpp"
#include "rstruct/io/mesh_io.hpp"
#include "rstruct/poles/pole_analysis.hpp"
#include "rstruct/sampling/sample_request.hpp"
#include "rstruct/triangulation/spatial_sort.hpp"

namespace rstruct::cli {

namespace {

struct Level {
  double rho;
  double shrink;
};

std::vector<Level> parse_levels(const std::string& text) {
  std::vector<Level> levels;
  std::istringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    Level level{};
    char colon = 0;
    std::istringstream one(item);
    if (!(one >> level.rho >> colon >> level.shrink) || colon != ':' ||
        !(one >> std::ws).eof()) {
      throw InvalidInput("--levels: expected RHO:SHRINK,..., got '" + item + "'");
    }
    require_range(level.rho, 1e-6, 1.0, "--levels rho");
    require_range(level.shrink, 0.0, 1.0, "--levels shrink");
    levels.push_back(level);
  }
  if (levels.empty()) throw InvalidInput("--levels: give at least one RHO:SHRINK");
  return levels;
}

class DemoCommand : public Command {
 public:
  void configure(CLI::App& app) override {
    app.add_option("--out-dir", out_dir_, "Folder for the outputs")->capture_default_str();
    app.add_option("--n", n_, "Number of double-torus samples")->capture_default_str();
    app.add_option("--levels", levels_,
                   "Levels of detail as RHO:SHRINK,... (shrink 0: no pruning)")
        ->capture_default_str();
    app.add_option("--cover-iterations", cover_iterations_,
                   "Work budget of each set cover: local-search iterations per search "
                   "stream; the outputs are then the same on any machine and thread count "
                   "(0: no work limit, --cover-time alone ends the search)")
        ->capture_default_str();
    app.add_option("--cover-time", cover_time_,
                   "Wall-clock limit of each set cover in seconds: a safety cap on the work "
                   "budget, or the budget itself with --cover-iterations 0")
        ->capture_default_str();
    app.add_option("--seed", seed_, "Seed of the sample")->capture_default_str();
    app.add_flag("--nested,!--no-nested", nested_,
                 "Prune each level among the balls kept by the previous level (when its "
                 "shrink factor is not smaller)")
        ->capture_default_str();
    app.add_option("--threads", threads_, "Threads (0: all cores)")->capture_default_str();
  }

  int run(Context& context) override {
    const std::vector<Level> levels = parse_levels(levels_);
    if (n_ < 100 || n_ > 50000000) throw InvalidInput("--n must be in [100, 5e7]");
    require_range(cover_time_, 0.0, 1e6, "--cover-time");
    require_range(static_cast<double>(cover_iterations_), 0.0, kMaxCoverIterations,
                  "--cover-iterations");
    std::filesystem::create_directories(out_dir_);

    sampling::SampleRequest request;
    request.shape = "double-torus";
    request.n = n_;
    request.seed = seed_;
    Report::Stage sample_stage(context.report, "sample");
    const sampling::SampleOutput sample = sampling::generate_sample(request);
    // The samples are written and processed along a Hilbert curve: the order of a sample
    // is arbitrary, and this one lets every per-sample array be read with locality.
    std::vector<Point3> samples;
    samples.reserve(sample.points.size());
    for (const std::uint32_t i : triangulation::hilbert_order(sample.points)) {
      samples.push_back(sample.points[i]);
    }
    sample_stage.finish();
    TriangleMesh points;
    points.vertices = samples;
    io::write_mesh(std::filesystem::path(out_dir_) / "double_torus_samples.ply", points);
    context.info("double torus (genus 2): " + std::to_string(samples.size()) +
                 " samples in " + std::to_string(sample.seconds) + " s -> " + out_dir_ +
                 "/double_torus_samples.ply");

    // Step 1 of every level, once: Delaunay, poles, D̂, and the pole labels, which only the
    // levels' final check reads: with more than one thread they run beside level 1.
    Report pole_report;
    poles::PoleAnalysisOptions pole_options;
    pole_options.threads = threads_;
    pole_options.label = !poles::label_beside(threads_);
    poles::PoleAnalysis analysis = poles::analyse_poles(samples, pole_options, &pole_report);
    std::optional<poles::PendingLabels> pending;
    if (!analysis.labelled) {
      pending.emplace(analysis, samples, pole_options.labeling, &pole_report);
    }
    if (!context.quiet) {
      std::cerr << "\nshared by every level: Delaunay, poles, pole distance"
                << (pending ? " (the pole labels run beside level 1)\n" : ", labels\n");
      pole_report.print_stages(std::cerr);
    }

    nlohmann::json level_reports = nlohmann::json::array();
    int failures = 0;
    std::vector<std::uint32_t> previous_kept;
    double previous_shrink = -1;
    for (std::size_t i = 0; i < levels.size(); ++i) {
      pipeline::SeedOptions options;
      options.rho = levels[i].rho;
      options.rho_tilde = levels[i].shrink;
      options.prune.time_limit = cover_time_;
      options.prune.iterations = cover_iterations_;
      options.threads = threads_;
      if (nested_ && options.rho_tilde > 0 && options.rho_tilde >= previous_shrink) {
        options.candidates = previous_kept;  // empty after an unpruned level: every sample
      }
      const std::string stem = (std::filesystem::path(out_dir_) /
                                ("level" + std::to_string(i + 1))).string();
      SeedOutputs outputs{stem + ".ply", stem + "_map.txt", stem + "_balls.ply", false};
      Report level_report;
      std::ostringstream title;
      title << "\nlevel " << i + 1 << ": rho = " << options.rho << ", shrink = "
            << options.rho_tilde << "  -> " << outputs.mesh;
      const pipeline::SeedPolytope seed = run_seed(samples, options, outputs, context,
                                                   level_report, title.str(), &analysis,
                                                   &pole_report, pending ? &*pending : nullptr);
      previous_kept = seed.kept;
      previous_shrink = options.rho_tilde;
      if (previous_kept.size() == samples.size()) previous_kept.clear();
      const bool genus_ok = seed.betti_output == complex::BettiNumbers{{1, 4, 1, 0}};
      if (!genus_ok) {
        ++failures;
        context.warn("level " + std::to_string(i + 1) +
                     ": output Betti numbers differ from the double torus's (1, 4, 1)");
      }
      level_reports.push_back(level_report.to_json());
    }
    context.report.data()["shared_poles"] = pole_report.to_json();
    context.report.data()["levels"] = level_reports;
    context.report.data()["samples"] = samples.size();
    return failures == 0 ? 0 : 1;
  }

 private:
  std::string out_dir_ = "demo-output";
  std::size_t n_ = 85237;
  // Level 3 reaches the paper's < 1 % of the samples (549 vertices in Figure 11) only with
  // ρ and ρ̃ above the guaranteed ranges; the pipeline warns about it, and the demo checks
  // the Betti numbers of every output instead.
  std::string levels_ = "0.5:0,0.56:0.15,0.8:0.5";
  double cover_time_ = pipeline::kDefaultCoverTimeCap;
  std::int64_t cover_iterations_ = pipeline::kDefaultCoverIterations;
  std::uint64_t seed_ = 1;
  bool nested_ = true;
  unsigned threads_ = 0;
};

}  // namespace

RSTRUCT_REGISTER_COMMAND(DemoCommand, "demo",
                         "Main job: the paper's double torus (85,237 samples) at three levels "
                         "of detail, with the Table 1 breakdown");

}  // namespace rstruct::cli
