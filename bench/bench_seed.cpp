// Benchmark of issue 7's speed targets: the seed pipeline at several levels of detail on
// one input, the pole analysis shared by the levels (as `rstruct demo` runs it). Default
// input: the demo's double torus (85,237 samples, seed 1), levels as the demo's
// (0.5:0, 0.56:0.15 nested, 0.8:0.5 nested). --torus N: a torus (R/a = 3) with N
// samples instead (the 10⁶-sample target: --torus 1000000 --levels 0.5:0).
// Prints, per level, every stage's median wall and CPU seconds over --runs, the level's
// total, and a checksum (kept balls, output vertices, triangles, Betti numbers, manifold);
// per run, the cover (size, certified bound, gap) and a hash of the kept balls and the
// output mesh, so that runs can be compared for identical results.
//
// The set cover stops on its work budget (--cover-iterations, default the pipeline's),
// so every run gives the same output; --cover-iterations 0 --cover-time 0.3 restores the
// former wall-clock budget.
//
//   bench_seed [--runs 3] [--torus N] [--levels RHO:SHRINK,...] [--cover-iterations N]
//              [--cover-time 60] [--threads 0] [--no-nested] [--random-order]
//              [--labels-first]
//
// With more than one thread the pole labels run beside level 1, as in `rstruct demo`;
// --labels-first labels them in the shared stage instead (to compare the two).

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "rstruct/complex/orthosphere_predicates.hpp"
#include "rstruct/core/large_blocks.hpp"
#include "rstruct/core/report.hpp"
#include "rstruct/core/stopwatch.hpp"
#include "rstruct/pipeline/seed_polytope.hpp"
#include "rstruct/predicates/counters.hpp"
#include "rstruct/poles/pole_analysis.hpp"
#include "rstruct/sampling/sample_request.hpp"
#include "rstruct/triangulation/spatial_sort.hpp"

namespace {

using rstruct::Point3;
using rstruct::Report;

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t k = v.size() / 2;
  return v.size() % 2 == 1 ? v[k] : 0.5 * (v[k - 1] + v[k]);
}

/// FNV-1a over the kept balls, the output vertices and the triangles.
std::uint64_t output_hash(const rstruct::pipeline::SeedPolytope& seed) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  const auto mix = [&h](std::uint64_t v) {
    for (int b = 0; b < 8; ++b) {
      h ^= (v >> (8 * b)) & 0xffU;
      h *= 0x100000001b3ULL;
    }
  };
  mix(seed.kept.size());
  for (const std::uint32_t s : seed.kept) mix(s);
  mix(seed.vertex_sample.size());
  for (const std::uint32_t s : seed.vertex_sample) mix(s);
  for (const auto& t : seed.triangles) {
    for (const std::uint32_t v : t) mix(v);
  }
  return h;
}

struct Level {
  double rho = 0.5;
  double shrink = 0;
};

std::vector<Level> parse_levels(const std::string& text) {
  std::vector<Level> levels;
  std::istringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    Level l;
    if (std::sscanf(item.c_str(), "%lf:%lf", &l.rho, &l.shrink) != 2) {
      std::fprintf(stderr, "bad level '%s'\n", item.c_str());
      std::exit(2);
    }
    levels.push_back(l);
  }
  return levels;
}

/// Stage → wall and CPU seconds of every run, in order of first appearance.
struct StageTimes {
  std::vector<std::string> order;
  std::map<std::string, std::vector<double>> wall;
  std::map<std::string, std::vector<double>> cpu;
  std::vector<double> total_wall;
  std::vector<double> total_cpu;

  void add(const Report& report) {
    double w = 0;
    double c = 0;
    for (std::size_t i = 0; i < report.stages().size(); ++i) {
      const std::string& name = report.stages()[i].first;
      if (!wall.count(name)) order.push_back(name);
      wall[name].push_back(report.stages()[i].second);
      cpu[name].push_back(report.stage_cpu_seconds()[i]);
      w += report.stages()[i].second;
      c += report.stage_cpu_seconds()[i];
    }
    total_wall.push_back(w);
    total_cpu.push_back(c);
  }

  void print(const char* title) const {
    std::printf("%s\n", title);
    for (const std::string& name : order) {
      std::printf("  %-24s %9.3f s %9.3f s cpu\n", name.c_str(), median(wall.at(name)),
                  median(cpu.at(name)));
    }
    std::printf("  %-24s %9.3f s %9.3f s cpu\n", "total", median(total_wall),
                median(total_cpu));
  }
};

/// In a build with -Dcounters=true: how often each stage decided orient3d and `id` since
/// the counts were reset.
void print_stage_counts(int run, const std::string& stage, rstruct::predicates::PredicateId id) {
  namespace pr = rstruct::predicates;
  if (!pr::counters_enabled()) return;
  for (const auto which : {pr::PredicateId::orient3d, id}) {
    const pr::StageCounts c = pr::stage_counts(which);
    std::fprintf(stderr, "run %d %s: %s %llu filter, %llu dynamic, %llu exact, %llu perturbed\n",
                 run + 1, stage.c_str(), pr::predicate_name(which),
                 static_cast<unsigned long long>(c.filter),
                 static_cast<unsigned long long>(c.dynamic),
                 static_cast<unsigned long long>(c.exact),
                 static_cast<unsigned long long>(c.perturbed));
  }
}

}  // namespace

int main(int argc, char** argv) {
  int runs = 3;
  std::size_t torus = 0;
  std::string levels_text = "0.5:0,0.56:0.15,0.8:0.5";
  double cover_time = rstruct::pipeline::kDefaultCoverTimeCap;
  long long cover_iterations = rstruct::pipeline::kDefaultCoverIterations;
  int cover_subgradient = rstruct::pipeline::kDefaultCoverSubgradientIterations;
  unsigned threads = 0;
  bool nested = true;
  bool random_order = false;
  bool labels_first = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const auto next = [&]() -> const char* {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "%s needs a value\n", a.c_str());
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--runs") {
      runs = std::atoi(next());
    } else if (a == "--torus") {
      torus = std::strtoull(next(), nullptr, 10);
    } else if (a == "--levels") {
      levels_text = next();
    } else if (a == "--cover-time") {
      cover_time = std::atof(next());
      if (!(cover_time >= 0 && cover_time <= 1e6)) {
        std::fprintf(stderr, "--cover-time must be in [0, 1e6] seconds\n");
        return 2;
      }
    } else if (a == "--cover-iterations") {
      cover_iterations = std::atoll(next());
      if (cover_iterations < 0 || cover_iterations > 1'000'000'000'000LL) {
        std::fprintf(stderr, "--cover-iterations must be in [0, 1e12] (0: time limit only)\n");
        return 2;
      }
    } else if (a == "--cover-subgradient") {
      cover_subgradient = std::atoi(next());
      if (cover_subgradient < 1 || cover_subgradient > 1'000'000) {
        std::fprintf(stderr, "--cover-subgradient must be in [1, 1e6]\n");
        return 2;
      }
    } else if (a == "--threads") {
      threads = static_cast<unsigned>(std::atoi(next()));
    } else if (a == "--no-nested") {
      nested = false;
    } else if (a == "--random-order") {
      random_order = true;
    } else if (a == "--labels-first") {
      labels_first = true;
    } else {
      std::fprintf(stderr,
                   "usage: bench_seed [--runs 3] [--torus N] [--levels RHO:SHRINK,...] "
                   "[--cover-iterations %lld] [--cover-time %g] [--threads 0] [--no-nested] "
                   "[--random-order] [--labels-first]\n"
                   "  --cover-iterations: set-cover local-search iterations per stream "
                   "(deterministic; 0: stop on --cover-time only)\n"
                   "  --cover-time: set-cover wall-clock limit in seconds (a safety cap "
                   "unless --cover-iterations is 0)\n",
                   static_cast<long long>(rstruct::pipeline::kDefaultCoverIterations),
                   rstruct::pipeline::kDefaultCoverTimeCap);
      return a == "--help" ? 0 : 2;
    }
  }
  const std::vector<Level> levels = parse_levels(levels_text);

  rstruct::sampling::SampleRequest request;
  request.shape = torus > 0 ? "torus" : "double-torus";
  request.n = torus > 0 ? torus : 85237;
  request.seed = 1;
  const std::vector<Point3> generated = rstruct::sampling::generate_sample(request).points;
  // As `rstruct demo` (and compute_seed_polytope without a PoleAnalysis) do: samples along
  // a Hilbert curve, for locality. --random-order keeps the sampler's order.
  std::vector<Point3> samples;
  if (random_order) {
    samples = generated;
  } else {
    for (const std::uint32_t i : rstruct::triangulation::hilbert_order(generated)) {
      samples.push_back(generated[i]);
    }
  }
  std::printf(
      "input: %s, %zu samples (%s order); levels %s; %d runs; cover budget %lld iterations "
      "(0: none), time limit %.2f s\n",
      request.shape.c_str(), samples.size(), random_order ? "sampler" : "Hilbert",
      levels_text.c_str(), runs, cover_iterations, cover_time);

  StageTimes poles;
  std::vector<StageTimes> level_times(levels.size());
  std::vector<std::string> checksums(levels.size());
  for (int run = 0; run < runs; ++run) {
    Report pole_report;
    rstruct::poles::PoleAnalysisOptions pole_options;
    pole_options.threads = threads;
    // As `rstruct demo`: with more than one thread the labels run beside level 1.
    pole_options.label = labels_first || !rstruct::poles::label_beside(threads);
    rstruct::predicates::reset_stage_counts();
    rstruct::poles::PoleAnalysis analysis =
        rstruct::poles::analyse_poles(samples, pole_options, &pole_report);
    std::optional<rstruct::poles::PendingLabels> pending;
    if (!analysis.labelled) {
      pending.emplace(analysis, samples, pole_options.labeling, &pole_report);
    }
    poles.add(pole_report);
    print_stage_counts(run, "shared", rstruct::predicates::PredicateId::insphere);
    std::vector<std::uint32_t> previous_kept;
    double previous_shrink = -1;
    for (std::size_t l = 0; l < levels.size(); ++l) {
      rstruct::pipeline::SeedOptions options;
      options.rho = levels[l].rho;
      options.rho_tilde = levels[l].shrink;
      options.prune.time_limit = cover_time;
      options.prune.iterations = cover_iterations;
      options.prune.subgradient_iterations = cover_subgradient;
      options.threads = threads;
      if (nested && options.rho_tilde > 0 && options.rho_tilde >= previous_shrink) {
        options.candidates = previous_kept;
      }
      Report report;
      rstruct::complex::reset_orthosphere_predicate_counters();
      rstruct::predicates::reset_stage_counts();
      const auto seed = rstruct::pipeline::compute_seed_polytope(
          samples, analysis, options, &report, pending ? &*pending : nullptr);
      level_times[l].add(report);
      previous_kept = seed.kept.size() == samples.size() ? std::vector<std::uint32_t>{}
                                                         : seed.kept;
      previous_shrink = options.rho_tilde;
      char line[256];
      std::snprintf(line, sizeof line,
                    "kept %zu, output %zu vertices (%.2f%%), %zu triangles, Betti (%lld, %lld, "
                    "%lld), %s, remapped %zu",
                    seed.kept.size(), seed.vertex_sample.size(),
                    100.0 * static_cast<double>(seed.vertex_sample.size()) /
                        static_cast<double>(samples.size()),
                    seed.triangles.size(), seed.betti_output[0], seed.betti_output[1],
                    seed.betti_output[2],
                    seed.manifold.is_closed_2_manifold ? "closed 2-manifold" : "NOT a manifold",
                    seed.remapped_samples);
      checksums[l] = line;
      const auto counters = rstruct::complex::orthosphere_predicate_counters();
      std::fprintf(stderr, "run %d level %zu: orthosphere predicates %llu filtered, %llu exact\n",
                   run + 1, l + 1, static_cast<unsigned long long>(counters.filtered),
                   static_cast<unsigned long long>(counters.exact));
      print_stage_counts(run, "level " + std::to_string(l + 1),
                         rstruct::predicates::PredicateId::power_test);
      std::fprintf(stderr, "run %d level %zu: %.3f s cpu; %s\n", run + 1, l + 1,
                   level_times[l].total_cpu.back(), line);
      if (seed.pruned) {
        const auto& st = seed.prune.solver;
        std::fprintf(stderr,
                     "run %d level %zu: cover %.0f, certified bound %.2f, gap %.2f%%; "
                     "%lld components, subgradient %lld, local search %lld iterations, "
                     "%lld exact nodes; stopped by %s\n",
                     run + 1, l + 1, seed.prune.cost, seed.prune.lower_bound,
                     100 * seed.prune.gap, static_cast<long long>(st.components),
                     static_cast<long long>(st.subgradient_iterations),
                     static_cast<long long>(st.local_search_iterations),
                     static_cast<long long>(st.exact_nodes),
                     rstruct::setcover::to_string(st.stopped_by));
        std::fprintf(stderr,
                     "run %d level %zu: set cover of %zu entries %.3f s: reduction %.3f "
                     "(domination work %.1f per entry; %lld rows and %lld columns dominated, %lld "
                     "columns forced), greedy %.3f, subgradient %.3f, local search %.3f, "
                     "certificate %.3f\n",
                     run + 1, l + 1, seed.prune.entries, st.seconds, st.reduction_seconds,
                     static_cast<double>(st.reduction_work) /
                         static_cast<double>(std::max<std::size_t>(seed.prune.entries, 1)),
                     static_cast<long long>(st.dominated_rows),
                     static_cast<long long>(st.dominated_columns),
                     static_cast<long long>(st.forced_columns), st.greedy_seconds,
                     st.subgradient_seconds, st.local_search_seconds, st.certificate_seconds);
      }
      std::fprintf(stderr, "run %d level %zu: output hash %016llx\n", run + 1, l + 1,
                   static_cast<unsigned long long>(output_hash(seed)));
    }
  }
  poles.print("shared: Delaunay + poles + labels + D^");
  for (std::size_t l = 0; l < levels.size(); ++l) {
    char title[128];
    std::snprintf(title, sizeof title, "level %zu (rho %.2f, shrink %.2f): %s", l + 1,
                  levels[l].rho, levels[l].shrink, checksums[l].c_str());
    level_times[l].print(title);
  }
  const rstruct::LargeBlockStats blocks = rstruct::large_block_stats();
  std::printf("large blocks (>= 8 MiB): %llu fresh (%llu freed ranges moved to their front), "
              "%llu served from freed pages, %llu ranges given back; peak memory %.0f MiB\n",
              static_cast<unsigned long long>(blocks.fresh),
              static_cast<unsigned long long>(blocks.moved),
              static_cast<unsigned long long>(blocks.reused),
              static_cast<unsigned long long>(blocks.released),
              static_cast<double>(rstruct::peak_memory_bytes()) / (1 << 20));
  return 0;
}
