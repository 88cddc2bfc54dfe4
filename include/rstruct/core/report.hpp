#pragma once
/// \file
/// Machine-readable run statistics (`--report FILE.json`) and the human-readable stage
/// table on stderr. Every pipeline stage records its seconds through Report::Stage.

#include <filesystem>
#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "rstruct/core/stopwatch.hpp"

namespace rstruct {

class Report {
 public:
  /// RAII timer of one stage: records seconds in stages[] when finished or destroyed.
  class Stage {
   public:
    Stage(Report& report, std::string name);
    Stage(const Stage&) = delete;
    Stage& operator=(const Stage&) = delete;
    ~Stage();
    /// Stops the clock and records the stage; returns its seconds.
    double finish();

   private:
    Report* report_;
    std::string name_;
    Stopwatch clock_;
    bool done_ = false;
  };

  /// Free-form values: inputs, parameters, counts. Nested keys with json_pointer syntax
  /// or plain json objects.
  nlohmann::json& data() { return data_; }
  const nlohmann::json& data() const { return data_; }

  /// Records a finished stage (name, wall seconds, CPU seconds of every thread; negative:
  /// not measured) in order of completion.
  void add_stage(std::string name, double seconds, double cpu_seconds = -1);
  const std::vector<std::pair<std::string, double>>& stages() const { return stages_; }
  /// CPU seconds of stage i of stages() (user + system, all threads), −1 if not measured.
  const std::vector<double>& stage_cpu_seconds() const { return stage_cpu_; }

  /// Adds a warning (also kept in the JSON under "warnings").
  void warn(const std::string& message);
  const std::vector<std::string>& warnings() const { return warnings_; }

  /// The full JSON document: data, stages, warnings, total seconds, peak memory.
  nlohmann::json to_json() const;

  /// Writes to_json() atomically. \throws IoError.
  void write(const std::filesystem::path& path) const;

  /// Prints the stage table ("stage  seconds  cpu seconds") to `out`.
  void print_stages(std::ostream& out) const;

 private:
  nlohmann::json data_ = nlohmann::json::object();
  std::vector<std::pair<std::string, double>> stages_;
  std::vector<double> stage_cpu_;
  std::vector<std::string> warnings_;
  Stopwatch total_;
};

}  // namespace rstruct
