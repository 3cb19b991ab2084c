#pragma once
// Counts and histograms that describe a mesh at a glance (`subdiv info`).

#include <cstdint>
#include <map>

#include "subdiv/core/types.h"
#include "subdiv/mesh/polygon_mesh.h"
#include "subdiv/mesh/topology.h"

namespace subdiv {

struct MeshStats {
  Index vertices = 0;
  Index faces = 0;
  Index edges = 0;
  Index corners = 0;
  std::map<Index, Index> face_sizes;  ///< face size -> number of faces
  std::map<Index, Index> valences;    ///< valence (distinct edges) -> number of used vertices
  Index triangles = 0;
  Index quads = 0;
  Index polygons = 0;                 ///< faces with 5 or more corners
  Index max_valence = 0;
  Index boundary_loops = 0;           ///< components of the boundary-edge graph
  Index boundary_edges = 0;
  Index non_manifold_edges = 0;
  Index non_manifold_vertices = 0;    ///< vertices whose faces form several fans
  Index flipped_edges = 0;            ///< edges whose two faces disagree on orientation
  Index isolated_vertices = 0;
  Index degenerate_faces = 0;         ///< fewer than 3 corners or a repeated vertex
  Index components = 0;               ///< components of faces joined through shared edges
  std::int64_t euler_characteristic = 0;  ///< V - E + F over used vertices
  Vec3 bbox_min;
  Vec3 bbox_max;
};

MeshStats compute_stats(const PolygonMesh& mesh, const MeshTopology& topology);

}  // namespace subdiv
