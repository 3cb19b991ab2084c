// Quasi 4-8 subdivision: all of its weights (L. Velho, "Quasi 4-8
// subdivision", CAGD 18(4), 2001, Algorithm 2 and section 4.3).
//
//   pass 1, new vertex v':  p(v') = (1/m) sum of its m neighbours (m = 4
//     inside: a split point joins its edge's ends and the two opposite
//     vertices, all old, since a face has at most one split edge);
//   pass 2, old vertex v:   p(v) = 1/2 p(v) + 1/(2k) sum of its k new
//     neighbours after pass 1 (k = 0: p(v) is kept; the paper's formula is
//     undefined there).
// Composed on a regular 4-8 grid: a new vertex 1/4 on each of the four
// corners around it, an old vertex 5/8 on itself, 1/16 on its four
// neighbours sharing two of its new neighbours and 1/32 on the four sharing
// one (Figure 4, whose picture is lost from the text; re-derived here and
// tested against the lattice).
//
// Tags (section 4.3, "a tagged vertex or edge is not affected by
// smoothing"): a tagged vertex keeps its position; a tagged edge keeps its
// ends in place and its split point at its midpoint, and its halves stay
// tagged, so the edge stays the straight segment it was. Boundaries: see
// Quasi48Boundary. The paper's "boundary vertices are constrained to move
// along the surface normal direction" is not implemented: it is not linear
// in the positions (no stencil could express it), and on the paper's planar
// examples it means what `fixed` does (boundary vertices do not move).

#include "subdiv/rules/quasi_4_8.h"

namespace subdiv {

const char* to_string(Quasi48Boundary b) { return b == Quasi48Boundary::fixed ? "fixed" : "smoothed"; }

const Scheme& quasi_4_8_scheme() {
  static const Scheme scheme{
      .name = "quasi-4-8",
      .summary = "approximating, geometry-sensitive bisection (one binary step per level, two per 4-8 step), "
                 "triangle meshes; two-pass averaging, tags not smoothed",
      .citation = "L. Velho: Quasi 4-8 subdivision, Computer Aided Geometric Design 18(4), 2001",
      .split = SplitRule::quasi_4_8,
      .traits = {.needs_triangles = true, .period = 2},  // two binary steps make one 4-8 step
      .parameters = Quasi48Parameters{}};
  return scheme;
}

std::vector<char> quasi_4_8_fixed_vertices(const PolygonMesh& child, const MeshTopology& child_topology,
                                           Quasi48Boundary boundary) {
  std::vector<char> fixed(static_cast<std::size_t>(child.vertex_count()), 0);
  const auto in_range = [&](Index v) { return v >= 0 && v < child.vertex_count(); };
  for (const CornerTag& t : child.tags.corners)
    if (t.sharpness > 0.0 && in_range(t.vertex)) fixed[static_cast<std::size_t>(t.vertex)] = 1;
  for (const CreaseTag& t : child.tags.creases)
    if (t.sharpness > 0.0 && in_range(t.v0) && in_range(t.v1)) {
      fixed[static_cast<std::size_t>(t.v0)] = 1;
      fixed[static_cast<std::size_t>(t.v1)] = 1;
    }
  if (boundary == Quasi48Boundary::fixed)
    for (Index v = 0; v < child_topology.vertex_count(); ++v)
      if (child_topology.vertex_kind(v) == VertexKind::boundary) fixed[static_cast<std::size_t>(v)] = 1;
  return fixed;
}

namespace {

bool on_boundary(const Quasi48Level& level, Index v) { return level.child.vertex_kind(v) == VertexKind::boundary; }

// The neighbours a vertex is smoothed over: all of them inside, those along
// boundary edges on a (smoothed) boundary.
template <typename Fn>
void for_each_smoothing_neighbour(const Quasi48Level& level, Index v, Fn&& fn) {
  const bool boundary = on_boundary(level, v);
  for (const Index e : level.child.vertex_edges(v))
    if (!boundary || level.child.is_boundary_edge(e)) fn(level.child.other_vertex(e, v));
}

}  // namespace

void quasi_4_8_new_vertex_mask(const Quasi48Level& level, Index v, MaskBuilder& mask) {
  if (level.fixed[static_cast<std::size_t>(v)]) {
    const Index e = level.map.split_edges[static_cast<std::size_t>(v - level.map.old_vertex_count)];
    const auto [a, b] = level.parent.edge_vertices(e);
    mask.add(a, 0.5);
    mask.add(b, 0.5);
    return;
  }
  int m = 0;
  for_each_smoothing_neighbour(level, v, [&](Index) { ++m; });
  for_each_smoothing_neighbour(level, v, [&](Index n) { mask.add(n, 1.0 / m); });
}

void quasi_4_8_old_vertex_mask(const Quasi48Level& level, Index v, MaskBuilder& mask) {
  int k = 0;
  if (!level.fixed[static_cast<std::size_t>(v)])
    for_each_smoothing_neighbour(level, v, [&](Index n) { k += level.map.is_new(n) ? 1 : 0; });
  if (k == 0) {
    mask.add(v, 1.0);
    return;
  }
  mask.add(v, 0.5);
  for_each_smoothing_neighbour(level, v, [&](Index n) {
    if (level.map.is_new(n)) mask.add_face_point(n - level.map.old_vertex_count, 0.5 / k);
  });
}

}  // namespace subdiv
