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
// Extraordinary vertices: the same stencil, read off the topology (it is
// defined around any quad of a closed quad mesh). This is the project's
// choice, not a published rule: the analysis finds it C1 at valences 3..6;
// at 7..16 its characteristic map overlaps itself, so Reif's sufficient
// condition fails and the verdict is inconclusive: C1 is not claimed there.
// A rule for those valences is open (docs/schemes/interpolating-sqrt2.md).
//
// Closed quad meshes only: no boundary rule is known, and sharp features
// are refused as on the other non-primal splits.

#include "subdiv/rules/interpolating_sqrt2.h"

namespace subdiv {

namespace {

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
    // (b, a, x, y): its vertices off the edge are x and y.
    const Index g = t.corner_across(c);
    if (g == kInvalidIndex) {  // as above: the edge's own ends, which keeps the rule affine
      mask.add(t.corner_vertex(c), -1.0 / 32.0);
      mask.add(t.corner_vertex(t.corner_next(c)), -1.0 / 32.0);
      continue;
    }
    mask.add(t.corner_vertex(t.corner_next(t.corner_next(g))), -1.0 / 32.0);
    mask.add(t.corner_vertex(t.corner_prev(g)), -1.0 / 32.0);
  }
}

void vertex_point(const LevelView&, Index v, VertexRule, MaskBuilder& mask) { mask.add(v, 1.0); }

}  // namespace

const Scheme& interpolating_sqrt2_scheme() noexcept {
  static const Scheme scheme{
      .name = "interpolating-sqrt2",
      .summary = "interpolating, sqrt2 split (arity sqrt 2), closed quad meshes; the 12-point rule (cubic precision), "
                 "C1 at valences 3..6 (not shown at 7 and above)",
      .citation = "I. Ivrissimtzis, N. Dodgson, M. Hassan, M. Sabin: On the geometry of recursive subdivision, IJSM "
                  "8(1), 2002 (the survey's row); rule from open research code, checked here",
      .split = SplitRule::sqrt2,
      .traits = {.interpolating = true, .needs_quads = true, .needs_closed_mesh = true, .period = 2},
      .masks = {.face_point = face_point, .vertex_point = vertex_point}};
  return scheme;
}

}  // namespace subdiv
