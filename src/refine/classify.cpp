// Sharp edges and vertex rules of a level, the same for every scheme. The
// counting of sharp edges follows the survey (section 3.2: crease vertices
// have two sharp edges, corners more, darts one) and OpenSubdiv's treatment
// of infinitely sharp features, boundaries and non-manifold elements.

#include "subdiv/refine/refine.h"

namespace subdiv {

LevelClassification classify_level(const PolygonMesh& mesh, const MeshTopology& topo, BoundaryInterpolation boundary) {
  LevelClassification out;
  out.edge_sharp.assign(static_cast<std::size_t>(topo.edge_count()), 0);
  for (Index e = 0; e < topo.edge_count(); ++e)
    if (topo.edge_face_count(e) != 2 || topo.is_flipped_edge(e)) out.edge_sharp[static_cast<std::size_t>(e)] = 1;
  for (const CreaseTag& c : mesh.tags.creases)
    if (c.sharpness >= kInfiniteSharpness) {
      const Index e = topo.find_edge(c.v0, c.v1);
      if (e != kInvalidIndex) out.edge_sharp[static_cast<std::size_t>(e)] = 1;
    }

  out.vertex_rule.assign(static_cast<std::size_t>(topo.vertex_count()), VertexRule::smooth);
  for (Index v = 0; v < topo.vertex_count(); ++v) {
    int sharp = 0;
    for (const Index e : topo.vertex_edges(v)) sharp += out.edge_sharp[static_cast<std::size_t>(e)];
    VertexRule rule = sharp == 0 ? VertexRule::smooth : sharp == 1 ? VertexRule::dart
                      : sharp == 2 ? VertexRule::crease : VertexRule::corner;
    const VertexKind kind = topo.vertex_kind(v);
    if (kind == VertexKind::isolated) rule = VertexRule::corner;
    // Non-manifold or flipped surroundings: sharp, a crease only along exactly two sharp edges.
    if (kind != VertexKind::isolated && !topo.ring_ordered(v) && rule != VertexRule::crease) rule = VertexRule::corner;
    // OpenSubdiv's edge-and-corner mode: a boundary vertex of a single face is a corner.
    if (boundary == BoundaryInterpolation::edge_and_corner && kind == VertexKind::boundary &&
        topo.vertex_face_count(v) == 1)
      rule = VertexRule::corner;
    out.vertex_rule[static_cast<std::size_t>(v)] = rule;
  }
  for (const CornerTag& c : mesh.tags.corners)
    if (c.sharpness >= kInfiniteSharpness && c.vertex >= 0 && c.vertex < topo.vertex_count())
      out.vertex_rule[static_cast<std::size_t>(c.vertex)] = VertexRule::corner;
  return out;
}

}  // namespace subdiv
