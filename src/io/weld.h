#pragma once
// Welding: the vertices of formats that store positions per corner or split
// them at attribute seams (STL, glTF) merged into shared vertices.

#include <vector>

#include "subdiv/core/types.h"

namespace subdiv::detail {

/// For each point in order, the index of the vertex it becomes: the earliest
/// kept point within `tolerance` of it in every coordinate, or a new vertex
/// (the point itself). Kept points are appended to `vertices`. A tolerance
/// of 0 merges equal points only (+0 and -0 alike); a negative one merges
/// nothing. Points must be finite.
std::vector<Index> weld(const std::vector<Vec3>& points, double tolerance, std::vector<Vec3>& vertices);

}  // namespace subdiv::detail
