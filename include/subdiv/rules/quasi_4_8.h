#pragma once
/// \file
/// Quasi 4-8 subdivision (L.\ Velho): the bisection split of
/// subdiv/topology/bisection_split.h, then the smoothing of Algorithm 2 in
/// two passes, every weight in quasi_4_8.cpp. One refinement step is one
/// binary step; two make a 4-8 step.
///
/// One level is a composite of three steps in the engine (Scheme::steps):
/// the bisection, which places each split point at its edge's midpoint and
/// keeps the old vertices; pass 1, an identity step of the bisected level
/// whose masks move the split points (weights over old vertices); pass 2,
/// an identity step whose masks move the old vertices (weights on themselves
/// and on the split points after pass 1). The passes read which vertices the
/// bisection made from LevelView::level_split and which vertices stay put
/// from LevelView::held. Composed, they are the stencils of the paper's
/// Figure 4 (tests/rules/quasi_4_8_test.cpp).

#include <span>
#include <vector>

#include "subdiv/rules/scheme.h"

namespace subdiv {

/// The boundary treatment's name.
/// \param boundary the treatment.
/// \return "fixed" or "smoothed", a static string.
const char* to_string(Quasi48Boundary boundary) noexcept;

/// The registered "quasi-4-8" scheme (Velho 2001): the bisection split,
/// then two smoothing passes (Scheme::steps); triangle meshes, period 2.
/// \return the scheme, a static object valid for the program's lifetime.
const Scheme& quasi_4_8_scheme() noexcept;

/// The child vertices smoothing leaves in place: corner-tagged vertices,
/// the ends of crease-tagged edges (any sharpness > 0: the paper's tags are
/// on or off), and under Quasi48Boundary::fixed every boundary vertex.
/// Tags naming vertices outside the mesh are ignored.
/// \param child the bisected level (its tags are read).
/// \param child_topology the topology of \p child.
/// \param boundary the boundary treatment.
/// \return one entry per vertex of \p child, 1 where it is held, else 0.
/// \pre \p child_topology was built from \p child (its vertex count is at
///   most that of \p child).
/// \throws std::bad_alloc if memory runs out.
std::vector<char> quasi_4_8_fixed_vertices(const PolygonMesh& child, const MeshTopology& child_topology,
                                           Quasi48Boundary boundary);

}  // namespace subdiv
