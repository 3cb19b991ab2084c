#pragma once
// The -s/--scheme option shared by refine, limit and analyze.

#include <string>

#include "subdiv/rules/scheme.h"

namespace subdiv::cli {

/// The registered scheme with this name; throws InvalidInputError naming
/// the known schemes otherwise.
const Scheme& scheme_named(const std::string& name);

}  // namespace subdiv::cli
