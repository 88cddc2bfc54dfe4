// `rstruct setcover`: solve an OR-Library set-cover file with a certified lower bound, or
// check a certificate with the independent verifier (issue 6).
//   rstruct setcover FILE [--unicost] [--time-limit S] [--seed N] [-o CERT]
//   rstruct setcover --verify FILE CERT
#include <cstdio>
#include <sstream>

#include "cli/command.hpp"
#include "rstruct/core/atomic_file.hpp"
#include "rstruct/core/error.hpp"
#include "rstruct/setcover/read_instance.hpp"
#include "rstruct/setcover/solver.hpp"
#include "rstruct/setcover/verifier.hpp"

namespace rstruct::cli {

namespace {

class SetCoverCommand : public Command {
 public:
  void configure(CLI::App& app) override {
    app.add_option("files", files_, "Instance file (OR-Library row format, or column format for "
                                    "rail* files); with --verify also the certificate")
        ->required()
        ->expected(1, 2);
    app.add_flag("--verify", verify_, "Check certificate CERT against FILE and print VALID/INVALID");
    app.add_flag("--unicost", unicost_, "Ignore the file's costs: every column costs 1");
    app.add_option("--time-limit", time_limit_, "Seconds for the search (anytime)")
        ->check(CLI::Range(0.0, 1e6));
    app.add_option("--seed", seed_, "Seed of the randomised search");
    app.add_option("-o,--output", output_, "Write the certificate (cover + multipliers) here");
    app.add_option("--format", format_, "Instance layout: auto (rail* = columns), rows, columns")
        ->check(CLI::IsMember({"auto", "rows", "columns"}));
  }

  int run(Context& context) override {
    using namespace rstruct::setcover;
    const std::filesystem::path file = files_.at(0);
    const ScpFormat format = format_ == "rows"      ? ScpFormat::kRows
                             : format_ == "columns" ? ScpFormat::kColumns
                                                    : guess_scp_format(file);
    context.report.data()["input"] = file.string();
    if (verify_) return run_verify(context, file, format);
    if (files_.size() != 1) throw InvalidInput("setcover: give one instance file (or use --verify FILE CERT)");
    Instance inst;
    {
      Report::Stage stage(context.report, "read");
      inst = read_scp_file(file, format);
      if (unicost_) inst = inst.with_unit_costs();
    }
    context.info("setcover: " + inst.summary());
    SolverOptions options;
    options.time_limit = time_limit_;
    options.seed = seed_;
    Solution sol;
    {
      Report::Stage stage(context.report, "solve");
      sol = solve(inst, options);
    }
    auto& d = context.report.data();
    d["rows"] = inst.num_rows();
    d["columns"] = inst.num_cols();
    d["entries"] = inst.num_entries();
    d["unicost"] = inst.is_unicost();
    d["cost"] = sol.cost;
    d["lower_bound"] = sol.lower_bound;
    d["gap"] = sol.gap;
    d["optimal"] = sol.optimal;
    d["proven_optimal"] = sol.proven_optimal;
    d["cover_size"] = sol.columns.size();
    d["seconds_to_best"] = sol.stats.seconds_to_best;
    d["forced_columns"] = sol.stats.forced_columns;
    d["dominated_rows"] = sol.stats.dominated_rows;
    d["dominated_columns"] = sol.stats.dominated_columns;
    d["components"] = sol.stats.components;
    d["subgradient_iterations"] = sol.stats.subgradient_iterations;
    d["local_search_iterations"] = sol.stats.local_search_iterations;
    if (!output_.empty()) {
      AtomicFile out(output_);
      write_certificate(out.stream(), sol.certificate);
      out.commit();
    }
    std::printf("cost %.17g bound %.17g gap %.4f%% columns %zu %s\n", sol.cost, sol.lower_bound,
                100.0 * sol.gap, sol.columns.size(), sol.optimal ? "optimal (certified)" : sol.proven_optimal ? "optimal (proven by search, not by the certificate)" : "feasible");
    return 0;
  }

 private:
  int run_verify(Context& context, const std::filesystem::path& file, setcover::ScpFormat format) {
    using namespace rstruct::setcover;
    if (files_.size() != 2) throw InvalidInput("setcover --verify: expected FILE CERT");
    Verdict v;
    {
      Report::Stage stage(context.report, "verify");
      v = verify_certificate_files(file, files_[1], format == ScpFormat::kRows
                                                        ? VerifierInputFormat::kRows
                                                        : VerifierInputFormat::kColumns);
    }
    auto& d = context.report.data();
    d["valid"] = v.valid;
    d["cost"] = v.cost;
    d["lower_bound"] = v.bound;
    d["gap"] = v.gap;
    d["problems"] = v.problems;
    std::printf("%s\n", v.summary().c_str());
    for (std::size_t k = 1; k < v.problems.size(); ++k) std::printf("  also: %s\n", v.problems[k].c_str());
    return v.valid ? 0 : 1;
  }

  std::vector<std::string> files_;
  bool verify_ = false;
  bool unicost_ = false;
  double time_limit_ = 10.0;
  std::uint64_t seed_ = 1;
  std::string output_;
  std::string format_ = "auto";
};

}  // namespace

RSTRUCT_REGISTER_COMMAND(SetCoverCommand, "setcover",
                         "Near-optimal set cover with a certified lower bound; --verify checks a certificate");

}  // namespace rstruct::cli
