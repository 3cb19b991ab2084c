#pragma once
// What every command that writes a mesh does before and after: refuse an
// output that is the input or has an unknown extension, and report notes.

#include <string>
#include <vector>

namespace subdiv::cli {

/// Throws InvalidInputError if `output` has no known mesh extension or is the
/// same file as `input` (inputs are never modified).
void check_output_path(const std::string& input, const std::string& output);

/// -q: warnings and progress lines are not printed; errors always are.
void set_quiet(bool quiet);
bool quiet();

/// Prints a warning or progress line (printf format, "subdiv: ..." and the
/// newline included by the caller) on stderr, unless quiet.
[[gnu::format(printf, 1, 2)]] void warnf(const char* format, ...);

/// Prints each note as "subdiv: warning: PATH: NOTE" on stderr, unless quiet.
void print_warnings(const std::string& path, const std::vector<std::string>& warnings);

}  // namespace subdiv::cli
