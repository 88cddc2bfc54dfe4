#pragma once
// The `rstruct` command's subcommand registry. Each subcommand lives in its own
// src/cli/cmd_<name>.cpp, which defines a Command subclass and registers it with
// RSTRUCT_REGISTER_COMMAND; main.cpp knows none of them by name. Commands throw
// rstruct's typed exceptions; main.cpp maps them to messages and exit codes.

#include <CLI/CLI.hpp>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "rstruct/core/report.hpp"
#include "rstruct/geometry/triangle_mesh.hpp"

namespace rstruct::cli {

/// Options shared by every subcommand, and the run's report.
struct Context {
  bool quiet = false;
  std::string report_path;  // empty: no JSON report
  Report report;

  /// Prints a line to stderr unless --quiet.
  void info(const std::string& line) const;
  /// Prints a warning to stderr (even with --quiet) and records it in the report.
  void warn(const std::string& line);
};

class Command {
 public:
  virtual ~Command() = default;
  /// Declares the subcommand's options on `app`.
  virtual void configure(CLI::App& app) = 0;
  /// Runs after parsing. Returns the exit code (0 success, 1 computation failed).
  virtual int run(Context& context) = 0;
};

struct CommandInfo {
  std::string name;
  std::string description;
  std::function<std::unique_ptr<Command>()> make;
};

std::vector<CommandInfo>& command_registry();

struct CommandRegistrar {
  CommandRegistrar(std::string name, std::string description,
                   std::function<std::unique_ptr<Command>()> make) {
    command_registry().push_back({std::move(name), std::move(description), std::move(make)});
  }
};

/// Parses "x,y,z" into three doubles. \throws InvalidInput.
std::array<double, 3> parse_triple(const std::string& text, const std::string& option);

/// Requires a finite number within [lo, hi]. \throws InvalidInput naming the option.
double require_range(double value, double lo, double hi, const std::string& option);

/// The weights of a point set read as a mesh: its PLY vertex property `weight`, or
/// `radius` (radius r gives weight r²), or an XYZ file's 4th column read as `weight`.
/// \throws InvalidInput naming `input` if there is neither, or a radius is negative or NaN
/// (`option` names what asked for the weights).
std::vector<double> weights_from_properties(const TriangleMesh& mesh, const std::string& input,
                                            const std::string& option);

/// Upper end of --cover-iterations (a day's work and more on any machine).
inline constexpr double kMaxCoverIterations = 1e12;

}  // namespace rstruct::cli

#define RSTRUCT_CONCAT_INNER(a, b) a##b
#define RSTRUCT_CONCAT(a, b) RSTRUCT_CONCAT_INNER(a, b)
#define RSTRUCT_REGISTER_COMMAND(Type, name, description)                                 \
  static const ::rstruct::cli::CommandRegistrar RSTRUCT_CONCAT(rstruct_registrar_, __LINE__)( \
      name, description, [] { return std::unique_ptr<::rstruct::cli::Command>(new Type()); })
