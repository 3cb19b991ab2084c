// 4-8: all of its weights (L. Velho, D. Zorin, "4-8 subdivision", CAGD 18(5),
// 2001), read on quads as the survey does (section 4.2, Figure 10): the 4-8
// mesh's diamonds are the quads, a bisection's new vertex is a face point,
// and as the edges are not refined only a face rule and a vertex rule exist.
//   face point    the average of the face's vertices;
//   vertex point  1/2 v + 1/(2k) (sum of v's k edge neighbours).
// On a regular quad mesh these are the rules of the four-direction box
// spline with every direction doubled (degree 6, C4; the survey: "C4 on
// regular grids"), derived here from its symbol: one sqrt2 step upsamples to
// the quincunx lattice and convolves with 2 cos^2(a/2) cos^2(b/2) along its
// two edge directions u, v, i.e. the mask 1/2 at the point, 1/4 at +-u, +-v
// (a new point's four old corners) and 1/8 at +-u +-v (an old vertex's edge
// neighbours); two steps give all four directions, doubled.
// tests/rules/four_eight_test.cpp checks two steps against the box spline's
// own mask, weight for weight.
//
// Extraordinary vertices: Velho and Zorin's rule for them is not in the
// survey's text and could not be recovered. A vertex of valence k != 4 takes
// the same average, 1/2 v + 1/(2k) sum; this generalisation is this
// project's, not the paper's (the analysis finds it C1 for k = 3..12).
//
// Closed meshes only (Scheme::needs_closed_mesh): at non-integer arity there
// is no natural boundary treatment (the survey, section 4.2); sharp features
// are refused as on the other non-primal splits. (Velho's Quasi 4-8 paper,
// seed 001, smooths old vertices over the new face points instead, 1/2 v +
// 1/(2k) sum of new points: on a regular grid that is 5/8, 1/16, 1/32, not
// the box spline, so it is not used.)

//
// Two steps at once (four_eight_two_steps_scheme): two sqrt2 steps of a
// closed mesh are its quad split. The first step makes a face point F_f (the
// face average) and moves each vertex to W_v = 1/2 v + 1/(2k) (sum of its k
// edge neighbours); in that level, a face point's edge neighbours are its
// face's vertices and a vertex's are the face points around it, and each
// parent edge (a, b) between faces f, g is the quad (a, F_g, b, F_f). So the
// second step makes
//   edge point    E_e  = 1/4 (W_a + W_b + F_f + F_g)    (that quad's face point)
//   face point    F'_f = 1/2 F_f + 1/(2n) sum of W over f's n corners
//   vertex point  W'_v = 1/2 W_v + 1/(2m) sum of F over v's m faces.
// The masks below spell these out over the parent's vertices (for stencils
// and the analysis); the fast path computes F and W first and then the
// three sums, about a third of the wide masks' multiply-adds (27 against 81
// per parent face on closed quads). The engine takes this scheme only on closed
// manifold levels; an edge with other than two faces averages them here,
// 1/2 (average of F over its faces), so the rules stay affine.

#include "subdiv/rules/four_eight.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "../core/large_buffers.h"
#include "rule_helpers.h"

namespace subdiv {

namespace {

void face_point(const LevelView& level, Index f, MaskBuilder& mask) { detail::add_face_average(level, f, 1.0, mask); }

// w times the first step's vertex point W_v.
void add_moved_vertex(const MeshTopology& t, Index v, double w, MaskBuilder& mask) {
  const auto edges = t.vertex_edges(v);
  mask.add(v, edges.empty() ? w : 0.5 * w);
  const double each = 0.5 * w / static_cast<double>(edges.size());
  for (const Index e : edges) mask.add(t.other_vertex(e, v), each);
}

void vertex_point(const LevelView& level, Index v, VertexRule, MaskBuilder& mask) {
  add_moved_vertex(level.topology, v, 1.0, mask);
}

// The two steps' masks, over the parent of both.

void two_step_face_point(const LevelView& level, Index f, MaskBuilder& mask) {
  const auto corners = level.topology.face_vertices(f);
  const double n = static_cast<double>(corners.size());
  detail::add_face_average(level, f, 0.5, mask);
  for (const Index v : corners) add_moved_vertex(level.topology, v, 0.5 / n, mask);
}

void two_step_edge_point(const LevelView& level, Index e, EdgeRule, MaskBuilder& mask) {
  const MeshTopology& t = level.topology;
  for (const Index v : t.edge_vertices(e)) add_moved_vertex(t, v, 0.25, mask);
  const auto sides = t.edge_corners(e);
  for (const Index c : sides) detail::add_face_average(level, t.corner_face(c), 0.5 / static_cast<double>(sides.size()), mask);
}

void two_step_vertex_point(const LevelView& level, Index v, VertexRule, MaskBuilder& mask) {
  const MeshTopology& t = level.topology;
  const auto corners = t.vertex_corners(v);
  if (corners.empty()) return mask.add(v, 1.0);  // an isolated vertex stays
  add_moved_vertex(t, v, 0.5, mask);
  const double each = 0.5 / static_cast<double>(corners.size());
  for (const Index c : corners) detail::add_face_average(level, t.corner_face(c), each, mask);
}

// The same values in two passes: F and W, then the quad split's points.
void two_step_positions(const MeshTopology& t, const SplitMap& map, std::span<const Vec3> p, std::span<Vec3> out) {
  const Index nf = t.face_count(), ne = t.edge_count(), nv = t.vertex_count();
  std::vector<Vec3> F, W;
  detail::assign_large(F, static_cast<std::size_t>(nf), Vec3{});
  detail::assign_large(W, static_cast<std::size_t>(nv), Vec3{});
  auto face_average = [&](Index f) {
    const auto corners = t.face_vertices(f);
    Vec3 sum;
    for (const Index v : corners) sum += p[static_cast<std::size_t>(v)];
    return sum * (1.0 / static_cast<double>(corners.size()));
  };
  const std::size_t grain = 4096;
  tbb::parallel_for(tbb::blocked_range<Index>(0, nf, grain), [&](const tbb::blocked_range<Index>& r) {
    for (Index f = r.begin(); f != r.end(); ++f) F[static_cast<std::size_t>(f)] = face_average(f);
  });
  tbb::parallel_for(tbb::blocked_range<Index>(0, nv, grain), [&](const tbb::blocked_range<Index>& r) {
    for (Index v = r.begin(); v != r.end(); ++v) {
      const auto edges = t.vertex_edges(v);
      Vec3 sum;
      for (const Index e : edges) sum += p[static_cast<std::size_t>(t.other_vertex(e, v))];
      const Vec3 at = p[static_cast<std::size_t>(v)];
      W[static_cast<std::size_t>(v)] = edges.empty() ? at : 0.5 * at + sum * (0.5 / static_cast<double>(edges.size()));
    }
  });
  tbb::parallel_for(tbb::blocked_range<Index>(0, nf, grain), [&](const tbb::blocked_range<Index>& r) {
    for (Index f = r.begin(); f != r.end(); ++f) {
      const auto corners = t.face_vertices(f);
      Vec3 sum;
      for (const Index v : corners) sum += W[static_cast<std::size_t>(v)];
      out[static_cast<std::size_t>(map.face_point(f))] =
          0.5 * F[static_cast<std::size_t>(f)] + sum * (0.5 / static_cast<double>(corners.size()));
    }
  });
  tbb::parallel_for(tbb::blocked_range<Index>(0, ne, grain), [&](const tbb::blocked_range<Index>& r) {
    for (Index e = r.begin(); e != r.end(); ++e) {
      const auto [a, b] = t.edge_vertices(e);
      const auto sides = t.edge_corners(e);
      Vec3 faces;
      for (const Index c : sides) faces += F[static_cast<std::size_t>(t.corner_face(c))];
      out[static_cast<std::size_t>(map.edge_point(e))] = 0.25 * (W[static_cast<std::size_t>(a)] + W[static_cast<std::size_t>(b)]) +
                                                        faces * (0.5 / static_cast<double>(sides.size()));
    }
  });
  tbb::parallel_for(tbb::blocked_range<Index>(0, nv, grain), [&](const tbb::blocked_range<Index>& r) {
    for (Index v = r.begin(); v != r.end(); ++v) {
      const auto corners = t.vertex_corners(v);
      Vec3 sum;
      for (const Index c : corners) sum += F[static_cast<std::size_t>(t.corner_face(c))];
      const Vec3 at = W[static_cast<std::size_t>(v)];
      out[static_cast<std::size_t>(map.vertex_point(v))] =
          corners.empty() ? at : 0.5 * at + sum * (0.5 / static_cast<double>(corners.size()));
    }
  });
}

}  // namespace

const Scheme& four_eight_two_steps_scheme() noexcept {
  static const Scheme scheme{
      .name = "four-eight (two steps)",
      .summary = "two four-eight steps as one quad split (closed meshes)",
      .citation = "L. Velho, D. Zorin: 4-8 subdivision, CAGD 18(5), 2001 (regular rules from its box spline)",
      .split = SplitRule::quad,
      .traits = {.needs_closed_mesh = true},
      .masks = {.face_point = two_step_face_point, .edge_point = two_step_edge_point,
                .vertex_point = two_step_vertex_point},
      .fast_path = {.positions = two_step_positions}};
  return scheme;
}

const Scheme& four_eight_scheme() noexcept {
  static const Scheme scheme{
      .name = "four-eight",
      .summary = "approximating, sqrt2 split (arity sqrt 2), closed polygon meshes; 4-8 on quads, the C4 box spline "
                 "on regular meshes (extraordinary vertices: the same averaging, not the paper's rule)",
      .citation = "L. Velho, D. Zorin: 4-8 subdivision, CAGD 18(5), 2001 (regular rules from its box spline)",
      .split = SplitRule::sqrt2,
      .traits = {.needs_closed_mesh = true, .period = 2},  // the layout turns by 45 degrees on each step
      .masks = {.face_point = face_point, .vertex_point = vertex_point},
      .fast_path = {.two_steps = &four_eight_two_steps_scheme()}};
  return scheme;
}

}  // namespace subdiv
