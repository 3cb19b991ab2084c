#include "subdiv/core/error.h"

namespace subdiv {

namespace {
std::string located(const std::string& path, std::uint64_t line, const std::string& what) {
  std::string where = path.empty() ? std::string("<input>") : path;
  if (line > 0) where += ":" + std::to_string(line);
  return where + ": " + what;
}
}  // namespace

ParseError::ParseError(const std::string& path, std::uint64_t line, const std::string& what)
    : IoError(located(path, line, what)), path_(path), line_(line) {}

}  // namespace subdiv
