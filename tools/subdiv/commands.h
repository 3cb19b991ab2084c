#pragma once
// The subcommands of the `subdiv` program. Each registers its options on the
// CLI11 app and returns the function that runs it (returning the exit code).

#include <cmath>
#include <functional>
#include <limits>
#include <string>

#include <CLI/CLI.hpp>

namespace subdiv::cli {

/// Exit codes, as documented in docs/cli.md.
inline constexpr int kExitOk = 0;
inline constexpr int kExitBadInput = 1;
inline constexpr int kExitInternal = 2;

using Command = std::function<int()>;

/// A positive finite number; the message names the value given (CLI11's
/// PositiveNumber prints the whole double range).
inline CLI::Validator positive_number() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double value = 0.0;
        if (!CLI::detail::lexical_cast(text, value)) return "not a number: " + text;
        if (!std::isfinite(value)) return "must be a finite number, not " + text;
        if (!(value > 0.0)) return "must be a positive number, not " + text;
        return {};
      },
      "POSITIVE");
}

Command add_info_command(CLI::App& app);
Command add_convert_command(CLI::App& app);
Command add_refine_command(CLI::App& app);
Command add_schemes_command(CLI::App& app);
Command add_limit_command(CLI::App& app);
Command add_analyze_command(CLI::App& app);
Command add_depth_command(CLI::App& app);
Command add_adaptive_command(CLI::App& app);
Command add_render_command(CLI::App& app);
Command add_compare_command(CLI::App& app);
Command add_eval_command(CLI::App& app);
Command add_tessellate_command(CLI::App& app);
Command add_project_command(CLI::App& app);

}  // namespace subdiv::cli
