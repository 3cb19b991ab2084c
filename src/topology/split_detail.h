#pragma once
// The individual splits; split_topology() dispatches to them.

#include "subdiv/topology/split.h"

namespace subdiv::detail {

/// Sharpness of a tag one level down: infinite stays, otherwise minus one.
double child_sharpness(double s);

SplitMap quad_split(const MeshTopology& topology, PolygonMesh& child);
SplitMap triangle_split(const MeshTopology& topology, PolygonMesh& child);

/// Face-varying values linear within each face, for the child's corners.
void quad_split_face_varying(const MeshTopology& topology, const FaceVaryingChannel& in, FaceVaryingChannel& out);
void triangle_split_face_varying(const MeshTopology& topology, const FaceVaryingChannel& in, FaceVaryingChannel& out);

void propagate_tags(const PolygonMesh& parent, const MeshTopology& topology, const SplitMap& map,
                    std::span<const double> child_end_sharpness, PolygonMesh& child);
void require_edges(const MeshTopology& topology);

}  // namespace subdiv::detail
