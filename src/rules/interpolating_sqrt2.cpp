// Interpolating sqrt2 subdivision: all of its weights.
//
// Survey's classification table: QP, arity sqrt 2, interpolating; it cites
// I. Ivrissimtzis, N. Dodgson, M. Hassan, M. Sabin, "On the geometry of
// recursive subdivision", IJSM 8(1), 2002. Split: the sqrt2 split (as
// four-eight's): old vertices are kept, each quad gets a new vertex, each
// old edge becomes the quad (v0, point of the face on its right, v1, point
// of the face on its left).
//
// Face point of a quad (a, b, c, d):
//   5/16 (a + b + c + d) - 1/32 (the 8 outer vertices),
// the outer vertices being, across each of the quad's edges, the two
// vertices of the neighbouring quad that are not on that edge. Recovered
// from open research code (../shared/notes/rules-found.md, which names no
// paper) and checked here: on the regular grid it is the symmetric rule on
// this 12-point support that reproduces cubic polynomials
// (tests/rules/interpolating_sqrt2_test.cpp; 4 a + 8 b = 1 and quadratic
// reproduction fix a = 5/16, b = -1/32), and the analysis finds its regular
// rules C1 (joint spectral radius of the second differences below 2^-1/2
// over two steps).
//
// Extraordinary vertices: the project's construction, not a published rule
// (docs/schemes/interpolating-sqrt2.md). The stencil keeps its 12 points,
// but each outer point that on the grid lies beyond an extraordinary corner
// of the quad (across the quad's edge at that corner, next to the corner)
// becomes a virtual point: the corner's ring interpolated trigonometrically
// at the angle opposite the quad's other edge there (add_point_beyond). It
// is the grid's point at valence 4, so the rule reduces to the regular one.
// The analysis finds it C1 at valences 3..16. (The same stencil read off
// the topology, without virtual points, was C1 at 3..6 only: at 7 and up
// its characteristic map overlapped itself.)
//
// Closed quad meshes only: no boundary rule is known, and sharp features
// are refused as on the other non-primal splits.

#include "subdiv/rules/interpolating_sqrt2.h"

#include <cmath>
#include <numbers>

namespace subdiv {

namespace {

// The point beyond a opposite its ring neighbour w, as the regular grid has
// it (a's neighbour on the far side of the line through w and a): a's ring
// e_0 .. e_{k-1} interpolated trigonometrically at w's angle plus pi, with
// the weights (1/k) (1 + 2 sum_h cos(h d_j)) (h < k/2; plus cos(k/2 d_j) for
// even k), d_j the angle from e_j. For even k that is the opposite
// neighbour e_{j+k/2} itself; the weights sum to 1 and are symmetric about
// the line. Added with `weight` where a is an interior vertex of valence
// other than 4; false (nothing added) elsewhere, where the grid's own point
// is the right one.
bool add_point_beyond(const MeshTopology& t, Index a, Index w, double weight, MaskBuilder& mask) {
  if (t.vertex_kind(a) != VertexKind::interior || t.valence(a) == 4 || !t.ring_ordered(a)) return false;
  const auto edges = t.vertex_edges(a);
  const int k = static_cast<int>(edges.size());
  int at = -1;
  for (int j = 0; j < k; ++j)
    if (t.other_vertex(edges[static_cast<std::size_t>(j)], a) == w) at = j;
  if (at < 0) return false;
  const double angle = 2.0 * std::numbers::pi / k;
  for (int j = 0; j < k; ++j) {
    const double d = std::numbers::pi + angle * (at - j);
    double c = 1.0;
    for (int h = 1; 2 * h < k; ++h) c += 2.0 * std::cos(h * d);
    if (k % 2 == 0) c += std::cos(k / 2 * d);
    mask.add(t.other_vertex(edges[static_cast<std::size_t>(j)], a), weight * c / k);
  }
  return true;
}

void face_point(const LevelView& level, Index f, MaskBuilder& mask) {
  const MeshTopology& t = level.topology;
  if (t.face_size(f) != 4) {  // only at the boundary of the analysis's ring meshes, outside what it reads
    const auto vs = t.face_vertices(f);
    for (const Index v : vs) mask.add(v, 1.0 / static_cast<double>(vs.size()));
    return;
  }
  const Index first = t.face_first_corner(f);
  for (Index c = first; c < first + 4; ++c) {
    mask.add(t.corner_vertex(c), 5.0 / 16.0);
    // The quad across the edge from c's vertex a to the next corner's b runs
    // (b, a, x, y): its vertices off the edge are x (next to a) and y (next
    // to b). On the grid x lies beyond a opposite a's other neighbour in
    // this quad, and y beyond b opposite b's: at an extraordinary a or b
    // that point is interpolated from its ring instead.
    const Index g = t.corner_across(c);
    if (g == kInvalidIndex) {  // as above: the edge's own ends, which keeps the rule affine
      mask.add(t.corner_vertex(c), -1.0 / 32.0);
      mask.add(t.corner_vertex(t.corner_next(c)), -1.0 / 32.0);
      continue;
    }
    const Index a = t.corner_vertex(c), b = t.corner_vertex(t.corner_next(c));
    if (!add_point_beyond(t, a, t.corner_vertex(t.corner_prev(c)), -1.0 / 32.0, mask))
      mask.add(t.corner_vertex(t.corner_next(t.corner_next(g))), -1.0 / 32.0);
    if (!add_point_beyond(t, b, t.corner_vertex(t.corner_next(t.corner_next(c))), -1.0 / 32.0, mask))
      mask.add(t.corner_vertex(t.corner_prev(g)), -1.0 / 32.0);
  }
}

void vertex_point(const LevelView&, Index v, VertexRule, MaskBuilder& mask) { mask.add(v, 1.0); }

}  // namespace

const Scheme& interpolating_sqrt2_scheme() noexcept {
  static const Scheme scheme{
      .name = "interpolating-sqrt2",
      .summary = "interpolating, sqrt2 split (arity sqrt 2), closed quad meshes; the 12-point rule (cubic precision), "
                 "virtual points at extraordinary vertices (the project's); C1 at valences 3..16",
      .citation = "I. Ivrissimtzis, N. Dodgson, M. Hassan, M. Sabin: On the geometry of recursive subdivision, IJSM "
                  "8(1), 2002 (the survey's row); rule from open research code, checked here",
      .split = SplitRule::sqrt2,
      .traits = {.interpolating = true, .needs_quads = true, .needs_closed_mesh = true, .period = 2},
      .masks = {.face_point = face_point, .vertex_point = vertex_point}};
  return scheme;
}

}  // namespace subdiv
