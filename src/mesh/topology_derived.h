#pragma once
// What the quad- and triangle-split derivations of a child level's topology
// share: a vertex point's ring is its parent vertex's ring, corner by corner
// and edge by edge.

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "subdiv/mesh/topology.h"

namespace subdiv {

// child_corner(c): the child corner at the vertex point of parent corner c;
// half(e, v): the child edge from the point of parent edge e to that of v.
template <typename ChildCorner, typename Half>
void MeshTopology::inherit_vertex_points(const MeshTopology& p, Index vertex_point, ChildCorner child_corner,
                                         Half half) {
  tbb::parallel_for(tbb::blocked_range<Index>(0, p.vertex_count(), 4096), [&](const tbb::blocked_range<Index>& range) {
    for (Index v = range.begin(); v != range.end(); ++v) {
      const Index cv = vertex_point + v;
      vertex_kind_[cv] = p.vertex_kind_[v];
      if (p.vertex_kind_[v] == VertexKind::isolated) {
        ring_ordered_[cv] = 0;
        fan_count_[cv] = 0;
        continue;
      }
      Index* corners = vertex_corners_.data() + vertex_corner_offsets_[cv];
      Index* edges = vertex_edges_.data() + vertex_edge_offsets_[cv];
      for (const Index c : p.vertex_corners(v)) *corners++ = child_corner(c);
      for (const Index e : p.vertex_edges(v)) *edges++ = half(e, v);
    }
  });
}

}  // namespace subdiv
