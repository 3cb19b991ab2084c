#pragma once
// The normals pictures are shaded with (render, compare --png).

#include <vector>

#include "subdiv/mesh/polygon_mesh.h"
#include "subdiv/refine/refine.h"
#include "subdiv/rules/scheme.h"

namespace subdiv::cli {

/// The scheme's limit normals at the vertices of `surface` (a refined mesh)
/// where the scheme has closed-form limit masks, which are cheap to
/// evaluate; empty otherwise (the picture then takes the faces' normals).
/// `refine` holds the rules the surface was refined with.
std::vector<Vec3> limit_normals_for_picture(const PolygonMesh& surface, const Scheme& scheme,
                                            const RefineOptions& refine);

}  // namespace subdiv::cli
