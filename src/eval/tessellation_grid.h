#pragma once
// The tessellation's faces and the ptex location of each of its points,
// before evaluation: tessellate() evaluates them, closest_points() samples
// the surface with them.

#include <vector>

#include "subdiv/eval/limit_evaluator.h"
#include "subdiv/mesh/polygon_mesh.h"

namespace subdiv::detail {

struct TessellationGrid {
  PolygonMesh faces;                       ///< faces only: no positions yet
  std::vector<SurfaceLocation> locations;  ///< one per point of the result
};

/// As tessellate() (its checks and its numbering), without evaluating.
TessellationGrid tessellation_grid(const PolygonMesh& mesh, const LimitEvaluator& evaluator, int rate);

}  // namespace subdiv::detail
