#include "cli_terms.h"

#include <string_view>
#include <utility>

namespace subdiv::cli {

std::string in_cli_terms(std::string message) {
  static constexpr std::pair<std::string_view, std::string_view> kFlags[] = {
      {"RuleOptions::allow_non_manifold", "--allow-non-manifold"},
      {"triangulate()", "--triangulate"},
  };
  for (const auto& [library, flag] : kFlags)
    for (std::size_t at = message.find(library); at != std::string::npos; at = message.find(library, at + flag.size()))
      message.replace(at, library.size(), flag);
  return message;
}

}  // namespace subdiv::cli
