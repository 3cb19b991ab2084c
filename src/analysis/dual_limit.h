#pragma once
// Limit positions of a mesh's vertices under a dual-split scheme (Doo-Sabin;
// gcc and midpoint of even degree).
//
// A dual split keeps no vertex: every child vertex is a corner point. A
// vertex v's limit point is defined as the limit of its V-face, the face its
// one-step children form around it (a k-gon, k = faces at v), i.e. the limit
// point of the centre of that face configuration. It is read off the
// analysis (`analyze(scheme, {interior, k})`: the eigenvalue-1 left
// eigenvector over the k-gon and the rings of faces around it that the
// matrix spans, cached per k), applied to the child's neighbourhood of the
// V-face, found by walking the analysis's ring mesh and the child face by
// face in lockstep from the k-gon across edges. Doo-Sabin's mask is zero on
// the ring (a face's children depend on its own vertices only), so its
// limit is the V-face's centroid, and where the ring is not the canonical
// one (a neighbouring non-quad) that face part alone is applied. On a
// regular grid this is the biquadratic B-spline at v's parameter.
//
// Boundary vertices: the limit of the scheme's boundary curve at v
// (boundary_vertex_limit(); Doo-Sabin's is Chaikin's quadratic B-spline of
// the boundary polygon, (a + 6 v + b) / 8 with a, b its boundary
// neighbours); normals are left zero there. Schemes whose boundary follows
// no curve scheme (gcc, midpoint) leave them unresolved. Interior vertices
// with fewer than 3 faces (no V-face), vertices whose neighbourhood does not
// match and isolated vertices keep their position and are counted as
// approximated.

#include "subdiv/analysis/limit.h"
#include "subdiv/mesh/topology.h"

namespace subdiv {

/// `limit_positions()` for `scheme.split == SplitRule::dual` (it dispatches
/// here). One step makes the V-faces; where a V-face's neighbourhood does not
/// match the analysis's (an extraordinary face within the rings its mask
/// reads), up to `isolation_levels` more steps are taken, within
/// `max_resolve_faces`, and its descendant is matched there (it keeps the
/// V-face's index and limit). `route` and `max_resolve_levels` do not apply.
/// Throws as refine() does for meshes it cannot refine, and
/// InvalidInputError for a scheme of another split.
LimitResult dual_limit_positions(const PolygonMesh& mesh, const Scheme& scheme, const LimitOptions& options = {});

/// The child's neighbourhood of face f in the order of the dual ring
/// layout's combinatorics: f's vertices from its first corner in face order,
/// then, for each of them in turn, the vertices of its other faces
/// (counter-clockwise after f, each face from the corner after the shared
/// vertex), those already listed skipped. `regular` tells whether it is the
/// canonical neighbourhood: every vertex of f interior with 4 faces, all
/// quads besides f.
std::vector<Index> face_neighbourhood(const MeshTopology& topology, Index f, bool& regular);

}  // namespace subdiv
