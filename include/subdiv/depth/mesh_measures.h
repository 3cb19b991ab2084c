#pragma once
// The quantities the depth bounds start from, measured on a control mesh.

#include <vector>

#include "subdiv/core/types.h"
#include "subdiv/mesh/polygon_mesh.h"
#include "subdiv/rules/scheme.h"
#include "subdiv/analysis/limit.h"

namespace subdiv {

/// The largest second difference |P_a - 2 P_v + P_b| over the mesh lines:
/// through every interior vertex with 4 edges and 4 faces, the two pairs of
/// opposite neighbours; through every boundary vertex with 3 edges, its two
/// boundary neighbours. These are Cheng's M (Catmull-Clark) and the paper's
/// M for Doo-Sabin on a grid; vertices of other valences have no lines.
double max_second_difference(const PolygonMesh& mesh);

struct LimitDistances {
  std::vector<double> distances;  ///< |P_v - limit(P_v)| per vertex
  double max = 0.0;
  Index max_vertex = kInvalidIndex;
  Index approximated = 0;  ///< vertices whose limit is only approximated (see LimitResult)
};

/// Every vertex's distance to its limit position under `scheme`
/// (through limit_positions()).
LimitDistances limit_distances(const PolygonMesh& mesh, const Scheme& scheme, const LimitOptions& options = {});

}  // namespace subdiv
