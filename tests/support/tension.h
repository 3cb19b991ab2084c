#pragma once
// Members of the tension families (Butterfly, Kobbelt) for the tests: copies
// of the registered schemes with another tension w.

#include "subdiv/rules/scheme.h"

namespace subdiv::test {

inline Scheme with_tension(const Scheme& scheme, double w) {
  Scheme s = scheme;
  std::get<TensionParameters>(s.parameters).tension = w;
  return s;
}

}  // namespace subdiv::test
