#pragma once
// A registered scheme by name, for tests that name the schemes they run.

#include <stdexcept>
#include <string>

#include "subdiv/rules/scheme.h"

namespace subdiv::test {

/// The registered scheme `name`; throws std::runtime_error where there is
/// none (a misspelt name fails the test instead of dereferencing null).
inline const Scheme& scheme(const char* name) {
  const Scheme* s = find_scheme(name);
  if (!s) throw std::runtime_error(std::string("no scheme ") + name);
  return *s;
}

}  // namespace subdiv::test
