// Entry point of the `rstruct` command: global options, subcommand dispatch, and the one
// place where exceptions become messages and exit codes:
//   0 success; 1 the computation failed (or an internal error); 2 bad usage or bad input.

#include <cmath>
#include <cstdio>
#include <iostream>
#include <new>
#include <sstream>

#include "cli/command.hpp"
#include "rstruct/core/error.hpp"
#include "rstruct/core/progress.hpp"

namespace rstruct::cli {

std::vector<CommandInfo>& command_registry() {
  static std::vector<CommandInfo> registry;
  return registry;
}

void Context::info(const std::string& line) const {
  if (!quiet) std::cerr << line << '\n';
}

void Context::warn(const std::string& line) {
  std::cerr << "warning: " << line << '\n';
  report.warn(line);
}

std::array<double, 3> parse_triple(const std::string& text, const std::string& option) {
  std::array<double, 3> v{};
  std::istringstream in(text);
  char comma = 0;
  if (!(in >> v[0] >> comma) || comma != ',' || !(in >> v[1] >> comma) || comma != ',' ||
      !(in >> v[2]) || !(in >> std::ws).eof()) {
    throw InvalidInput(option + ": expected three numbers X,Y,Z, got '" + text + "'");
  }
  for (double x : v) {
    if (!std::isfinite(x)) throw InvalidInput(option + ": values must be finite");
  }
  return v;
}

double require_range(double value, double lo, double hi, const std::string& option) {
  if (!std::isfinite(value) || value < lo || value > hi) {
    std::ostringstream msg;
    msg << option << " must be a finite number in [" << lo << ", " << hi << "], got " << value;
    throw InvalidInput(msg.str());
  }
  return value;
}

std::vector<double> weights_from_properties(const TriangleMesh& mesh, const std::string& input,
                                            const std::string& option) {
  if (const std::vector<double>* w = mesh.property("weight")) return *w;
  if (const std::vector<double>* r = mesh.property("radius")) {
    std::vector<double> w(r->size());
    for (std::size_t i = 0; i < r->size(); ++i) {
      if (!((*r)[i] >= 0)) {
        throw InvalidInput(input + ": vertex " + std::to_string(i) +
                           " has a negative or NaN radius");
      }
      w[i] = (*r)[i] * (*r)[i];
    }
    return w;
  }
  throw InvalidInput(input + ": " + option + " needs a `weight` or `radius` vertex property "
                     "(PLY) or a 4th column (XYZ)");
}

}  // namespace rstruct::cli

int main(int argc, char** argv) {
  using namespace rstruct;
  using namespace rstruct::cli;

  CLI::App app{"rstruct: recovering structure from r-sampled objects.\n"
               "Seed polytopes, scalable reconstructions and stable medial axes from point "
               "samples of closed surfaces, with exact geometric predicates."};
  app.set_version_flag("--version", std::string("rstruct ") + RSTRUCT_VERSION);
  app.require_subcommand(1);
  Context context;
  app.add_flag("-q,--quiet", context.quiet, "No progress or informational output on stderr");
  app.add_option("--report", context.report_path,
                 "Write machine-readable statistics (inputs, parameters, counts, per-stage "
                 "seconds, peak memory) to this JSON file");

  std::vector<std::pair<CLI::App*, std::unique_ptr<Command>>> commands;
  for (const CommandInfo& info : command_registry()) {
    CLI::App* sub = app.add_subcommand(info.name, info.description);
    auto command = info.make();
    command->configure(*sub);
    // Global options may also follow the subcommand.
    sub->add_flag("-q,--quiet", context.quiet, "No progress or informational output");
    sub->add_option("--report", context.report_path, "Write a JSON report to this file");
    commands.emplace_back(sub, std::move(command));
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  Progress::set_enabled(!context.quiet);

  try {
    for (auto& [sub, command] : commands) {
      if (sub->parsed()) {
        context.report.data()["command"] = sub->get_name();
        const int code = command->run(context);
        if (!context.report_path.empty()) context.report.write(context.report_path);
        return code;
      }
    }
  } catch (const InvalidInput& e) {
    std::cerr << "rstruct: error: " << e.what() << '\n';
    return 2;
  } catch (const IoError& e) {
    std::cerr << "rstruct: error: " << e.what() << '\n';
    return 2;
  } catch (const ComputationFailed& e) {
    std::cerr << "rstruct: failed: " << e.what() << '\n';
    return 1;
  } catch (const InternalError& e) {
    std::cerr << "rstruct: " << e.what() << " (please report this as a bug)\n";
    return 1;
  } catch (const std::bad_alloc&) {
    std::cerr << "rstruct: failed: out of memory\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "rstruct: failed: " << e.what() << '\n';
    return 1;
  }
  return 2;
}
