#pragma once
// Library messages name the library's options (RuleOptions fields, library
// functions); the program's user knows them as flags. This turns the one
// into the other where a message suggests a remedy.

#include <string>

namespace subdiv::cli {

/// `message` with each library option it names replaced by the flag that
/// sets it.
std::string in_cli_terms(std::string message);

}  // namespace subdiv::cli
