#pragma once
// --stats and --json, as every command that refines reads them: the wall
// time of each phase, and one JSON document on stdout in place of the text
// summary (its schema per command: docs/cli.md, "JSON output").

#include <chrono>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

namespace subdiv::cli {

struct ReportOptionValues {
  bool stats = false;
  bool json = false;
};

/// --stats and --json; `stats_help` says what --stats adds for the command.
void add_report_options(CLI::App& cmd, ReportOptionValues& values, const std::string& stats_help);

/// Wall time per phase of a command, phases ending one after another.
class PhaseClock {
 public:
  PhaseClock() : last_(std::chrono::steady_clock::now()) {}
  /// Ends the running phase and names it (a name given twice adds up).
  void lap(const std::string& name);
  /// "read 0.012 s, refine 0.310 s, write 0.050 s".
  std::string text() const;
  /// {"read": 0.012, "refine": 0.310, ...}, in seconds.
  nlohmann::ordered_json json() const;

 private:
  std::chrono::steady_clock::time_point last_;
  std::vector<std::pair<std::string, double>> seconds_;
};

/// Prints `document` on stdout, indented, with a final newline.
void print_json(const nlohmann::ordered_json& document);

}  // namespace subdiv::cli
