#pragma once
/// \file
/// The control points of the regular patches found by walking the topology,
/// ordered for the bases of analysis/patch_basis.h: Catmull-Clark's 16 (the
/// 3 x 3 faces around a quad whose corners are interior vertices of four
/// quads) and Loop's 12 (the vertices of the triangles touching a triangle
/// whose corners are interior vertices of six triangles); and, next to
/// boundaries and infinitely sharp creases, the same patches with the
/// points beyond the sharp edges reflected from those inside (PatchStencil).
#include <array>
#include <optional>
#include <vector>

#include "subdiv/core/types.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/refine/creasing.h"

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

/// A control point of a patch as a combination of mesh vertices: a vertex
/// itself (one term of weight 1), or a phantom point reflected across a
/// sharp edge (2 p - q, or 4 p - 2 q - 2 r + s beyond a corner).
struct PatchStencil {
  std::array<Index, 4> vertex{};   ///< the vertices, `size` of them
  std::array<double, 4> weight{};  ///< their weights (sum 1)
  int size = 0;                    ///< 1 to 4
};

/// The bicubic patch of the quad that holds `corner` where its sharp edges
/// (boundaries, infinitely sharp creases) run along its sides, as
/// OpenSubdiv's regular boundary patches: beyond a sharp side the grid's
/// row is the reflection 2 p - q of the rows inside, which reproduces
/// Catmull-Clark's crease and boundary rule (1/8, 3/4, 1/8) and, where two
/// sharp sides meet at a corner vertex, its corner rule. Each corner must
/// be one of: smooth (an interior vertex of four quads, no sharp edge); a
/// crease or boundary vertex (crease rule, exactly two sharp edges: the
/// face's side and its continuation; four quads, or two on a boundary);
/// a corner (corner rule) where both of the face's sides at it are sharp.
/// Semi-sharp edges at a corner (0 < sharpness < infinite) are refused:
/// their rules are not the B-spline's until they decay.
/// \param topology the level's topology.
/// \param creasing the level's creasing (compute_creasing).
/// \param corner a corner of a quad, at parameter (0, 0) as in
///   bicubic_patch_points.
/// \return the 16 points in bicubic_patch_points' order; empty where the
///   face is no such patch (including where the real points reach a vertex
///   twice). Without sharp edges, equal to bicubic_patch_points.
/// \pre \p corner is in [0, topology.corner_count()) (unchecked).
std::optional<std::array<PatchStencil, 16>> bicubic_patch_stencils(const MeshTopology& topology,
                                                                  const LevelCreasing& creasing, Index corner);

/// Whether the vertex at `corner` is one of bicubic_patch_stencils' corner
/// kinds for the quad holding `corner`.
/// \param topology the level's topology.
/// \param creasing the level's creasing.
/// \param corner a corner of a quad.
/// \return whether it is.
/// \pre \p corner is in [0, topology.corner_count()) (unchecked).
bool is_regular_patch_corner(const MeshTopology& topology, const LevelCreasing& creasing, Index corner);

/// The sector between sharp edges (edges of positive sharpness, or boundary
/// edges) around `corner`'s vertex that holds `corner`'s face.
/// \param topology the level's topology.
/// \param creasing the level's creasing.
/// \param corner a corner of the face.
/// \return the corners at the vertex of the sector's faces, counter-clockwise
///   from the first (whose edge leaving the vertex is sharp) to the last
///   (whose edge entering it is); empty where no sharp edge bounds the faces
///   around the vertex (a closed fan is no sector).
/// \pre \p corner is in [0, topology.corner_count()) (unchecked).
std::optional<std::vector<Index>> sector_corners(const MeshTopology& topology, const LevelCreasing& creasing,
                                                 Index corner);

/// Whether the vertex at `corner` is one of box_spline_patch_stencils'
/// corner kinds for the triangle holding `corner`.
/// \param topology the level's topology.
/// \param creasing the level's creasing.
/// \param corner a corner of a triangle.
/// \return whether it is.
/// \pre \p corner is in [0, topology.corner_count()) (unchecked).
bool is_regular_box_spline_corner(const MeshTopology& topology, const LevelCreasing& creasing, Index corner);

/// The box-spline patch of the triangle that holds `corner` next to a
/// sharp edge (a boundary, an infinitely sharp crease): beyond the crease
/// line each lattice point x is the parallelogram reflection p(m1) + p(m2)
/// - p(R x) of its mirror image across the line (m1, m2 the two points of
/// the line beside it), which reproduces Loop's crease rule (1/8, 3/4,
/// 1/8) and its edge midpoints there. Each corner must be a smooth interior
/// vertex of six triangles, or a vertex with the crease rule whose sector
/// holding the face has three triangles (a straight crease, or a boundary
/// vertex of three faces), the face anywhere in it; the crease corners on
/// one crease line. Corners (the corner rule) are no such patch.
/// \param topology the level's topology.
/// \param creasing the level's creasing.
/// \param corner a corner of a triangle, at lattice point (0, 0).
/// \return the 12 points in the order of kBoxSplineLattice; empty where the
///   face is no such patch. Without sharp edges, box_spline_patch_points.
/// \pre \p corner is in [0, topology.corner_count()) (unchecked).
std::optional<std::array<PatchStencil, 12>> box_spline_patch_stencils(const MeshTopology& topology,
                                                                     const LevelCreasing& creasing, Index corner);

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
