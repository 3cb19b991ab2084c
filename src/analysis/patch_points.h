#pragma once
/// \file
/// The control points of the regular patches found by walking the topology,
/// ordered for the bases of analysis/patch_basis.h: Catmull-Clark's 16 (the
/// 3 x 3 faces around a quad whose corners are interior vertices of four
/// quads) and Loop's 12 (the vertices of the triangles touching a triangle
/// whose corners are interior vertices of six triangles).
#include <array>
#include <optional>

#include "subdiv/core/types.h"
#include "subdiv/mesh/topology.h"

namespace subdiv {

/// The bicubic patch of the quad that holds `corner`, with that corner at
/// parameter (0, 0), the next corner of its face at (1, 0) and the previous
/// one at (0, 1).
/// \param topology the mesh's topology.
/// \param corner a corner of a quad.
/// \return grid point (i, j), i and j in -1..2, at index (i + 1) + 4 (j + 1);
///   empty unless the face is a quad and each of its corners is an interior
///   vertex with four faces, all quads, consistently oriented around it.
/// \pre \p corner is in [0, topology.corner_count()) (unchecked).
std::optional<std::array<Index, 16>> bicubic_patch_points(const MeshTopology& topology, Index corner);

/// The box-spline patch of the triangle that holds `corner`, with that
/// corner at lattice point (0, 0), the next corner of its face at (1, 0) and
/// the previous one at (0, 1).
/// \param topology the mesh's topology.
/// \param corner a corner of a triangle.
/// \return the 12 vertices in the order of kBoxSplineLattice; empty unless
///   the face is a triangle and each of its corners is an interior vertex
///   with six faces, all triangles, consistently oriented around it, and the
///   12 vertices are distinct.
/// \pre \p corner is in [0, topology.corner_count()) (unchecked).
std::optional<std::array<Index, 12>> box_spline_patch_points(const MeshTopology& topology, Index corner);

}  // namespace subdiv
