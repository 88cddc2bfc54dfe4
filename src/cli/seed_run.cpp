#include "cli/seed_run.hpp"

#include <cstdio>
#include <iostream>
#include <sstream>

#include "rstruct/core/atomic_file.hpp"
#include "rstruct/io/mesh_io.hpp"

namespace rstruct::cli {

namespace {

std::string betti_text(const complex::BettiNumbers& b) {
  std::ostringstream s;
  s << "(" << b[0] << ", " << b[1] << ", " << b[2] << ", " << b[3] << ")";
  return s.str();
}

double stage_sum(const Report& report, std::initializer_list<const char*> names) {
  double sum = 0;
  for (const auto& [name, seconds] : report.stages()) {
    for (const char* n : names) {
      if (name == n) sum += seconds;
    }
  }
  return sum;
}

void write_outputs(const std::vector<Point3>& samples, const pipeline::SeedPolytope& seed,
                   const SeedOutputs& outputs) {
  io::WriteOptions options;
  options.ascii = outputs.ascii;
  if (!outputs.mesh.empty()) {
    TriangleMesh mesh;
    std::vector<double> sample_id, radius;
    for (std::uint32_t s : seed.vertex_sample) {
      mesh.vertices.push_back(samples[s]);
      sample_id.push_back(s);
      radius.push_back(seed.radius[s]);
    }
    mesh.faces = seed.triangles;
    mesh.vertex_properties = {{"sample_id", std::move(sample_id)}, {"radius", std::move(radius)}};
    io::write_mesh(outputs.mesh, mesh, options);
  }
  if (!outputs.map.empty()) {
    AtomicFile file(outputs.map);
    file.stream() << "# output vertex id of every input sample (0-based, input order)\n";
    for (std::uint32_t v : seed.sample_vertex) {
      file.stream() << (v == 0xffffffffu ? -1 : static_cast<long long>(v)) << '\n';
    }
    file.commit();
  }
  if (!outputs.balls.empty()) {
    TriangleMesh mesh;
    std::vector<double> radius, sample_id;
    for (std::uint32_t s : seed.kept) {
      mesh.vertices.push_back(samples[s]);
      radius.push_back(seed.radius[s]);
      sample_id.push_back(s);
    }
    mesh.vertex_properties = {{"radius", std::move(radius)}, {"sample_id", std::move(sample_id)}};
    io::write_mesh(outputs.balls, mesh, options);
  }
}

}  // namespace

pipeline::SeedPolytope run_seed(const std::vector<Point3>& samples,
                                const pipeline::SeedOptions& options,
                                const SeedOutputs& outputs, Context& context, Report& report,
                                const std::string& title) {
  pipeline::SeedPolytope seed = pipeline::compute_seed_polytope(samples, options, &report);
  for (const std::string& w : seed.warnings) context.warn(w);
  {
    Report::Stage stage(report, "output");
    write_outputs(samples, seed, outputs);
  }

  auto& d = report.data();
  d["parameters"] = {{"rho", options.rho}, {"rho_tilde", options.rho_tilde},
                     {"cover_time_limit", options.prune.time_limit}};
  d["samples"] = samples.size();
  d["kept_balls"] = seed.kept.size();
  d["hidden_balls"] = seed.hidden_balls;
  if (seed.pruned) {
    d["cover"] = {{"size", seed.prune.cost}, {"certified_lower_bound", seed.prune.lower_bound},
                  {"gap", seed.prune.gap}, {"optimal", seed.prune.optimal},
                  {"matrix_entries", seed.prune.entries}};
  }
  d["dual_complex"] = {{"simplices", seed.k_counts},
                       {"facets_exterior_singular_regular_interior", seed.facet_classes},
                       {"betti", seed.betti_k.b}};
  d["output"] = {{"vertices", seed.vertex_sample.size()},
                 {"triangles", seed.triangles.size()},
                 {"betti", seed.betti_output.b},
                 {"euler_characteristic", seed.betti_output.euler_characteristic()},
                 {"closed_2_manifold", seed.manifold.is_closed_2_manifold},
                 {"oriented", seed.oriented},
                 {"first_manifold_problem", seed.manifold.first_problem},
                 {"remapped_samples", seed.remapped_samples}};
  d["guarantee_holds"] = seed.warnings.empty();

  if (!context.quiet) {
    const double dp = stage_sum(report, {"delaunay", "poles", "labels", "pole distance"});
    const double sb = stage_sum(report, {"surface balls"});
    const double pr = stage_sum(report, {"covering sets", "set cover"});
    const double al = stage_sum(report, {"regular triangulation", "dual complex", "collapse",
                                         "homology"});
    const double out = stage_sum(report, {"sample map", "output"});
    char line[256];
    std::cerr << title << "\n";
    std::snprintf(line, sizeof line, "  %-28s %8.3f s\n", "Delaunay + poles", dp);
    std::cerr << line;
    std::snprintf(line, sizeof line, "  %-28s %8.3f s\n", "surface balls", sb);
    std::cerr << line;
    if (seed.pruned) {
      std::snprintf(line, sizeof line,
                    "  %-28s %8.3f s   cover %.0f balls, certified bound %.2f, gap %.2f%%\n",
                    "pruning (set cover)", pr, seed.prune.cost, seed.prune.lower_bound,
                    100 * seed.prune.gap);
    } else {
      std::snprintf(line, sizeof line, "  %-28s %8s     (rho~ = 0: every ball kept)\n",
                    "pruning (set cover)", "-");
    }
    std::cerr << line;
    std::snprintf(line, sizeof line, "  %-28s %8zu\n", "# remaining balls", seed.kept.size());
    std::cerr << line;
    std::snprintf(line, sizeof line, "  %-28s %8.3f s\n", "weighted alpha-shape", al);
    std::cerr << line;
    std::snprintf(line, sizeof line, "  %-28s %8.3f s\n", "output + sample map", out);
    std::cerr << line;
    std::snprintf(line, sizeof line, "  %-28s %8.3f s\n", "total", dp + sb + pr + al + out);
    std::cerr << line;
    std::cerr << "  dual complex K: " << seed.k_counts[0] << " vertices, " << seed.k_counts[1]
              << " edges, " << seed.k_counts[2] << " triangles, " << seed.k_counts[3]
              << " tetrahedra; Betti " << betti_text(seed.betti_k) << "\n";
    std::cerr << "  output: " << seed.vertex_sample.size() << " vertices ("
              << 100.0 * static_cast<double>(seed.vertex_sample.size()) /
                     static_cast<double>(samples.size())
              << "% of the samples), " << seed.triangles.size() << " triangles; Betti "
              << betti_text(seed.betti_output)
              << (seed.manifold.is_closed_2_manifold ? "; closed 2-manifold"
                                                     : "; NOT a closed 2-manifold: " +
                                                           seed.manifold.first_problem)
              << "\n";
  }
  return seed;
}

}  // namespace rstruct::cli
