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
  if (!done_) report_->add_stage(name_, s, clock_.cpu_seconds());
  done_ = true;
  return s;
}

void Report::add_stage(std::string name, double seconds, double cpu_seconds) {
  stages_.emplace_back(std::move(name), seconds);
  stage_cpu_.push_back(cpu_seconds);
}

void Report::warn(const std::string& message) { warnings_.push_back(message); }

nlohmann::json Report::to_json() const {
  nlohmann::json j = data_;
  nlohmann::json stages = nlohmann::json::array();
  for (std::size_t i = 0; i < stages_.size(); ++i) {
    nlohmann::json stage = {{"stage", stages_[i].first}, {"seconds", stages_[i].second}};
    if (stage_cpu_[i] >= 0) stage["cpu_seconds"] = stage_cpu_[i];
    stages.push_back(std::move(stage));
  }
  j["stages"] = stages;
  j["warnings"] = warnings_;
  j["total_seconds"] = total_.seconds();
  j["total_cpu_seconds"] = total_.cpu_seconds();
  j["peak_memory_bytes"] = peak_memory_bytes();
  return j;
}

void Report::write(const std::filesystem::path& path) const {
  write_file_atomically(path, to_json().dump(2) + "\n");
}

void Report::print_stages(std::ostream& out) const {
  double sum = 0;
  double cpu_sum = 0;
  char line[160];
  for (std::size_t i = 0; i < stages_.size(); ++i) {
    const double cpu = stage_cpu_[i];
    if (cpu >= 0) {
      std::snprintf(line, sizeof line, "  %-32s %10.3f s %9.3f s cpu\n",
                    stages_[i].first.c_str(), stages_[i].second, cpu);
      cpu_sum += cpu;
    } else {
      std::snprintf(line, sizeof line, "  %-32s %10.3f s\n", stages_[i].first.c_str(),
                    stages_[i].second);
    }
    out << line;
    sum += stages_[i].second;
  }
  std::snprintf(line, sizeof line, "  %-32s %10.3f s %9.3f s cpu   (peak memory %.1f MiB)\n",
                "total", sum, cpu_sum,
                static_cast<double>(peak_memory_bytes()) / (1024.0 * 1024.0));
  out << line;
}

}  // namespace rstruct
