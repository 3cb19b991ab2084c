#pragma once
// The canonical mesh around one configuration: k sectors of a regular grid
// (quads for the quad split, triangles for the triangle split) laid out in
// the plane around the centre vertex at the origin. Sector s spans the rays
// at angles a s / k and a (s + 1) / k (a = the configuration's sector
// angle, or a quarter turn per face where a / k would reach pi), and its
// grid point (i, j) sits at i u_s + j u_(s+1), u_s the unit
// vector of ray s. Within a sector the layout is linear, so the split's own
// placement (face centroids, edge midpoints) puts the child of a layout
// point p at p / 2: that is how analysis identifies a neighbourhood with
// its image one level down.

#include "subdiv/analysis/configuration.h"
#include "subdiv/mesh/polygon_mesh.h"
#include "subdiv/topology/split.h"

namespace subdiv {

struct RingMesh {
  PolygonMesh mesh;  ///< positions are the planar layout
  Index centre = 0;
};

/// The configuration's mesh with `rings` rings of faces around the centre.
/// Corners carry an infinitely sharp corner tag of the configuration's type
/// and angle on the centre. Throws InvalidInputError for k < 1 (interior:
/// k < 3), rings < 1, or a split without a grid layout.
RingMesh ring_mesh(SplitRule split, const Configuration& configuration, int rings);

}  // namespace subdiv
