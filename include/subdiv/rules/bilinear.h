#pragma once
/// \file
/// Bilinear subdivision: quad split with averaging only (face centroid, edge
/// midpoint, vertices kept). A baseline and a test of the topology.

#include "subdiv/rules/scheme.h"

namespace subdiv {

/// The registered "bilinear" scheme: quad split, face centroids, edge
/// midpoints, old vertices kept; any polygon mesh.
/// \return the scheme, a static object valid for the program's lifetime.
const Scheme& bilinear_scheme() noexcept;

}  // namespace subdiv
