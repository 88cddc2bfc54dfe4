#include "cli/seed_run.hpp"

#include <algorithm>
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

/// Wall and CPU seconds of the named stages.
struct Seconds {
  double wall = 0;
  double cpu = 0;
  Seconds& operator+=(const Seconds& o) {
    wall += o.wall;
    cpu += o.cpu;
    return *this;
  }
};

Seconds stage_sum(const Report& report, std::initializer_list<const char*> names) {
  Seconds sum;
  for (std::size_t i = 0; i < report.stages().size(); ++i) {
    for (const char* n : names) {
      if (report.stages()[i].first == n) {
        sum.wall += report.stages()[i].second;
        sum.cpu += std::max(0.0, report.stage_cpu_seconds()[i]);
      }
    }
  }
  return sum;
}

void print_row(const char* name, const Seconds& s, const std::string& tail = "") {
  char line[256];
  std::snprintf(line, sizeof line, "  %-28s %8.3f s %8.3f s cpu%s\n", name, s.wall, s.cpu,
                tail.c_str());
  std::cerr << line;
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
                                const std::string& title, const poles::PoleAnalysis* shared,
                                const Report* shared_report, poles::PendingLabels* pending) {
  pipeline::SeedPolytope seed =
      shared != nullptr
          ? pipeline::compute_seed_polytope(samples, *shared, options, &report, pending)
          : pipeline::compute_seed_polytope(samples, options, &report);
  for (const std::string& w : seed.warnings) context.warn(w);
  {
    Report::Stage stage(report, "output");
    write_outputs(samples, seed, outputs);
  }

  auto& d = report.data();
  d["parameters"] = {{"rho", options.rho}, {"rho_tilde", options.rho_tilde},
                     {"cover_time_limit", options.prune.time_limit},
                     {"cover_iterations", options.prune.iterations},
                     {"candidates", options.candidates.empty() ? samples.size()
                                                               : options.candidates.size()},
                     {"shared_poles", shared != nullptr}};
  d["samples"] = samples.size();
  d["kept_balls"] = seed.kept.size();
  d["hidden_balls"] = seed.hidden_balls;
  if (seed.pruned) {
    const setcover::SolverOptions& budget = seed.prune.solver_options;
    const setcover::SolverStats& st = seed.prune.solver;
    d["cover"] = {{"size", seed.prune.cost}, {"certified_lower_bound", seed.prune.lower_bound},
                  {"gap", seed.prune.gap}, {"optimal", seed.prune.optimal},
                  {"matrix_entries", seed.prune.entries},
                  // The limits the solver ran with (0 local-search iterations: no limit)
                  // and which kind ended it: "time" means the cover depends on the machine.
                  {"budget", {{"local_search_iterations_per_stream",
                               budget.max_local_search_iterations},
                              {"local_search_streams", budget.local_search_streams},
                              {"subgradient_iterations_per_component",
                               budget.max_subgradient_iterations},
                              {"time_limit", budget.time_limit},
                              {"seed", budget.seed}}},
                  {"stopped_by", setcover::to_string(st.stopped_by)},
                  {"components", st.components},
                  {"subgradient_iterations", st.subgradient_iterations},
                  {"local_search_iterations", st.local_search_iterations},
                  {"exact_nodes", st.exact_nodes},
                  {"domination_work", st.reduction_work},
                  {"solver_seconds", st.seconds}};
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
  if (seed.pruned && options.prune.iterations > 0 &&
      seed.prune.solver.stopped_by == setcover::SearchLimit::kTime) {
    char limit[32];
    std::snprintf(limit, sizeof limit, "%g", options.prune.time_limit);
    context.warn(std::string("set cover: the time limit (") + limit +
                 " s) ended the search before the work budget, so the cover may differ "
                 "between runs and machines (raise --cover-time)");
  }

  if (!context.quiet) {
    const std::initializer_list<const char*> pole_stages = {
        "delaunay", "poles", "labels + pole distance", "pole distance"};
    const Seconds dp = stage_sum(shared_report != nullptr ? *shared_report : report,
                                 pole_stages);
    // The labels computed beside the level: the time the level waited for them at its end.
    const Seconds lw = stage_sum(report, {"labels (wait)"});
    bool labels_beside = false;
    for (const auto& stage : report.stages()) labels_beside |= stage.first == "labels (wait)";
    const Seconds sb = stage_sum(report, {"surface balls"});
    const Seconds pr = stage_sum(report, {"covering sets", "set cover"});
    const Seconds al = stage_sum(report, {"regular triangulation", "vertex stars",
                                          "dual complex", "collapse + homology"});
    const Seconds out = stage_sum(report, {"sample map", "output"});
    char line[256];
    std::cerr << title << "\n";
    print_row(shared != nullptr ? "Delaunay + poles (shared)" : "Delaunay + poles", dp);
    print_row("surface balls", sb);
    if (seed.pruned) {
      std::snprintf(line, sizeof line, "   cover %.0f balls, certified bound %.2f, gap %.2f%%",
                    seed.prune.cost, seed.prune.lower_bound, 100 * seed.prune.gap);
      print_row("pruning (set cover)", pr, line);
      const setcover::SolverStats& st = seed.prune.solver;
      const setcover::SolverOptions& budget = seed.prune.solver_options;
      std::string budget_text = "no iteration limit";
      if (budget.max_local_search_iterations > 0) {
        budget_text = "budget " + std::to_string(budget.max_local_search_iterations) +
                      " x " + std::to_string(budget.local_search_streams) + " streams";
      }
      std::snprintf(line, sizeof line,
                    "    %lld local-search (%s), %lld subgradient iterations; %.3g s limit; "
                    "stopped by %s\n",
                    static_cast<long long>(st.local_search_iterations), budget_text.c_str(),
                    static_cast<long long>(st.subgradient_iterations), budget.time_limit,
                    setcover::to_string(st.stopped_by));
      std::cerr << line;
    } else {
      std::snprintf(line, sizeof line, "  %-28s %8s     (rho~ = 0: every ball kept)\n",
                    "pruning (set cover)", "-");
      std::cerr << line;
    }
    std::snprintf(line, sizeof line, "  %-28s %8zu\n", "# remaining balls", seed.kept.size());
    std::cerr << line;
    print_row("weighted alpha-shape", al);
    print_row("output + sample map", out);
    if (labels_beside) print_row("pole labels (waited for)", lw);
    Seconds level = sb;
    level += pr;
    level += al;
    level += out;
    level += lw;
    print_row(shared != nullptr ? "level total (poles shared)" : "total",
              shared != nullptr ? level : (level += dp));
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
