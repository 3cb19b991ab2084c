#pragma once
// Limit positions and normals of a mesh's vertices for any scheme, through
// the masks the analysis reads off the scheme's own rules: the left
// eigenvectors of the local subdivision matrix (eigenvalue 1: the limit
// position; the subdominant pair: two tangents). Masks are computed once
// per configuration and cached.
//
// A vertex's neighbourhood is matched to its configuration's canonical ring
// (centre, then the ring counter-clockwise from the first edge, as the ring
// mesh lays it out), so it must look like that ring: faces of the split's
// kind (quads, triangles) around a smooth interior vertex, a boundary
// vertex, or a corner. The mesh is first refined `isolation_levels` times,
// which makes every face a quad (quad split) and separates extraordinary
// vertices; a vertex's limit is the limit of its vertex point. A vertex on
// an interior crease takes the boundary configuration's mask along the
// crease (the crease and boundary rules are the same curve rules). Vertices
// that match no canonical ring (darts, non-manifold vertices, semi-sharp
// features not yet resolved) keep their refined position and are counted.

#include <vector>

#include "subdiv/core/types.h"
#include "subdiv/mesh/polygon_mesh.h"
#include "subdiv/refine/refine.h"

namespace subdiv {

struct LimitOptions {
  int isolation_levels = 2;
  bool normals = true;
  /// Boundary interpolation and non-manifold handling, as for refine().
  RefineOptions refine;
};

struct LimitResult {
  std::vector<Vec3> positions;  ///< one per input vertex
  std::vector<Vec3> normals;    ///< unit normals (empty unless asked; zero where undefined)
  /// Vertices whose neighbourhood matched no canonical ring: their position
  /// is the refined vertex point, not the limit.
  Index approximated = 0;
};

/// Limit positions (and normals) of every vertex of `mesh` under `scheme`.
/// Throws as refine() does for meshes it cannot refine, and
/// InvalidInputError for a scheme whose masks need more than the one-ring.
LimitResult limit_positions(const PolygonMesh& mesh, const Scheme& scheme, const LimitOptions& options = {});

}  // namespace subdiv
