#pragma once
/// \file
/// Linear subdivision: triangle split with edge midpoints, vertices kept. A
/// baseline and a test of the topology.

#include "subdiv/rules/scheme.h"

namespace subdiv {

/// The registered "linear" scheme: triangle split, edge midpoints, old
/// vertices kept; triangle meshes.
/// \return the scheme, a static object valid for the program's lifetime.
const Scheme& linear_scheme() noexcept;

}  // namespace subdiv
