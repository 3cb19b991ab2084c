#include "scheme_option.h"

#include "subdiv/core/error.h"

namespace subdiv::cli {

const Scheme& scheme_named(const std::string& name) {
  if (const Scheme* scheme = find_scheme(name)) return *scheme;
  std::string names;
  for (const Scheme* s : all_schemes()) names += (names.empty() ? "" : ", ") + std::string(s->name);
  throw InvalidInputError("unknown scheme '" + name + "' (known: " + names + ")");
}

}  // namespace subdiv::cli
