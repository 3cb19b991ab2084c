#pragma once
// The meshes and parameters the evaluation benchmarks share with their
// OpenSubdiv Bfr peer: the same points evaluated by both.

#include <vector>

#include "subdiv/eval/limit_evaluator.h"
#include "subdiv/mesh/polygon_mesh.h"

namespace subdiv::bench {

/// A closed quad mesh with extraordinary vertices: the cube split into
/// 4^levels quads per side (bilinear), jittered; 8 vertices of valence 3.
PolygonMesh refined_cube(int levels);

/// `per_face` pseudo-random parameters in each listed face (quads: the unit
/// square), face after face.
std::vector<SurfaceLocation> points_in_faces(const std::vector<Index>& faces, int per_face);

/// `per_face` pseudo-random parameters in each listed quad within `reach`
/// (in u and in v) of its first corner of valence other than 4: the points
/// nearest an extraordinary vertex, which exact evaluation reaches through
/// the eigenbasis. Faces without such a corner get points near corner 0.
std::vector<SurfaceLocation> points_near_extraordinary_corners(const PolygonMesh& mesh, const std::vector<Index>& faces,
                                                               int per_face, double reach);

/// The faces of `mesh` with an extraordinary corner (valence other than 4).
std::vector<Index> faces_at_extraordinary_vertices(const PolygonMesh& mesh);

/// Every face of `mesh`.
std::vector<Index> all_faces(const PolygonMesh& mesh);

}  // namespace subdiv::bench
