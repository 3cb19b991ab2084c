#pragma once
// Bilinear subdivision: quad split with averaging only (face centroid, edge
// midpoint, vertices kept). A baseline and a test of the topology.

#include "subdiv/rules/scheme.h"

namespace subdiv {

const Scheme& bilinear_scheme();

}  // namespace subdiv
