#pragma once
// Shared by `rstruct seed`, `rstruct reconstruct` and `rstruct demo`: run the seed-polytope
// pipeline on samples, print the Table 1 style breakdown, and write the outputs.

#include <string>
#include <vector>

#include "cli/command.hpp"
#include "rstruct/pipeline/seed_polytope.hpp"

namespace rstruct::cli {

struct SeedOutputs {
  std::string mesh;   // seed polytope / reconstruction (PLY, OFF, OBJ)
  std::string map;    // per-sample output vertex id, one per line
  std::string balls;  // kept balls as PLY vertices with radius
  bool ascii = false;
};

/// Runs the pipeline, records the breakdown in `report`, writes the outputs and returns
/// the result. Prints the summary to stderr unless quiet. With `shared` (a pole analysis
/// of `samples` computed once for several levels, whose stages are in `shared_report`)
/// the poles are not recomputed and the breakdown shows the shared stage's figures; if
/// that analysis is still being labelled, `pending` is its labelling (see
/// pipeline::compute_seed_polytope).
pipeline::SeedPolytope run_seed(const std::vector<Point3>& samples,
                                const pipeline::SeedOptions& options,
                                const SeedOutputs& outputs, Context& context, Report& report,
                                const std::string& title,
                                const poles::PoleAnalysis* shared = nullptr,
                                const Report* shared_report = nullptr,
                                poles::PendingLabels* pending = nullptr);

}  // namespace rstruct::cli
