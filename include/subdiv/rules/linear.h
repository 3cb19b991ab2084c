#pragma once
// Linear subdivision: triangle split with edge midpoints, vertices kept. A
// baseline and a test of the topology.

#include "subdiv/rules/scheme.h"

namespace subdiv {

const Scheme& linear_scheme();

}  // namespace subdiv
