// Set-cover benchmark (issue 6): every OR-Library instance of the data folder, weighted and
// unicost, with cost, certified bound, gap, seconds and time to the best cover, against the
// best-known values. Also synthetic geometric instances (see geometric_instance.hpp).
//
// usage: bench_setcover [--data DIR] [--weighted-limit S] [--unicost-limit S] [--only NAME]
//                       [--skip-orlib] [--geometric] [--geometric-limit S] [--seed N]
//                       [--write DIR]   (geometric instances also written in OR-Library
//                                        row format, unit costs, for other solvers)
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <cmath>
#include <map>
#include <random>
#include <unordered_map>
#include <sstream>
#include <string>
#include <vector>

#include "rstruct/core/stopwatch.hpp"
#include "rstruct/setcover/read_instance.hpp"
#include "rstruct/setcover/solver.hpp"
#include "rstruct/setcover/verifier.hpp"

namespace fs = std::filesystem;
using namespace rstruct::setcover;

namespace {

struct Args {
  std::string data = "/work/shared/data/scp";
  double weighted_limit = 5.0;
  double unicost_limit = 10.0;
  std::string only;
  bool orlib = true;
  bool weighted = true;
  bool unicost = true;
  std::uint64_t seed = 1;
  bool geometric = false;
  double geometric_limit = 2.0;
  std::int32_t samples = 100000;
  std::int64_t ls_iterations = 0;  // 0: time limit only
  double only_rho = 0.0;  // 0: both 0.03 and 0.1
  int only_shape = -1;    // -1: torus and double torus
  std::string write_dir;  // non-empty: also write each geometric instance there
};

// Best-known unicost values from the data README (families 4, 5, 6, A).
const std::map<std::string, int> kUnicostBest = {
    {"scp41", 38}, {"scp42", 37}, {"scp43", 38}, {"scp44", 38}, {"scp45", 38},
    {"scp46", 37}, {"scp47", 38}, {"scp48", 37}, {"scp49", 38}, {"scp410", 38},
    {"scp51", 34}, {"scp52", 34}, {"scp53", 34}, {"scp54", 34}, {"scp55", 34},
    {"scp56", 34}, {"scp57", 34}, {"scp58", 34}, {"scp59", 35}, {"scp510", 34},
    {"scp61", 21}, {"scp62", 20}, {"scp63", 21}, {"scp64", 20}, {"scp65", 21},
    {"scpa1", 38}, {"scpa2", 38}, {"scpa3", 38}, {"scpa4", 37}, {"scpa5", 38}};

std::map<std::string, double> read_best_known(const fs::path& csv) {
  std::map<std::string, double> out;
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string name, file, rows, cols, bks;
    std::getline(s, name, ',');
    std::getline(s, file, ',');
    std::getline(s, rows, ',');
    std::getline(s, cols, ',');
    std::getline(s, bks, ',');
    if (!bks.empty()) out[name] = std::stod(bks);
  }
  return out;
}

void run_orlib(const Args& args) {
  const auto bks = read_best_known(fs::path(args.data) / "best_known.csv");
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(args.data)) {
    if (e.path().extension() == ".txt") files.push_back(e.path());
  }
  std::sort(files.begin(), files.end(), [](const fs::path& a, const fs::path& b) {
    const auto key = [](const fs::path& p) {
      std::string s = p.stem().string();
      // scp41 < scp42 < … < scp410: pad the instance number.
      const std::string fam = s.substr(3, 1), num = s.substr(4);
      return fam + std::string(3 - num.size(), '0') + num;
    };
    return key(a) < key(b);
  });
  std::printf("%-7s %-8s %5s %5s %9s %9s %7s %7s %7s %7s %8s %s\n", "inst", "mode", "rows", "cols",
              "cost", "bound", "gap%", "secs", "t_best", "best", "cost-bk", "cert proven");
  int hits[2] = {0, 0}, total[2] = {0, 0};
  for (const fs::path& f : files) {
    const std::string name = f.stem().string();
    if (!args.only.empty() && name.find(args.only) == std::string::npos) continue;
    const Instance weighted = read_scp_file(f, ScpFormat::kRows);
    for (int mode = 0; mode < 2; ++mode) {
      if ((mode == 0 && !args.weighted) || (mode == 1 && !args.unicost)) continue;
      const Instance inst = mode == 0 ? weighted : weighted.with_unit_costs();
      SolverOptions opt;
      opt.time_limit = mode == 0 ? args.weighted_limit : args.unicost_limit;
      opt.max_local_search_iterations = args.ls_iterations;
      opt.seed = args.seed;
      const Solution sol = solve(inst, opt);
      const fs::path cert = fs::temp_directory_path() / ("bench_setcover_" + name + ".cert");
      { std::ofstream out(cert); write_certificate(out, sol.certificate); }
      const Verdict v = verify_certificate_files(f, cert, VerifierInputFormat::kRows);
      fs::remove(cert);
      double best = 0;
      if (mode == 0 && bks.count(name)) best = bks.at(name);
      if (mode == 1 && kUnicostBest.count(name)) best = kUnicostBest.at(name);
      ++total[mode];
      if (sol.cost <= best) ++hits[mode];
      std::printf("%-7s %-8s %5d %5d %9.0f %9.0f %7.2f %7.2f %7.2f %7.0f %8.0f %s %s\n", name.c_str(),
                  mode == 0 ? "weighted" : "unicost", inst.num_rows(), inst.num_cols(), sol.cost,
                  sol.lower_bound, 100.0 * sol.gap, sol.stats.seconds, sol.stats.seconds_to_best,
                  best, sol.cost - best, v.valid ? "VALID" : "INVALID", sol.proven_optimal ? "yes" : "no");
      std::fflush(stdout);
    }
  }
  std::printf("weighted: %d/%d at best known; unicost: %d/%d at best known\n", hits[0], total[0],
              hits[1], total[1]);
}

// ---- Synthetic geometric instances (until the poles module provides real ones) ----------
// Samples uniformly distributed (by area) on a torus of radii R = 3, a = 1 around the z axis,
// or on the union of two such tori centred at x = ±2.6 (a genus-2 surface). The local scale
// of a sample is the torus's local feature size min(a, distance to the axis of symmetry);
// column j covers row t iff |p_j − p_t| ≤ ρ̃ · scale(p_j) (DESIGN.md §2).

struct Point {
  double x, y, z;
};

constexpr double kMajor = 3.0, kMinor = 1.0, kShift = 2.6;

Point torus_point(std::mt19937_64& rng, double cx) {
  std::uniform_real_distribution<double> angle(0.0, 2.0 * M_PI), unit(0.0, 1.0);
  while (true) {  // rejection sampling for the area element (R + a cos v)
    const double u = angle(rng), v = angle(rng);
    if (unit(rng) * (kMajor + kMinor) > kMajor + kMinor * std::cos(v)) continue;
    const double w = kMajor + kMinor * std::cos(v);
    return {cx + w * std::cos(u), w * std::sin(u), kMinor * std::sin(v)};
  }
}

/// Signed distance-like test: is p strictly inside the solid torus centred at (cx, 0, 0)?
bool inside_torus(const Point& p, double cx) {
  const double rho = std::hypot(p.x - cx, p.y) - kMajor;
  return rho * rho + p.z * p.z < kMinor * kMinor;
}

double local_scale(const Point& p, double cx) {
  return std::min(kMinor, std::hypot(p.x - cx, p.y));
}

Instance geometric_instance(bool double_torus, std::int32_t n, double rho, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<Point> pts;
  std::vector<double> scale;
  while (static_cast<std::int32_t>(pts.size()) < n) {
    const double cx = double_torus ? (rng() % 2 == 0 ? -kShift : kShift) : 0.0;
    const Point p = torus_point(rng, cx);
    if (double_torus && inside_torus(p, -cx)) continue;  // keep the union's boundary only
    pts.push_back(p);
    scale.push_back(local_scale(p, cx));
  }
  const double cell = rho * kMinor;  // the largest radius
  auto key = [&](long long a, long long b, long long c) { return (a * 73856093LL) ^ (b * 19349663LL) ^ (c * 83492791LL); };
  auto coord = [&](double v) { return static_cast<long long>(std::floor(v / cell)); };
  std::unordered_map<long long, std::vector<std::int32_t>> grid;
  for (std::int32_t t = 0; t < n; ++t) grid[key(coord(pts[t].x), coord(pts[t].y), coord(pts[t].z))].push_back(t);
  std::vector<std::int64_t> start{0};
  std::vector<std::int32_t> rows;
  for (std::int32_t j = 0; j < n; ++j) {
    const Point& c = pts[j];
    const double r = rho * scale[j];
    const long long cx = coord(c.x), cy = coord(c.y), cz = coord(c.z);
    for (long long a = cx - 1; a <= cx + 1; ++a)
      for (long long b = cy - 1; b <= cy + 1; ++b)
        for (long long d = cz - 1; d <= cz + 1; ++d) {
          const auto it = grid.find(key(a, b, d));
          if (it == grid.end()) continue;
          for (std::int32_t t : it->second) {
            const double dx = pts[t].x - c.x, dy = pts[t].y - c.y, dz = pts[t].z - c.z;
            if (coord(pts[t].x) == a && coord(pts[t].y) == b && coord(pts[t].z) == d &&
                dx * dx + dy * dy + dz * dz <= r * r) rows.push_back(t);
          }
        }
    start.push_back(static_cast<std::int64_t>(rows.size()));
  }
  return Instance::from_csr(n, start, rows);
}

void run_geometric(const Args& args) {
  std::printf("\n%-12s %5s %7s %7s %9s %7s %8s %8s %6s %7s %7s %7s %s\n", "surface", "rho", "rows",
              "cols", "entries", "build_s", "cost", "bound", "gap%", "secs", "t_best", "forced", "cert");
  for (int shape = 0; shape < 2; ++shape) {
    if (args.only_shape >= 0 && shape != args.only_shape) continue;
    for (double rho : {0.03, 0.1}) {
      if (args.only_rho > 0 && rho != args.only_rho) continue;
      rstruct::Stopwatch build;
      const Instance inst = geometric_instance(shape == 1, args.samples, rho, args.seed);
      const double build_s = build.seconds();
      if (!args.write_dir.empty()) {
        // OR-Library row format (unit costs), for other solvers to reproduce the figures.
        char name[64];
        std::snprintf(name, sizeof name, "/%s_%.2f.txt", shape == 0 ? "torus" : "double_torus", rho);
        std::FILE* f = std::fopen((args.write_dir + name).c_str(), "w");
        if (f == nullptr) {
          std::fprintf(stderr, "cannot write %s%s\n", args.write_dir.c_str(), name);
          std::exit(1);
        }
        std::fprintf(f, "%d %d\n", inst.num_rows(), inst.num_cols());
        for (std::int32_t j = 0; j < inst.num_cols(); ++j) std::fprintf(f, "1%c", j % 12 == 11 ? '\n' : ' ');
        std::fprintf(f, "\n");
        for (std::int32_t i = 0; i < inst.num_rows(); ++i) {
          std::fprintf(f, "%zu\n", inst.row(i).size());
          for (std::int32_t j : inst.row(i)) std::fprintf(f, "%d ", j + 1);
          std::fprintf(f, "\n");
        }
        std::fclose(f);
      }
      SolverOptions opt;
      opt.time_limit = args.geometric_limit;
      opt.seed = args.seed;
      const Solution sol = solve(inst, opt);
      std::vector<std::vector<std::int32_t>> cols(static_cast<std::size_t>(inst.num_cols()));
      for (std::int32_t j = 0; j < inst.num_cols(); ++j) cols[j].assign(inst.column(j).begin(), inst.column(j).end());
      std::istringstream cert(certificate_text(sol.certificate));
      const Verdict v = verify_certificate(inst.num_rows(), cols, {}, cert);
      std::printf("%-12s %5.2f %7d %7d %9lld %7.2f %8.0f %8.0f %6.2f %7.2f %7.2f %7lld %s\n",
                  shape == 0 ? "torus" : "double-torus", rho, inst.num_rows(), inst.num_cols(),
                  static_cast<long long>(inst.num_entries()), build_s, sol.cost, sol.lower_bound,
                  100.0 * sol.gap, sol.stats.seconds, sol.stats.seconds_to_best,
                  static_cast<long long>(sol.stats.forced_columns), v.valid ? "VALID" : "INVALID");
      std::printf("    stages: reduce %.2f greedy %.2f subgradient %.2f (%lld it) local search %.2f "
                  "(%lld it) certificate %.2f; %lld components, %lld dominated rows, %lld dominated cols, "
                  "domination work %.1f per entry\n",
                  sol.stats.reduction_seconds, sol.stats.greedy_seconds, sol.stats.subgradient_seconds,
                  static_cast<long long>(sol.stats.subgradient_iterations), sol.stats.local_search_seconds,
                  static_cast<long long>(sol.stats.local_search_iterations), sol.stats.certificate_seconds,
                  static_cast<long long>(sol.stats.components), static_cast<long long>(sol.stats.dominated_rows),
                  static_cast<long long>(sol.stats.dominated_columns),
                  static_cast<double>(sol.stats.reduction_work) /
                      static_cast<double>(std::max<std::int64_t>(inst.num_entries(), 1)));
      std::fflush(stdout);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  Args args;
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    auto value = [&]() { return k + 1 < argc ? std::string(argv[++k]) : std::string(); };
    if (a == "--data") args.data = value();
    else if (a == "--weighted-limit") args.weighted_limit = std::stod(value());
    else if (a == "--unicost-limit") args.unicost_limit = std::stod(value());
    else if (a == "--only") args.only = value();
    else if (a == "--skip-orlib") args.orlib = false;
    else if (a == "--weighted-only") args.unicost = false;
    else if (a == "--unicost-only") args.weighted = false;
    else if (a == "--seed") args.seed = std::stoull(value());
    else if (a == "--geometric") args.geometric = true;
    else if (a == "--geometric-limit") args.geometric_limit = std::stod(value());
    else if (a == "--samples") args.samples = std::stoi(value());
    else if (a == "--rho") args.only_rho = std::stod(value());
    else if (a == "--ls-iterations") args.ls_iterations = std::stoll(value());
    else if (a == "--shape") args.only_shape = std::stoi(value());
    else if (a == "--write") args.write_dir = value();
    else {
      std::fprintf(stderr, "unknown argument %s\n", a.c_str());
      return 2;
    }
  }
  if (args.orlib) run_orlib(args);
  if (args.geometric) run_geometric(args);
  return 0;
}
