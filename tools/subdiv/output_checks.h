#pragma once
// What every command that writes a mesh does before and after: refuse an
// output that is the input or has an unknown extension, and report notes.

#include <string>
#include <vector>

namespace subdiv::cli {

/// Throws InvalidInputError if `output` has no known mesh extension or is the
/// same file as `input` (inputs are never modified).
void check_output_path(const std::string& input, const std::string& output);

/// Throws InvalidInputError where `output` is the file `input` (a text
/// output of any name).
void check_not_an_input(const std::string& input, const std::string& output);

/// Throws InvalidInputError when --ascii is given for an output that is not
/// PLY or STL (the formats with both encodings; glTF's are two extensions).
void check_ascii_applies(bool ascii, const std::string& output);

/// -q: warnings and progress lines are not printed; errors always are.
void set_quiet(bool quiet);
bool quiet();

/// Keeps a warning line (printf format, "subdiv: warning: ..." and the
/// newline included by the caller) for finish_warnings(), unless quiet.
[[gnu::format(printf, 1, 2)]] void warnf(const char* format, ...);

/// Prints a progress line on stderr at once, unless quiet.
[[gnu::format(printf, 1, 2)]] void progressf(const char* format, ...);

/// Prints the kept warnings when the command succeeded; drops them when it
/// failed, so that a failure stays one line on stderr.
void finish_warnings(bool succeeded);

/// Keeps each note as the warning "subdiv: warning: PATH: NOTE" (warnf).
void print_warnings(const std::string& path, const std::vector<std::string>& warnings);

}  // namespace subdiv::cli
