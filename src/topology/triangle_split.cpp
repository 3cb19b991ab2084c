// Triangle split (TP, arity 2): triangle (a, b, c) with edge points ab, bc,
// ca becomes [a, ab, ca], [b, bc, ab], [c, ca, bc] and the centre
// [ab, bc, ca], in that order (child faces 4f .. 4f+3), all keeping the
// parent's orientation.

#include <tbb/parallel_for.h>

#include "../core/large_buffers.h"
#include "split_detail.h"
#include "subdiv/core/error.h"

namespace subdiv::detail {

// Face-varying values: the parent's, then one per parent corner for the
// midpoint of the edge leaving it within its face.
void triangle_split_face_varying(const MeshTopology& topo, const FaceVaryingChannel& in, FaceVaryingChannel& out) {
  const auto k = static_cast<std::size_t>(in.components);
  const auto p = static_cast<Index>(in.value_count());
  const Index corners = topo.corner_count();
  out.name = in.name;
  out.components = in.components;
  out.values.assign(in.values.begin(), in.values.end());
  out.values.resize((static_cast<std::size_t>(p) + static_cast<std::size_t>(corners)) * k);
  for (Index c = 0; c < corners; ++c) {
    const std::size_t a = static_cast<std::size_t>(in.indices[static_cast<std::size_t>(c)]) * k;
    const std::size_t b = static_cast<std::size_t>(in.indices[static_cast<std::size_t>(topo.corner_next(c))]) * k;
    const std::size_t m = static_cast<std::size_t>(p + c) * k;
    for (std::size_t j = 0; j < k; ++j) out.values[m + j] = 0.5 * (out.values[a + j] + out.values[b + j]);
  }
  out.indices.resize(4 * static_cast<std::size_t>(corners));
  for (Index f = 0; f < topo.face_count(); ++f) {
    const Index c0 = 3 * f, c1 = c0 + 1, c2 = c0 + 2;
    const Index t[12] = {in.indices[static_cast<std::size_t>(c0)], p + c0, p + c2,
                         in.indices[static_cast<std::size_t>(c1)], p + c1, p + c0,
                         in.indices[static_cast<std::size_t>(c2)], p + c2, p + c1,
                         p + c0, p + c1, p + c2};
    std::copy(t, t + 12, out.indices.begin() + 12 * static_cast<std::ptrdiff_t>(f));
  }
}

SplitMap triangle_split(const MeshTopology& topo, PolygonMesh& child) {
  for (Index f = 0; f < topo.face_count(); ++f)
    if (topo.face_size(f) != 3)
      throw TopologyError("the triangle split needs a triangle mesh, but face " + std::to_string(f) + " has " +
                          std::to_string(topo.face_size(f)) + " vertices (triangulate it first)");
  SplitMap map;
  map.rule = SplitRule::triangle;
  const Index nf = topo.face_count(), ne = topo.edge_count(), nv = topo.vertex_count();
  map.edge_points = 0;
  map.vertex_points = ne;
  map.child_vertex_count = ne + nv;

  detail::assign_large(child.positions, static_cast<std::size_t>(map.child_vertex_count), Vec3{});
  detail::assign_large(child.face_offsets, 4 * static_cast<std::size_t>(nf) + 1);
  detail::assign_large(child.face_indices, 12 * static_cast<std::size_t>(nf));
  tbb::parallel_for(tbb::blocked_range<Index>(0, nf, 4096), [&](const tbb::blocked_range<Index>& range) {
    for (Index f = range.begin(); f != range.end(); ++f) {
      const Index c0 = topo.face_first_corner(f);  // faces are triangles: corners 3f .. 3f+2
      const Index a = map.vertex_point(topo.corner_vertex(c0));
      const Index b = map.vertex_point(topo.corner_vertex(c0 + 1));
      const Index c = map.vertex_point(topo.corner_vertex(c0 + 2));
      const Index ab = map.edge_point(topo.corner_edge(c0));
      const Index bc = map.edge_point(topo.corner_edge(c0 + 1));
      const Index ca = map.edge_point(topo.corner_edge(c0 + 2));
      const Index t[12] = {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca};
      std::copy(t, t + 12, child.face_indices.begin() + 12 * static_cast<std::ptrdiff_t>(f));
      for (Index i = 0; i < 4; ++i) {
        child.face_offsets[static_cast<std::size_t>(4 * f + i)] = 3 * (4 * f + i);
      }
    }
  });
  child.face_offsets[4 * static_cast<std::size_t>(nf)] = 12 * nf;

  return map;
}

}  // namespace subdiv::detail
