// Sqrt2 split (QP, arity sqrt 2; the survey, section 3.1): every face gets a
// face point, and every interior edge (a, b) between faces F and G becomes
// the quad (a, point(G), b, point(F)) (for the side of F that runs a -> b):
// the old edges are dropped, and after one step every face is a quad whatever
// the parent's faces were. Two steps on a quad mesh are the quad split turned
// back into the parent's orientation: the second step's face points lie on
// the old edges, so the layout repeats at half the size. This is the 4-8
// refinement of Velho and Zorin read on quads (the survey's Figure 10).
//
// There is no natural boundary rule at non-integer arity (the survey, section
// 4.2): a boundary edge (a, b) of F becomes the triangle (a, b, point(F)),
// which the analysis' ring meshes need at their outer boundary; schemes on
// this split refuse open meshes (Scheme::needs_closed_mesh).
//
// Child vertices are numbered [face points (= parent face) | vertex points];
// child faces by edge, one per edge. Every face keeps the parent's orientation.

#include <tbb/parallel_for.h>

#include "../core/large_buffers.h"
#include "split_detail.h"
#include "subdiv/core/error.h"

namespace subdiv::detail {

SplitMap sqrt2_split(const MeshTopology& topo, PolygonMesh& child) {
  const Index nf = topo.face_count(), ne = topo.edge_count(), nv = topo.vertex_count();
  for (Index e = 0; e < ne; ++e)
    if (topo.edge_corners(e).size() > 2)
      throw TopologyError("the sqrt2 split needs a manifold mesh, but edge " + std::to_string(e) + " has " +
                          std::to_string(topo.edge_corners(e).size()) + " faces");
  SplitMap map;
  map.rule = SplitRule::sqrt2;
  map.face_points = 0;
  map.edge_points = nf;  // no edge points
  map.vertex_points = nf;
  map.child_vertex_count = nf + nv;

  std::vector<Index> first_index(static_cast<std::size_t>(ne) + 1, 0);
  for (Index e = 0; e < ne; ++e)
    first_index[static_cast<std::size_t>(e) + 1] = first_index[static_cast<std::size_t>(e)] + (topo.is_boundary_edge(e) ? 3 : 4);
  detail::assign_large(child.positions, static_cast<std::size_t>(map.child_vertex_count), Vec3{});
  detail::assign_large(child.face_offsets, static_cast<std::size_t>(ne) + 1);
  detail::assign_large(child.face_indices, static_cast<std::size_t>(first_index.back()));
  tbb::parallel_for(tbb::blocked_range<Index>(0, ne, 4096), [&](const tbb::blocked_range<Index>& range) {
    for (Index e = range.begin(); e != range.end(); ++e) {
      const auto sides = topo.edge_corners(e);
      const Index cf = sides[0];  // runs a -> b in its face
      const Index a = map.vertex_point(topo.corner_vertex(cf)), b = map.vertex_point(topo.corner_vertex(topo.corner_next(cf)));
      const Index pf = map.face_point(topo.corner_face(cf));
      const Index at = first_index[static_cast<std::size_t>(e)];
      Index* q = child.face_indices.data() + at;
      if (sides.size() == 1) {
        q[0] = a, q[1] = b, q[2] = pf;
      } else {
        q[0] = a, q[1] = map.face_point(topo.corner_face(sides[1])), q[2] = b, q[3] = pf;
      }
      child.face_offsets[static_cast<std::size_t>(e)] = at;
    }
  });
  child.face_offsets[static_cast<std::size_t>(ne)] = first_index.back();
  return map;
}

}  // namespace subdiv::detail
