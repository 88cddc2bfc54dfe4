#include "rstruct/core/report.hpp"

#include <cstdio>
#include <ostream>

#include "rstruct/core/atomic_file.hpp"

namespace rstruct {

Report::Stage::Stage(Report& report, std::string name)
    : report_(&report), name_(std::move(name)) {}

Report::Stage::~Stage() {
  if (!done_) finish();
}

double Report::Stage::finish() {
  const double s = clock_.seconds();
  if (!done_) report_->add_stage(name_, s);
  done_ = true;
  return s;
}

void Report::add_stage(std::string name, double seconds) {
  stages_.emplace_back(std::move(name), seconds);
}

void Report::warn(const std::string& message) { warnings_.push_back(message); }

nlohmann::json Report::to_json() const {
  nlohmann::json j = data_;
  nlohmann::json stages = nlohmann::json::array();
  for (const auto& [name, seconds] : stages_) {
    stages.push_back({{"stage", name}, {"seconds", seconds}});
  }
  j["stages"] = stages;
  j["warnings"] = warnings_;
  j["total_seconds"] = total_.seconds();
  j["peak_memory_bytes"] = peak_memory_bytes();
  return j;
}

void Report::write(const std::filesystem::path& path) const {
  write_file_atomically(path, to_json().dump(2) + "\n");
}

void Report::print_stages(std::ostream& out) const {
  double sum = 0;
  char line[160];
  for (const auto& [name, seconds] : stages_) {
    std::snprintf(line, sizeof line, "  %-32s %10.3f s\n", name.c_str(), seconds);
    out << line;
    sum += seconds;
  }
  std::snprintf(line, sizeof line, "  %-32s %10.3f s   (peak memory %.1f MiB)\n", "total", sum,
                static_cast<double>(peak_memory_bytes()) / (1024.0 * 1024.0));
  out << line;
}

}  // namespace rstruct
