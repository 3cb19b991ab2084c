#include "output_checks.h"

#include <cstdarg>
#include <cstdio>
#include <filesystem>

#include "subdiv/core/error.h"
#include "subdiv/io/mesh_io.h"

namespace subdiv::cli {

void check_output_path(const std::string& input, const std::string& output) {
  format_from_path(output);  // fail on a bad extension before reading
  check_not_an_input(input, output);
}

void check_not_an_input(const std::string& input, const std::string& output) {
  std::error_code ec;
  if (std::filesystem::exists(output, ec) && std::filesystem::equivalent(input, output, ec))
    throw InvalidInputError(output + ": output is the input file; choose another name (inputs are never modified)");
}

void check_ascii_applies(bool ascii, const std::string& output) {
  const FileFormat format = format_from_path(output);
  if (!ascii || format == FileFormat::ply || format == FileFormat::stl) return;
  throw InvalidInputError("--ascii applies to PLY and STL output, not to " + output + " (" + to_string(format) +
                          (format == FileFormat::glb ? " is binary by definition; .gltf is its text form)" : " is text already)"));
}

namespace {
bool quiet_ = false;
std::vector<std::string> pending_;  // warnings of the running command
}  // namespace

void set_quiet(bool quiet) { quiet_ = quiet; }
bool quiet() { return quiet_; }

void warnf(const char* format, ...) {
  if (quiet_) return;
  std::va_list args;
  va_start(args, format);
  char line[2048];
  std::vsnprintf(line, sizeof line, format, args);
  va_end(args);
  pending_.emplace_back(line);
}

void progressf(const char* format, ...) {
  if (quiet_) return;
  std::va_list args;
  va_start(args, format);
  std::vfprintf(stderr, format, args);
  va_end(args);
}

void finish_warnings(bool succeeded) {
  if (succeeded)
    for (const std::string& line : pending_) std::fputs(line.c_str(), stderr);
  pending_.clear();
}

void print_warnings(const std::string& path, const std::vector<std::string>& warnings) {
  for (const auto& w : warnings) warnf("subdiv: warning: %s: %s\n", path.c_str(), w.c_str());
}

}  // namespace subdiv::cli
