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

const char* to_string(Quasi48Boundary b) noexcept { return b == Quasi48Boundary::fixed ? "fixed" : "smoothed"; }

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

std::vector<char> held_vertices(const PolygonMesh& level, const MeshTopology& topology,
                                const SchemeParameters& parameters) {
  return quasi_4_8_fixed_vertices(level, topology, std::get<Quasi48Parameters>(parameters).boundary);
}

// Whether vertex v of the bisected level is a split point (the bisection
// numbers the old vertices first, then the split points).
bool is_split_point(const LevelView& level, Index v) { return v >= level.level_split->edge_points; }

bool is_held(const LevelView& level, Index v) { return level.held[static_cast<std::size_t>(v)] != 0; }

// The neighbours a vertex is smoothed over: all of them inside, those along
// boundary edges on a (smoothed) boundary.
template <typename Fn>
void for_each_smoothing_neighbour(const LevelView& level, Index v, Fn&& fn) {
  const MeshTopology& t = level.topology;
  const bool boundary = t.vertex_kind(v) == VertexKind::boundary;
  for (const Index e : t.vertex_edges(v))
    if (!boundary || t.is_boundary_edge(e)) fn(t.other_vertex(e, v));
}

// The bisection's placement: old vertices kept, a split point at its
// edge's midpoint (which a held split point keeps).
void kept_vertex(const LevelView&, Index v, VertexRule, MaskBuilder& mask) { mask.add(v, 1.0); }

void edge_midpoint(const LevelView& level, Index e, EdgeRule, MaskBuilder& mask) {
  const auto [a, b] = level.topology.edge_vertices(e);
  mask.add(a, 0.5);
  mask.add(b, 0.5);
}

// Pass 1: a split point the average of its m smoothing neighbours (m = 4
// inside: its edge's ends and the two opposite vertices, all old, since a
// face has at most one split edge); old vertices unchanged.
void pass_1(const LevelView& level, Index v, VertexRule, MaskBuilder& mask) {
  if (!is_split_point(level, v) || is_held(level, v)) return mask.add(v, 1.0);
  int m = 0;
  for_each_smoothing_neighbour(level, v, [&](Index) { ++m; });
  for_each_smoothing_neighbour(level, v, [&](Index n) { mask.add(n, 1.0 / m); });
}

// Pass 2: an old vertex 1/2 itself + 1/(2k) its k split-point neighbours
// after pass 1 (kept where k = 0); split points unchanged.
void pass_2(const LevelView& level, Index v, VertexRule, MaskBuilder& mask) {
  int k = 0;
  if (!is_split_point(level, v) && !is_held(level, v))
    for_each_smoothing_neighbour(level, v, [&](Index n) { k += is_split_point(level, n) ? 1 : 0; });
  if (k == 0) return mask.add(v, 1.0);
  mask.add(v, 0.5);
  for_each_smoothing_neighbour(level, v, [&](Index n) {
    if (is_split_point(level, n)) mask.add(n, 0.5 / k);
  });
}

Scheme step(std::string_view name, SplitRule split, SchemeMasks masks) {
  return Scheme{.name = name, .split = split, .traits = {.needs_triangles = true}, .masks = masks};
}

std::vector<Scheme> steps_of(const SchemeParameters& parameters) {
  std::vector<Scheme> steps{
      step("quasi-4-8 bisection", SplitRule::quasi_4_8, {.edge_point = edge_midpoint, .vertex_point = kept_vertex}),
      step("quasi-4-8 pass 1", SplitRule::identity, {.vertex_point = pass_1, .held_vertices = held_vertices}),
      step("quasi-4-8 pass 2", SplitRule::identity, {.vertex_point = pass_2, .held_vertices = held_vertices})};
  for (Scheme& s : steps) s.parameters = parameters;
  return steps;
}

}  // namespace

const Scheme& quasi_4_8_scheme() noexcept {
  static const Scheme scheme{
      .name = "quasi-4-8",
      .summary = "approximating, geometry-sensitive bisection (one binary step per level, two per 4-8 step), "
                 "triangle meshes; two-pass averaging, tags not smoothed",
      .citation = "L. Velho: Quasi 4-8 subdivision, Computer Aided Geometric Design 18(4), 2001",
      .split = SplitRule::quasi_4_8,
      .traits = {.needs_triangles = true, .period = 2},  // two binary steps make one 4-8 step
      .steps = steps_of,
      .parameters = Quasi48Parameters{}};
  return scheme;
}

}  // namespace subdiv
