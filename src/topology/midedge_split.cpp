// Midedge split (QD, arity sqrt 2; Peters and Reif 1997): every edge becomes
// a child vertex, and the child faces are
//   F-faces: one per parent face, the points of its edges in the face's order;
//   V-faces: one per vertex, the points of its edges in ring order.
// Every child vertex is then shared by four faces (two of each kind), and the
// parent's edges are gone: two steps make a child vertex per parent corner,
// the dual split's topology (Zorin's survey, section 4.2). Manifold meshes
// only. A boundary vertex with k >= 2 faces gets the (k + 1)-gon of its
// edges' points; there is no natural boundary rule (the survey, ibid.): with
// midpoints the boundary polygon shrinks to a point, so the midedge scheme
// refuses open meshes (Scheme::needs_closed_mesh) and only the analysis,
// whose ring mesh has an outer boundary far from what it reads, splits them.
//
// Child vertices are numbered as the parent's edges; child faces [F-faces |
// V-faces in vertex order, of the vertices that have one]. Every face keeps the parent's orientation.

#include "split_detail.h"
#include "subdiv/core/error.h"

namespace subdiv::detail {

SplitMap midedge_split(const MeshTopology& topo, PolygonMesh& child) {
  for (Index v = 0; v < topo.vertex_count(); ++v)
    if (topo.vertex_face_count(v) > 0 && (topo.vertex_kind(v) == VertexKind::non_manifold || !topo.ring_ordered(v)))
      throw TopologyError("the midedge split needs a manifold mesh, but vertex " + std::to_string(v) +
                          " is non-manifold");
  SplitMap map;
  map.rule = SplitRule::midedge;
  map.edge_points = 0;
  map.vertex_points = topo.edge_count();
  map.child_vertex_count = topo.edge_count();

  child.positions.assign(static_cast<std::size_t>(map.child_vertex_count), Vec3{});
  child.face_offsets.assign(1, 0);
  child.face_indices.clear();
  child.face_indices.reserve(2 * static_cast<std::size_t>(topo.corner_count()));
  auto close_face = [&] { child.face_offsets.push_back(static_cast<Index>(child.face_indices.size())); };
  for (Index f = 0; f < topo.face_count(); ++f) {
    const Index first = topo.face_first_corner(f);
    for (Index c = first; c < first + topo.face_size(f); ++c) child.face_indices.push_back(topo.corner_edge(c));
    close_face();
  }
  for (Index v = 0; v < topo.vertex_count(); ++v) {
    const auto edges = topo.vertex_edges(v);
    // Isolated, a 2-gon whose F-faces already share its edge, or a boundary
    // vertex with one face (whose two edge points its F-face joins).
    if (edges.size() < 3) continue;
    child.face_indices.insert(child.face_indices.end(), edges.begin(), edges.end());
    close_face();
  }
  return map;
}

// One value per child vertex: its edge's midpoint within the first face
// that has the edge. Seams are not kept (the V-faces straddle them).
void midedge_split_face_varying(const MeshTopology& topo, const PolygonMesh& child, const FaceVaryingChannel& in,
                                FaceVaryingChannel& out) {
  const auto k = static_cast<std::size_t>(in.components);
  out.name = in.name;
  out.components = in.components;
  out.values.assign(static_cast<std::size_t>(topo.edge_count()) * k, 0.0);
  for (Index e = 0; e < topo.edge_count(); ++e) {
    const Index side = topo.edge_corners(e)[0];
    const double* a = in.values.data() + static_cast<std::size_t>(in.indices[static_cast<std::size_t>(side)]) * k;
    const double* b =
        in.values.data() + static_cast<std::size_t>(in.indices[static_cast<std::size_t>(topo.corner_next(side))]) * k;
    for (std::size_t j = 0; j < k; ++j) out.values[static_cast<std::size_t>(e) * k + j] = 0.5 * (a[j] + b[j]);
  }
  out.indices = child.face_indices;
}

}  // namespace subdiv::detail
