// Quad split (QP, arity 2): corner c of an n-gon f becomes the child quad
// [vertex point, point of the edge leaving c, face point, point of the edge
// entering c], which keeps the parent's orientation. Child face = corner c.

#include <tbb/parallel_for.h>

#include "../core/large_buffers.h"
#include "split_detail.h"

namespace subdiv::detail {

// Face-varying values: the parent's, then one per parent corner for the edge
// leaving it (midpoint within the face), then one per face (centroid). Linear
// within each face, so seams stay where they are.
void quad_split_face_varying(const MeshTopology& topo, const FaceVaryingChannel& in, FaceVaryingChannel& out) {
  const auto k = static_cast<std::size_t>(in.components);
  const auto parent_values = static_cast<Index>(in.value_count());
  const Index corners = topo.corner_count(), faces = topo.face_count();
  out.name = in.name;
  out.components = in.components;
  out.values.assign(in.values.begin(), in.values.end());
  out.values.resize((static_cast<std::size_t>(parent_values) + static_cast<std::size_t>(corners) +
                     static_cast<std::size_t>(faces)) * k, 0.0);
  auto value = [&](Index i) { return out.values.data() + static_cast<std::size_t>(i) * k; };
  for (Index c = 0; c < corners; ++c) {
    const double* a = value(in.indices[static_cast<std::size_t>(c)]);
    const double* b = value(in.indices[static_cast<std::size_t>(topo.corner_next(c))]);
    double* m = value(parent_values + c);
    for (std::size_t j = 0; j < k; ++j) m[j] = 0.5 * (a[j] + b[j]);
  }
  for (Index f = 0; f < faces; ++f) {
    double* m = value(parent_values + corners + f);
    const Index first = topo.face_first_corner(f), n = topo.face_size(f);
    for (Index c = first; c < first + n; ++c) {
      const double* a = value(in.indices[static_cast<std::size_t>(c)]);
      for (std::size_t j = 0; j < k; ++j) m[j] += a[j] / n;
    }
  }
  out.indices.resize(4 * static_cast<std::size_t>(corners));
  for (Index c = 0; c < corners; ++c) {
    Index* q = out.indices.data() + 4 * static_cast<std::size_t>(c);
    q[0] = in.indices[static_cast<std::size_t>(c)];
    q[1] = parent_values + c;
    q[2] = parent_values + corners + topo.corner_face(c);
    q[3] = parent_values + topo.corner_prev(c);
  }
}

SplitMap quad_split(const MeshTopology& topo, PolygonMesh& child) {
  SplitMap map;
  map.rule = SplitRule::quad;
  const Index nf = topo.face_count(), ne = topo.edge_count(), nv = topo.vertex_count(), nc = topo.corner_count();
  map.face_points = 0;
  map.edge_points = nf;
  map.vertex_points = nf + ne;
  map.child_vertex_count = nf + ne + nv;

  detail::assign_large(child.positions, static_cast<std::size_t>(map.child_vertex_count), Vec3{});
  detail::assign_large(child.face_offsets, static_cast<std::size_t>(nc) + 1);
  detail::assign_large(child.face_indices, 4 * static_cast<std::size_t>(nc));
  tbb::parallel_for(tbb::blocked_range<Index>(0, nf, 4096), [&](const tbb::blocked_range<Index>& range) {
    for (Index f = range.begin(); f != range.end(); ++f) {
      const Index first = topo.face_first_corner(f), n = topo.face_size(f);
      for (Index c = first; c < first + n; ++c) {
        Index* q = child.face_indices.data() + 4 * static_cast<std::size_t>(c);
        q[0] = map.vertex_point(topo.corner_vertex(c));
        q[1] = map.edge_point(topo.corner_edge(c));
        q[2] = map.face_point(f);
        q[3] = map.edge_point(topo.corner_edge(topo.corner_prev(c)));
        child.face_offsets[static_cast<std::size_t>(c)] = 4 * c;
      }
    }
  });
  child.face_offsets[static_cast<std::size_t>(nc)] = 4 * nc;

  return map;
}

}  // namespace subdiv::detail
