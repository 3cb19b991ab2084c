#pragma once
// Small helpers for the program's messages.

#include <cstdint>
#include <string>
#include <string_view>

namespace subdiv::cli {

/// "1 vertex", "8 vertices": the count with the noun in the right number.
inline std::string count_of(std::int64_t n, std::string_view one, std::string_view many) {
  return std::to_string(n) + " " + std::string(n == 1 ? one : many);
}

}  // namespace subdiv::cli
