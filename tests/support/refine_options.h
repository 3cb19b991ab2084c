#pragma once
// RefineOptions for the tests that only choose the number of levels.

#include "subdiv/refine/refine.h"

namespace subdiv::test {

inline RefineOptions levels(int n) {
  RefineOptions options;
  options.levels = n;
  return options;
}

}  // namespace subdiv::test
