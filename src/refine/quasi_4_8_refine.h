#pragma once
// The refinement path of schemes whose split reads positions (quasi 4-8):
// refine(), refine_stencils() and refine_stencil_table() hand them here.
// Each level: bisect on the current positions, build the child's topology,
// then smooth (the fast path evaluates the masks in place, pass 1 then
// pass 2; the stencil path composes them into rows over the parent).

#include <vector>

#include "subdiv/mesh/source_lines.h"
#include "subdiv/refine/refine.h"

namespace subdiv::detail {

PolygonMesh refine_quasi_4_8(const PolygonMesh& mesh, const Scheme& scheme, const RefineOptions& options,
                             const SourceLines* lines);

/// The tables are exact for the mesh's own positions; applied to other
/// positions they keep the topology those positions' refinement chose.
std::vector<StencilTable> refine_quasi_4_8_stencils(const PolygonMesh& mesh, const Scheme& scheme,
                                                    const RefineOptions& options, PolygonMesh* final_level);

}  // namespace subdiv::detail
