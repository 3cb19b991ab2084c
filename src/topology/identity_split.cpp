// Identity "split": the child has the parent's faces and one vertex per
// parent vertex (its vertex point, same number). A smoothing step of a
// composite scheme (generalized Catmull-Clark's B_{alpha,beta}) moves the
// vertices without changing the mesh.

#include "../core/large_buffers.h"
#include "split_detail.h"

namespace subdiv::detail {

SplitMap identity_split(const MeshTopology& topo, PolygonMesh& child) {
  SplitMap map;
  map.rule = SplitRule::identity;
  map.face_points = map.edge_points = map.vertex_points = 0;
  map.child_vertex_count = topo.vertex_count();
  detail::assign_large(child.positions, static_cast<std::size_t>(map.child_vertex_count), Vec3{});
  const Index nf = topo.face_count();
  detail::assign_large(child.face_offsets, static_cast<std::size_t>(nf) + 1);
  detail::assign_large(child.face_indices, static_cast<std::size_t>(topo.corner_count()));
  for (Index f = 0; f < nf; ++f) {
    const Index first = topo.face_first_corner(f);
    child.face_offsets[static_cast<std::size_t>(f)] = first;
    for (Index c = first; c < first + topo.face_size(f); ++c)
      child.face_indices[static_cast<std::size_t>(c)] = topo.corner_vertex(c);
  }
  child.face_offsets[static_cast<std::size_t>(nf)] = topo.corner_count();
  return map;
}

}  // namespace subdiv::detail
