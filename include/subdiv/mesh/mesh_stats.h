#pragma once
/// \file
/// Counts and histograms that describe a mesh at a glance (`subdiv info`).

#include <cstdint>
#include <map>

#include "subdiv/core/types.h"
#include "subdiv/mesh/polygon_mesh.h"
#include "subdiv/mesh/topology.h"

namespace subdiv {

/// What compute_stats() finds: element counts, face-size and valence
/// histograms, defect counts and the bounding box.
struct MeshStats {
  Index vertices = 0;                 ///< all vertices, isolated ones included
  Index faces = 0;                    ///< all faces, holes and degenerate ones included
  Index edges = 0;                    ///< distinct vertex pairs joined by a face side (sides from a vertex to itself are not edges here)
  Index corners = 0;                  ///< face corners over all faces
  std::map<Index, Index> face_sizes;  ///< face size -> number of faces
  std::map<Index, Index> valences;    ///< valence (distinct edges) -> number of used vertices
  Index triangles = 0;                ///< faces with 3 corners
  Index quads = 0;                    ///< faces with 4 corners
  Index polygons = 0;                 ///< faces with 5 or more corners
  Index max_valence = 0;              ///< largest valence of a used vertex; 0 if none
  Index boundary_loops = 0;           ///< components of the boundary-edge graph
  Index boundary_edges = 0;           ///< edges with exactly one face side
  Index non_manifold_edges = 0;       ///< edges with more than two face sides
  Index non_manifold_vertices = 0;    ///< vertices whose faces form several fans
  Index flipped_edges = 0;            ///< edges whose two faces disagree on orientation
  Index isolated_vertices = 0;        ///< vertices used by no face
  Index degenerate_faces = 0;         ///< fewer than 3 corners or a repeated vertex
  Index components = 0;               ///< components of faces joined through shared edges
  std::int64_t euler_characteristic = 0;  ///< V - E + F over used vertices
  Vec3 bbox_min;                      ///< smallest coordinates over all positions; (0, 0, 0) for no vertices
  Vec3 bbox_max;                      ///< largest coordinates over all positions; (0, 0, 0) for no vertices
};

/// Computes a mesh's statistics in one pass over faces, vertices and edges
/// (O(V + E + corners), plus the cost of the histograms). Edges are vertex
/// pairs here: where the topology has coincident edges (faces repeating a
/// vertex), the statistics are taken from one that merges them, and sides
/// joining a vertex to itself count as no edge.
/// \pre \p topology was built from \p mesh (not checked); the mesh's face
///      arrays are therefore well formed.
/// \param mesh the mesh.
/// \param topology its topology.
/// \return the statistics.
/// \throws std::bad_alloc if memory runs out.
MeshStats compute_stats(const PolygonMesh& mesh, const MeshTopology& topology);

}  // namespace subdiv
