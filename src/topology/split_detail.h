#pragma once
// The individual splits; split_topology() dispatches to them.

#include "subdiv/topology/split.h"

namespace subdiv::detail {

SplitMap quad_split(const MeshTopology& topology, PolygonMesh& child);
SplitMap triangle_split(const MeshTopology& topology, PolygonMesh& child);
SplitMap dual_split(const MeshTopology& topology, PolygonMesh& child);
SplitMap midedge_split(const MeshTopology& topology, PolygonMesh& child);
SplitMap identity_split(const MeshTopology& topology, PolygonMesh& child);
/// `level`: the parent's level, whose parity says whether the step trisects.
SplitMap sqrt3_split(const MeshTopology& topology, PolygonMesh& child, int level);
SplitMap sqrt2_split(const MeshTopology& topology, PolygonMesh& child);
/// Tags the vertex point of each boundary vertex with one face as an
/// infinitely sharp corner (SplitOptions::boundary).
void sqrt3_keep_one_face_corners(const MeshTopology& parent, const SplitMap& map, Tags& child_tags);

/// Face-varying values linear within each face, for the child's corners.
void quad_split_face_varying(const MeshTopology& topology, const FaceVaryingChannel& in, FaceVaryingChannel& out);
void triangle_split_face_varying(const MeshTopology& topology, const FaceVaryingChannel& in, FaceVaryingChannel& out);
/// Dual split: a corner point's value halfway between its corner's value and
/// its face's centroid value, a boundary point's 3/4 and 1/4 of its edge's
/// end values in the edge's face; `child` holds the split's faces.
void dual_split_face_varying(const MeshTopology& topology, const SplitMap& map, const PolygonMesh& child,
                             const FaceVaryingChannel& in, FaceVaryingChannel& out);
/// Midedge split: a child vertex's value is its edge's midpoint value.
void midedge_split_face_varying(const MeshTopology& topology, const PolygonMesh& child, const FaceVaryingChannel& in,
                                FaceVaryingChannel& out);

/// Sqrt3 and sqrt2 splits: one value per child vertex (sqrt3_split.cpp).
void point_split_face_varying(const MeshTopology& topology, const SplitMap& map, const PolygonMesh& child,
                              const FaceVaryingChannel& in, FaceVaryingChannel& out);

/// `level`: the parent's (0: the control mesh, whose non-manifold corners
/// become corner tags, MeshTopology::is_non_manifold_corner()).
void propagate_tags(const PolygonMesh& parent, const MeshTopology& topology, const SplitMap& map,
                    std::span<const double> child_end_sharpness, int level, PolygonMesh& child);
void require_edges(const MeshTopology& topology, SplitRule rule);

/// The edge keys of the quad or triangle split's child (MeshTopology's keyed
/// constructor): the two halves of each parent edge and each edge inside a
/// parent face are an edge each, as the hierarchy makes them, also where two
/// of them join the same two vertices (the halves of an edge joining a vertex
/// to itself).
/// \throws InvalidInputError for other splits, or when the keys overflow.
std::vector<Index> child_edge_keys(const MeshTopology& parent, SplitRule rule);

}  // namespace subdiv::detail
