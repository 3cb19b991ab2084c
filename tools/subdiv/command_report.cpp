#include "command_report.h"

#include <algorithm>
#include <cstdio>

#include <fmt/format.h>

namespace subdiv::cli {

void add_report_options(CLI::App& cmd, ReportOptionValues& values, const std::string& stats_help) {
  cmd.add_flag("--stats", values.stats, stats_help);
  cmd.add_flag("--json", values.json,
               "Print one JSON document instead of the text summary (with the --stats figures; schema in docs/cli.md)");
}

void PhaseClock::lap(const std::string& name) {
  const auto now = std::chrono::steady_clock::now();
  const double seconds = std::chrono::duration<double>(now - last_).count();
  last_ = now;
  auto it = std::find_if(seconds_.begin(), seconds_.end(), [&](const auto& p) { return p.first == name; });
  if (it == seconds_.end()) seconds_.emplace_back(name, seconds);
  else it->second += seconds;
}

std::string PhaseClock::text() const {
  std::string out;
  for (const auto& [name, seconds] : seconds_) out += fmt::format("{}{} {:.3f} s", out.empty() ? "" : ", ", name, seconds);
  return out;
}

nlohmann::ordered_json PhaseClock::json() const {
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (const auto& [name, seconds] : seconds_) out[name] = seconds;
  return out;
}

void print_json(const nlohmann::ordered_json& document) {
  const std::string text = document.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
  std::printf("%s\n", text.c_str());
}

}  // namespace subdiv::cli
